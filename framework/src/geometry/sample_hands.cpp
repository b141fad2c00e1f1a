#include "antipode/geometry/sample_hands.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "antipode/core/error.hpp"
#include "cloud_select.hpp"

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

// Random stream of the scene layout: one no sample index of the search reaches.
constexpr std::uint64_t kSceneStream = 0xFFFFFFFFFFFEull;

// The points within `range_m` of the sensor that saw them (the first view in their mask).
Cloud within_range(const Cloud& cloud, float range_m) {
  Cloud out = geometry::select_indices(cloud, [&](std::size_t i) {
    const std::uint32_t mask = cloud.view_masks.empty() ? 1u : cloud.view_masks[i];
    int view = 0;
    while (view < 31 && !(mask & (1u << view))) ++view;
    const std::size_t v = std::min<std::size_t>(std::size_t(view), cloud.view_origins_m.size() - 1);
    return (cloud.points_m[i] - cloud.view_origins_m[v]).norm() <= range_m;
  });
  if (out.empty())
    throw Error("no point of the cloud lies within max_range_m " + std::to_string(range_m) +
                " of its sensor");
  return out;
}

// The object each hand closes on: the one holding most of its closing points (the lower id
// on ties), or -1.
void label_objects(const std::vector<std::int32_t>& object_of_point, std::size_t objects,
                   std::vector<Hand>& hands) {
  std::vector<std::size_t> votes(objects);
  for (Hand& hand : hands) {
    std::fill(votes.begin(), votes.end(), 0);
    for (const std::int32_t i : hand.closing_points) {
      const std::int32_t object = object_of_point[std::size_t(i)];
      if (object >= 0) ++votes[std::size_t(object)];
    }
    const auto best = std::max_element(votes.begin(), votes.end());
    hand.object = best == votes.end() || *best == 0 ? -1 : std::int32_t(best - votes.begin());
  }
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
  if (options.max_range_m > 0.0f && !prepared->view_origins_m.empty()) {
    *prepared = within_range(*prepared, options.max_range_m);
  }
  SceneLayout layout;
  SearchScene scene;
  if (options.objects == ObjectMode::kAuto && !search.outward_from_m &&
      search.support_plane == SupportPlaneMode::kAuto) {
    layout = find_scene_layout(*prepared, geometry::sensor_position(*prepared), options.scene,
                               random.derive(kSceneStream));
    if (layout.support) {
      scene.support = layout.support;
      scene.sample_points.emplace();
      for (std::size_t i = 0; i < prepared->size(); ++i) {
        if (layout.object_of_point[i] >= 0) scene.sample_points->push_back(std::int32_t(i));
      }
    }
  }
  HandSearchResult result = search_hands(*prepared, search, random, scene);
  if (stats != nullptr) *stats = result.stats;
  if (layout.support) label_objects(layout.object_of_point, layout.objects.size(), result.hands);
  return HandSet{std::move(prepared), std::move(result.hands), search.hand, result.support_plane,
                 std::move(layout.objects)};
}

}  // namespace antipode
