#include "antipode/grasp/normals.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/local_frame.hpp"
#include "antipode/geometry/point_index.hpp"

namespace antipode {
namespace {

// Unit direction from point `i` towards what saw it (see estimate_normals); zero when the
// directions cancel out.
Eigen::Vector3f toward_sensors(const Cloud& cloud, std::size_t i,
                               const Eigen::Vector3f& outward_from) {
  if (!cloud.view_origins_m.empty()) return cloud.direction_to_sensors(i);
  const Eigen::Vector3f sum = cloud.points_m[i] - outward_from;
  const float norm = sum.norm();
  return norm > 1e-6f ? (sum / norm).eval() : Eigen::Vector3f::Zero();
}

Eigen::Vector3f centroid(const Cloud& cloud) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : cloud.points_m) sum += p.cast<double>();
  return cloud.empty() ? Eigen::Vector3f::Zero()
                       : (sum / static_cast<double>(cloud.size())).cast<float>().eval();
}

}  // namespace

void NormalEstimationOptions::validate() const {
  if (!(radius_m > 0.0) || !std::isfinite(radius_m)) {
    throw Error("normal estimation: radius_m must be > 0, got " + std::to_string(radius_m));
  }
  if (min_neighbours < 9) {
    throw Error("normal estimation: min_neighbours must be at least 9, got " +
                std::to_string(min_neighbours));
  }
  if (threads < 0) {
    throw Error("normal estimation: threads must be >= 0, got " + std::to_string(threads));
  }
}

std::vector<Eigen::Vector3f> estimate_normals(const Cloud& cloud,
                                              const NormalEstimationOptions& options,
                                              const std::vector<std::int32_t>* which) {
  options.validate();
  cloud.validate();
  std::vector<Eigen::Vector3f> normals(cloud.size(), Eigen::Vector3f::Zero());
  if (cloud.empty()) return normals;
  // The points to estimate, each once (a repeated index would be written twice).
  std::vector<std::int32_t> points;
  if (which != nullptr) {
    for (const std::int32_t i : *which) {
      if (i < 0 || static_cast<std::size_t>(i) >= cloud.size()) {
        throw Error("normal estimation: point index " + std::to_string(i) +
                    " is outside the cloud of " + std::to_string(cloud.size()) + " points");
      }
    }
    points = *which;
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
  }
  const std::size_t count = which != nullptr ? points.size() : cloud.size();
  const Eigen::Vector3f outward_from =
      options.outward_from_m ? *options.outward_from_m : centroid(cloud);
  const PointIndex index(cloud.points_m);
  LocalFrameOptions frame_options;
  frame_options.min_points = options.min_neighbours;
  frame_options.axis_normals = 0;  // only the normal is wanted
  const float radius = static_cast<float>(options.radius_m);
  tbb::enumerable_thread_specific<std::vector<std::int32_t>> scratch;
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 64),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        std::vector<std::int32_t>& neighbours = scratch.local();
                        for (std::size_t k = range.begin(); k != range.end(); ++k) {
                          const std::size_t i =
                              which != nullptr ? static_cast<std::size_t>(points[k]) : k;
                          const Eigen::Vector3f viewer = toward_sensors(cloud, i, outward_from);
                          if (viewer.isZero()) continue;
                          const Eigen::Vector3f& p = cloud.points_m[i];
                          index.radius_search(p, radius, neighbours);
                          const LocalFrame frame = estimate_local_frame(cloud.points_m, neighbours,
                                                                        p, viewer, frame_options);
                          if (frame.usable()) normals[i] = frame.normal;
                        }
                      });
  });
  return normals;
}

std::vector<Eigen::Vector3f> closing_point_normals(const HandSet& set,
                                                   const NormalEstimationOptions& options,
                                                   const std::string& who) {
  if (set.hands.empty()) return {};
  if (set.cloud == nullptr) throw Error(who + ": the hand set has no cloud");
  const Cloud& cloud = *set.cloud;
  // The union of all closing points, in index order: each normal is estimated once.
  std::vector<std::uint8_t> needed(cloud.size(), 0);
  for (const Hand& hand : set.hands) {
    for (const std::int32_t i : hand.closing_points) {
      if (i < 0 || static_cast<std::size_t>(i) >= cloud.size()) {
        throw Error(who + ": closing point " + std::to_string(i) + " is outside the cloud of " +
                    std::to_string(cloud.size()) + " points");
      }
      needed[static_cast<std::size_t>(i)] = 1;
    }
  }
  std::vector<std::int32_t> which;
  for (std::size_t i = 0; i < needed.size(); ++i) {
    if (needed[i]) which.push_back(static_cast<std::int32_t>(i));
  }
  return estimate_normals(cloud, options, &which);
}

}  // namespace antipode
