#include "antipode/grasp/antipodal.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "antipode/core/error.hpp"

namespace antipode {

void AntipodalParameters::validate() const {
  if (min_points < 1) {
    throw Error("antipodal check: min_points must be at least 1, got " +
                std::to_string(min_points));
  }
  if (!(max_angle_deg > 0.0 && max_angle_deg <= 90.0)) {
    throw Error("antipodal check: max_angle_deg must be in (0, 90], got " +
                std::to_string(max_angle_deg));
  }
  if (!(contact_depth_m >= 0.0 && contact_depth_m < 1.0)) {
    throw Error("antipodal check: contact_depth_m must be in [0, 1), got " +
                std::to_string(contact_depth_m));
  }
  if (!(contact_trim >= 0.0 && contact_trim <= 0.45)) {
    throw Error("antipodal check: contact_trim must be in [0, 0.45], got " +
                std::to_string(contact_trim));
  }
}

AntipodalCount count_antipodal_normals(const Hand& hand,
                                       const std::vector<Eigen::Vector3f>& normals,
                                       double max_angle_deg) {
  const float cos_theta = static_cast<float>(std::cos(max_angle_deg * M_PI / 180.0));
  const Eigen::Vector3f closing = hand.closing().cast<float>();
  AntipodalCount count;
  for (const std::int32_t i : hand.closing_points) {
    if (i < 0 || static_cast<std::size_t>(i) >= normals.size()) {
      throw Error("antipodal check: closing point " + std::to_string(i) +
                  " is outside the cloud of " + std::to_string(normals.size()) + " points");
    }
    const float c = normals[static_cast<std::size_t>(i)].dot(closing);
    if (c >= cos_theta) ++count.facing_plus;
    if (c <= -cos_theta) ++count.facing_minus;
  }
  return count;
}

namespace {

// The two fingers' first contacts among the points' coordinates `ys` along the closing
// direction (not empty; may be reordered): the lowest and the highest, or with `trim` > 0 the
// floor(trim (n - 1))-th from each end.
std::pair<float, float> first_contacts(std::vector<float>& ys, double trim) {
  if (trim <= 0.0) {
    const auto [low, high] = std::minmax_element(ys.begin(), ys.end());
    return {*low, *high};
  }
  const auto n = static_cast<std::ptrdiff_t>(ys.size());
  const auto k = static_cast<std::ptrdiff_t>(trim * static_cast<double>(n - 1));
  std::nth_element(ys.begin(), ys.begin() + k, ys.end());
  const float lowest = ys[static_cast<std::size_t>(k)];
  std::nth_element(ys.begin(), ys.begin() + (n - 1 - k), ys.end());
  return {lowest, ys[static_cast<std::size_t>(n - 1 - k)]};
}

}  // namespace

AntipodalCount count_antipodal_normals(const Hand& hand, const std::vector<Eigen::Vector3f>& points,
                                       const std::vector<Eigen::Vector3f>& normals,
                                       const AntipodalParameters& parameters) {
  if (parameters.contact_depth_m <= 0.0)
    return count_antipodal_normals(hand, normals, parameters.max_angle_deg);
  const float cos_theta = static_cast<float>(std::cos(parameters.max_angle_deg * M_PI / 180.0));
  const Eigen::Vector3f closing = hand.closing().cast<float>();
  const float origin = closing.dot(hand.position_m().cast<float>());
  // Each point's coordinate along the closing direction, and the two first contacts.
  thread_local std::vector<float> ys;
  ys.clear();
  for (const std::int32_t i : hand.closing_points) {
    if (i < 0 || static_cast<std::size_t>(i) >= points.size() ||
        static_cast<std::size_t>(i) >= normals.size()) {
      throw Error("antipodal check: closing point " + std::to_string(i) +
                  " is outside the cloud of " + std::to_string(points.size()) + " points");
    }
    ys.push_back(closing.dot(points[static_cast<std::size_t>(i)]) - origin);
  }
  if (ys.empty()) return {};
  const auto [lowest, highest] = first_contacts(ys, parameters.contact_trim);
  const float depth = static_cast<float>(parameters.contact_depth_m);
  AntipodalCount count;
  for (const std::int32_t i : hand.closing_points) {
    const float y = closing.dot(points[static_cast<std::size_t>(i)]) - origin;
    const float c = normals[static_cast<std::size_t>(i)].dot(closing);
    if (y >= highest - depth && c >= cos_theta) ++count.facing_plus;
    if (y <= lowest + depth && c <= -cos_theta) ++count.facing_minus;
  }
  return count;
}

HandLabel antipodal_label(const AntipodalCount& count, int min_points) {
  const bool plus = count.facing_plus >= min_points;
  const bool minus = count.facing_minus >= min_points;
  if (plus && minus) return HandLabel::kPositive;
  if (plus || minus) return HandLabel::kIndeterminate;
  return HandLabel::kNegative;
}

double antipodal_score(const AntipodalCount& count, int min_points) {
  return static_cast<double>(std::min(count.facing_plus, count.facing_minus)) /
         static_cast<double>(std::max(min_points, 1));
}

std::vector<AntipodalCount> count_antipodal_normals(const HandSet& set,
                                                    const AntipodalLabellingOptions& options) {
  options.antipodal.validate();
  options.normals.validate();
  if (set.hands.empty()) return {};
  const std::vector<Eigen::Vector3f> normals =
      closing_point_normals(set, options.normals, "antipodal check");
  std::vector<AntipodalCount> counts(set.hands.size());
  const int threads = options.normals.threads;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, set.hands.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t h = range.begin(); h != range.end(); ++h) {
                          counts[h] = count_antipodal_normals(set.hands[h], set.cloud->points_m,
                                                              normals, options.antipodal);
                        }
                      });
  });
  return counts;
}

}  // namespace antipode
