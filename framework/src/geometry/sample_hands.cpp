#include "antipode/geometry/sample_hands.hpp"

#include <memory>

namespace antipode {
namespace {

bool inside_bounding_box(const Cloud& cloud, const Eigen::Vector3f& p) {
  Eigen::Vector3f lo = cloud.points_m.front(), hi = lo;
  for (const auto& q : cloud.points_m) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  return (p.array() > lo.array()).all() && (p.array() < hi.array()).all();
}

Eigen::Vector3f centroid(const Cloud& cloud) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : cloud.points_m) sum += p.cast<double>();
  return (sum / static_cast<double>(cloud.size())).cast<float>();
}

}  // namespace

HandSet sample_hands(const Cloud& cloud, const HandSamplingOptions& options,
                     const RandomStream& random, HandSearchStats* stats) {
  options.search.validate();
  cloud.validate();
  auto prepared = std::make_shared<Cloud>(preprocess(cloud, options.preprocess));
  if (prepared->view_origins_m.empty()) {
    prepared->view_origins_m.push_back(options.default_view_origin_m);
  }
  HandSearchParameters search = options.search;
  if (prepared->view_origins_m.size() == 1 &&
      inside_bounding_box(*prepared, prepared->view_origins_m.front())) {
    search.outward_from_m = centroid(*prepared);
    prepared->view_origins_m.clear();
    prepared->view_masks.clear();
  }
  HandSearchResult result = search_hands(*prepared, search, random);
  if (stats != nullptr) *stats = result.stats;
  return HandSet{std::move(prepared), std::move(result.hands), search.hand, result.support_plane};
}

}  // namespace antipode
