#include "depth_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <thread>

#include <embree3/rtcore.h>

#include "antipode/core/error.hpp"
#include "dexnet_noise.hpp"
#include "sensor_random.hpp"

namespace antipode::cells {
namespace {

constexpr int kTile = 4;  // rays are cast in 4 x 4 packets

// What a pixel's ray hit: depth along the optical axis (0 = no return) and the cosine of the
// angle between the ray and the surface normal.
struct Hit {
  float depth = 0.f;
  float cos_incidence = 0.f;
};

// A mesh's own BVH, built once in the mesh's frame and instanced at every pose.
struct MeshScene {
  std::shared_ptr<const TriangleMesh> mesh;  // keeps the key's address alive
  RTCScene scene = nullptr;
};

RTCScene build_mesh_scene(RTCDevice device, const TriangleMesh& mesh) {
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    Eigen::Map<Eigen::Vector3f>(vertices + 3 * i) = mesh.vertices[i];
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) indices[3 * i + k] = unsigned(mesh.triangles[i][k]);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

}  // namespace

struct DepthRenderer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::map<const TriangleMesh*, MeshScene> meshes;
  std::vector<Eigen::Matrix3f> rotations;  // per instance id: object -> base

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    for (auto& [key, entry] : meshes) rtcReleaseScene(entry.scene);
    if (device) rtcReleaseDevice(device);
  }

  void add_instance(const PhysicsWorld::Visual& visual) {
    auto it = meshes.find(visual.mesh.get());
    if (it == meshes.end())
      it = meshes
               .emplace(visual.mesh.get(),
                        MeshScene{visual.mesh, build_mesh_scene(device, *visual.mesh)})
               .first;
    RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, it->second.scene);
    const Eigen::Matrix4f matrix = visual.pose.matrix().cast<float>();
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, matrix.data());
    rtcCommitGeometry(instance);
    const unsigned id = rtcAttachGeometry(scene, instance);
    rtcReleaseGeometry(instance);
    if (rotations.size() <= id) rotations.resize(id + 1);
    rotations[id] = matrix.topLeftCorner<3, 3>();
  }

  // Drops the BVHs of meshes that are no longer in the scene.
  void forget_unused(const std::vector<PhysicsWorld::Visual>& visuals) {
    std::map<const TriangleMesh*, MeshScene> kept;
    for (const auto& visual : visuals) {
      auto it = meshes.find(visual.mesh.get());
      if (it != meshes.end()) kept.insert(meshes.extract(it));
    }
    for (auto& [key, entry] : meshes) rtcReleaseScene(entry.scene);
    meshes = std::move(kept);
  }
};

namespace {

// Casts the rays of the kTile x kTile tile at (u0, v0) and writes their hits into `image`.
void cast_tile(RTCScene scene, const std::vector<Eigen::Matrix3f>& rotations,
               const CameraSpec& camera, const Eigen::Isometry3f& X_BaseCamera, int u0, int v0,
               std::vector<Hit>& image) {
  alignas(64) RTCRayHit16 packet;
  alignas(64) int valid[16];
  Eigen::Vector3f directions[16];
  for (int i = 0; i < 16; ++i) {
    const int u = u0 + i % kTile, v = v0 + i / kTile;
    valid[i] = (u < camera.width_px && v < camera.height_px) ? -1 : 0;
    const Eigen::Vector3f ray(float((u - camera.cx_px) / camera.fx_px),
                              float((v - camera.cy_px) / camera.fy_px), 1.f);
    directions[i] = X_BaseCamera.linear() * ray;
    packet.ray.org_x[i] = X_BaseCamera.translation().x();
    packet.ray.org_y[i] = X_BaseCamera.translation().y();
    packet.ray.org_z[i] = X_BaseCamera.translation().z();
    packet.ray.dir_x[i] = directions[i].x();
    packet.ray.dir_y[i] = directions[i].y();
    packet.ray.dir_z[i] = directions[i].z();
    packet.ray.tnear[i] = 0.f;
    packet.ray.tfar[i] = std::numeric_limits<float>::infinity();
    packet.ray.mask[i] = 0xFFFFFFFFu;
    packet.ray.flags[i] = 0;
    packet.ray.time[i] = 0.f;
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring pixels' rays
  rtcIntersect16(valid, scene, &context, &packet);
  for (int i = 0; i < 16; ++i) {
    if (!valid[i] || packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
    const Eigen::Vector3f normal =
        rotations[packet.hit.instID[0][i]] *
        Eigen::Vector3f(packet.hit.Ng_x[i], packet.hit.Ng_y[i], packet.hit.Ng_z[i]);
    Hit& hit = image[(v0 + i / kTile) * camera.width_px + u0 + i % kTile];
    hit.depth = packet.ray.tfar[i];  // the ray's optical-axis component is 1
    hit.cos_incidence =
        std::abs(normal.dot(directions[i])) / (normal.norm() * directions[i].norm() + 1e-12f);
  }
}

// Turns one image row of hits into points, drawing the sensor's errors from the row's own
// stream (seeded by `row_seed`). Per return: the incidence angle from its cosine, a dropout
// draw only where the dropout probability is not zero (beyond dropout_start_rad), then three
// standard normals (axial, and lateral in x and y).
void row_to_points(const std::vector<Hit>& image, int v, const CameraSpec& camera,
                   const SensorModel& sensor, const DexNetNoise* dexnet,
                   const Eigen::Isometry3d& X_BaseCamera, std::uint64_t row_seed,
                   std::uint32_t mask, Cloud& cloud) {
  SensorRandom random(row_seed);
  cloud.points_m.reserve(std::size_t(camera.width_px));
  cloud.view_masks.reserve(std::size_t(camera.width_px));
  const Eigen::Matrix3d R = X_BaseCamera.linear();
  const Eigen::Vector3d t = X_BaseCamera.translation();
  const double ray_y = (v - camera.cy_px) / camera.fy_px, inv_fx = 1.0 / camera.fx_px;
  for (int u = 0; u < camera.width_px; ++u) {
    const Hit& hit = image[v * camera.width_px + u];
    if (hit.depth < camera.min_range_m || hit.depth > camera.max_range_m) continue;
    const double ray_x = (u - camera.cx_px) * inv_fx;
    double z = hit.depth, x = ray_x * z, y = ray_y * z;
    if (dexnet != nullptr) {
      z = dexnet->apply(z, u, v);
      x = ray_x * z, y = ray_y * z;
    } else if (sensor.scale > 0.0) {
      const double theta = fast_acos(std::min(1.0, double(hit.cos_incidence)));
      if (theta > sensor.dropout_start_rad && random.uniform() < sensor.dropout_probability(theta))
        continue;
      const double lateral_m = sensor.lateral_sigma_px(theta) * z * inv_fx;
      z += sensor.axial_sigma_m(z, theta) * random.normal();
      const double dx = random.normal(), dy = random.normal();
      x = ray_x * z + lateral_m * dx;
      y = ray_y * z + lateral_m * dy;
    }
    cloud.points_m.push_back((R * Eigen::Vector3d(x, y, z) + t).cast<float>());
    cloud.view_masks.push_back(mask);
  }
}

// Runs job(0) .. job(threads - 1), job(0) on the calling thread.
template <typename Job>
void run_parallel(int threads, const Job& job) {
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back([&job, t] { job(t); });
  job(0);
  for (auto& thread : pool) thread.join();
}

}  // namespace

// Embree picks its ray kernels for the CPU it runs on, and they round hit distances
// differently: on one AVX2 machine, 300 x 300 rays at a sphere returned bit-identical
// distances with the SSE2, SSE4.2 and AVX kernels and different ones (in the last bits) with
// AVX2's. A last bit of depth moves the cloud, and the cell's outcome can follow it, so the
// kernel is capped at AVX2: every CPU with AVX2 (and AVX-512) renders the same images; an
// older CPU gets the SSE kernels and slightly different ones.
constexpr const char* kDeviceConfig = "threads=1,max_isa=avx2";

DepthRenderer::DepthRenderer() : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(kDeviceConfig);
  if (!impl_->device) throw Error("Embree device creation failed");
}

DepthRenderer::~DepthRenderer() = default;

void DepthRenderer::set_scene(const std::vector<PhysicsWorld::Visual>& visuals) {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  impl_->forget_unused(visuals);
  impl_->rotations.clear();
  impl_->scene = rtcNewScene(impl_->device);
  for (const auto& visual : visuals) impl_->add_instance(visual);
  rtcCommitScene(impl_->scene);
}

void DepthRenderer::render(const CameraSpec& camera, const SensorModel& sensor,
                           const RandomStream& random, std::uint32_t view_index, Cloud& cloud,
                           int threads) const {
  if (!impl_->scene) throw Error("the renderer has no scene");
  const Eigen::Isometry3d X_BaseCamera = look_at(camera.position_m, camera.look_at_m);
  const Eigen::Isometry3f X_BaseCamera_f = X_BaseCamera.cast<float>();
  threads = std::max(1, threads);
  std::vector<Hit> image(std::size_t(camera.width_px) * camera.height_px);
  std::vector<Cloud> rows(std::size_t(camera.height_px));
  // Worker t takes every threads-th tile row and image row; rows are joined in order, so the
  // cloud is the same for any thread count.
  auto work = [&](int t) {
    for (int v0 = kTile * t; v0 < camera.height_px; v0 += kTile * threads)
      for (int u0 = 0; u0 < camera.width_px; u0 += kTile)
        cast_tile(impl_->scene, impl_->rotations, camera, X_BaseCamera_f, u0, v0, image);
  };
  // Dex-Net's noise is drawn once per image, before the rows: only for that model.
  std::optional<DexNetNoise> dexnet;
  if (sensor.kind == SensorKind::kDexNet)
    dexnet.emplace(sensor, camera.width_px, camera.height_px,
                   mix_seed(random.seed() ^ 0xde7e70000ULL));
  auto noise = [&](int t) {
    for (int v = t; v < camera.height_px; v += threads)
      row_to_points(image, v, camera, sensor, dexnet ? &*dexnet : nullptr, X_BaseCamera,
                    mix_seed(random.seed() ^ mix_seed(0x5e750000ULL + std::uint64_t(v))),
                    1u << view_index, rows[v]);
  };
  run_parallel(threads, work);
  run_parallel(threads, noise);
  std::size_t total = cloud.size();
  for (const auto& row : rows) total += row.size();
  cloud.points_m.reserve(total);
  cloud.view_masks.reserve(total);
  for (const auto& row : rows) {
    cloud.points_m.insert(cloud.points_m.end(), row.points_m.begin(), row.points_m.end());
    cloud.view_masks.insert(cloud.view_masks.end(), row.view_masks.begin(), row.view_masks.end());
  }
}

}  // namespace antipode::cells
