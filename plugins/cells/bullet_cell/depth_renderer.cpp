#include "depth_renderer.hpp"

#include <cmath>
#include <limits>

#include <embree3/rtcore.h>

#include "antipode/core/error.hpp"

namespace antipode::cells {

struct DepthRenderer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

void add_mesh(RTCDevice device, RTCScene scene, const PhysicsWorld::Visual& visual) {
  const TriangleMesh& mesh = *visual.mesh;
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.vertices.size()));
  const Eigen::Affine3f pose = visual.pose.cast<float>();
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    Eigen::Map<Eigen::Vector3f>(vertices + 3 * i) = pose * mesh.vertices[i];
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) indices[3 * i + k] = unsigned(mesh.triangles[i][k]);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
}

struct Hit {
  float depth = 0.f;  // along the optical axis; 0 = no return
  float cos_incidence = 0.f;
};

Hit cast(RTCScene scene, const Eigen::Vector3f& origin, const Eigen::Vector3f& direction) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query;
  query.ray.org_x = origin.x();
  query.ray.org_y = origin.y();
  query.ray.org_z = origin.z();
  query.ray.dir_x = direction.x();
  query.ray.dir_y = direction.y();
  query.ray.dir_z = direction.z();
  query.ray.tnear = 0.f;
  query.ray.tfar = std::numeric_limits<float>::infinity();
  query.ray.mask = 0xFFFFFFFFu;
  query.ray.flags = 0;
  query.ray.time = 0.f;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &query);
  Hit hit;
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  const Eigen::Vector3f normal(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
  hit.depth = query.ray.tfar;
  hit.cos_incidence = std::abs(normal.dot(direction)) / (normal.norm() * direction.norm() + 1e-12f);
  return hit;
}

}  // namespace

DepthRenderer::DepthRenderer() : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice("threads=1");
  if (!impl_->device) throw Error("Embree device creation failed");
}

DepthRenderer::~DepthRenderer() = default;

void DepthRenderer::set_scene(const std::vector<PhysicsWorld::Visual>& visuals) {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  impl_->scene = rtcNewScene(impl_->device);
  for (const auto& visual : visuals) add_mesh(impl_->device, impl_->scene, visual);
  rtcCommitScene(impl_->scene);
}

void DepthRenderer::render(const CameraSpec& camera, const SensorModel& sensor,
                           const RandomStream& random, std::uint32_t view_index,
                           Cloud& cloud) const {
  if (!impl_->scene) throw Error("the renderer has no scene");
  const Eigen::Isometry3d X_BaseCamera = look_at(camera.position_m, camera.look_at_m);
  const Eigen::Matrix3f R = X_BaseCamera.linear().cast<float>();
  const Eigen::Vector3f origin = camera.position_m.cast<float>();
  for (int v = 0; v < camera.height_px; ++v) {
    RandomStream row = random.derive(std::uint64_t(v));
    for (int u = 0; u < camera.width_px; ++u) {
      const Eigen::Vector3f ray_camera(float((u - camera.cx_px) / camera.fx_px),
                                       float((v - camera.cy_px) / camera.fy_px), 1.f);
      const Hit hit = cast(impl_->scene, origin, R * ray_camera);
      if (hit.depth < camera.min_range_m || hit.depth > camera.max_range_m) continue;
      const double theta = std::acos(std::min(1.f, hit.cos_incidence));
      if (sensor.scale > 0.0 && row.uniform() < sensor.dropout_probability(theta)) continue;
      double z = hit.depth, x = ray_camera.x() * z, y = ray_camera.y() * z;
      if (sensor.scale > 0.0) {
        const double lateral_m = sensor.lateral_sigma_px(theta) * z / camera.fx_px;
        z += sensor.axial_sigma_m(z, theta) * row.normal();
        x = ray_camera.x() * z + lateral_m * row.normal();
        y = ray_camera.y() * z + lateral_m * row.normal();
      }
      cloud.points_m.push_back((X_BaseCamera * Eigen::Vector3d(x, y, z)).cast<float>());
      cloud.view_masks.push_back(1u << view_index);
    }
  }
}

}  // namespace antipode::cells
