#include "view_segments.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/core/random.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/geometry/scene_layout.hpp"
#include "view_encode.hpp"

namespace antipode::cli {
namespace {

using Json = nlohmann::ordered_json;

constexpr float kVoxel_m = 0.003f;     // the sampler's default voxel
constexpr float kOnSupport_m = 0.01f;  // SceneOptions::plane_distance_m's default
constexpr std::int16_t kSupport = -1, kOther = -2;

// The voxel a point falls in, packed (as voxelize() keys them; a voxel's mean stays in it).
std::uint64_t voxel_key(const Eigen::Vector3f& p) {
  const auto cell = [](float v) {
    return std::uint64_t(std::int64_t(std::floor(v / kVoxel_m)) + (std::int64_t(1) << 20)) &
           0x1fffff;
  };
  return cell(p.x()) | cell(p.y()) << 21 | cell(p.z()) << 42;
}

// The support's extent: the rectangle, in the plane, bounding its points.
Json support_corners(const Cloud& cloud, const SupportPlane& plane) {
  // In-plane axes along the frame's x (or y) axis where the plane allows: a table's sides.
  const Eigen::Vector3f n = plane.normal.normalized();
  const Eigen::Vector3f x =
      std::fabs(n.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  const Eigen::Vector3f e1 = (x - n.dot(x) * n).normalized(), e2 = n.cross(e1);
  float lo1 = INFINITY, hi1 = -INFINITY, lo2 = INFINITY, hi2 = -INFINITY;
  for (const Eigen::Vector3f& p : cloud.points_m) {
    if (std::fabs(plane.distance(p)) > kOnSupport_m) continue;
    lo1 = std::min(lo1, e1.dot(p)), hi1 = std::max(hi1, e1.dot(p));
    lo2 = std::min(lo2, e2.dot(p)), hi2 = std::max(hi2, e2.dot(p));
  }
  if (!(lo1 <= hi1)) return nullptr;
  const Eigen::Vector3f foot = -plane.offset * n;  // the plane's point nearest the origin
  Json corners = Json::array();
  for (const auto& [a, b] : {std::pair{lo1, lo2}, {hi1, lo2}, {hi1, hi2}, {lo1, hi2}}) {
    const Eigen::Vector3f c = foot + a * e1 + b * e2;  // e1 and e2 are normal to the foot
    corners.push_back({c.x(), c.y(), c.z()});
  }
  return corners;
}

}  // namespace

Json segments_json(const Cloud& cloud, const Cloud& shown) {
  Json out = {{"segments", ""}, {"objects", 0}, {"support", nullptr}};
  if (cloud.empty()) return out;
  const Cloud voxels = voxelize(cloud, kVoxel_m);
  const Eigen::Vector3f sensor =
      voxels.view_origins_m.empty() ? Eigen::Vector3f::Zero() : voxels.view_origins_m.front();
  const SceneLayout layout = find_scene_layout(voxels, sensor, SceneOptions{}, RandomStream(0));
  std::unordered_map<std::uint64_t, std::int16_t> label_of;
  for (std::size_t i = 0; i < voxels.size(); ++i) {
    const std::int32_t object = layout.object_of_point[i];
    std::int16_t label = object >= 0 ? std::int16_t(std::min(object, 32767)) : kOther;
    if (object < 0 && layout.support &&
        std::fabs(layout.support->distance(voxels.points_m[i])) <= kOnSupport_m)
      label = kSupport;
    label_of.emplace(voxel_key(voxels.points_m[i]), label);
  }
  std::vector<std::int16_t> labels(shown.size(), kOther);
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const auto found = label_of.find(voxel_key(shown.points_m[i]));
    if (found != label_of.end()) labels[i] = found->second;
  }
  out["segments"] = base64(labels.data(), 2 * labels.size());
  out["objects"] = layout.objects.size();
  if (layout.support) out["support"] = support_corners(cloud, *layout.support);
  return out;
}

void add_cloud(const Cloud& cloud, double voxel_m, Json& scene) {
  const Cloud shown = voxel_m > 0.0 ? voxelize(cloud, float(voxel_m)) : cloud;
  Json segments = segments_json(cloud, shown);
  scene["cloud"] = cloud_json(shown);
  scene["cloud"]["segments"] = std::move(segments["segments"]);
  scene["cloud"]["objects"] = segments["objects"];
  scene["support"] = segments["support"];
}

}  // namespace antipode::cli
