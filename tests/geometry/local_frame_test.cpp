#include "antipode/geometry/local_frame.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "antipode/geometry/point_index.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "synthetic_shapes.hpp"

namespace antipode {
namespace {

using testing::ShapeOptions;

struct FrameStats {
  int frames = 0;
  int axis_within_10deg = 0;
  int facing_sensor = 0;
};

// Frames at every 7th point of `cloud` farther than 4 cm from the ends of a cylinder with
// `axis` through `centre`.
FrameStats cylinder_frames(const Cloud& cloud, const Eigen::Vector3d& centre,
                           const Eigen::Vector3d& axis, double half_length) {
  const PointIndex index(cloud.points_m);
  std::vector<std::int32_t> neighbours;
  FrameStats stats;
  for (std::size_t i = 0; i < cloud.size(); i += 7) {
    const Eigen::Vector3f& p = cloud.points_m[i];
    if (std::abs((p.cast<double>() - centre).dot(axis)) > half_length - 0.04) continue;
    index.radius_search(p, 0.03f, neighbours);
    const LocalFrame frame = estimate_local_frame(cloud.points_m, neighbours, p, -p.normalized());
    if (!frame.usable()) continue;
    ++stats.frames;
    if (std::abs(frame.axis.cast<double>().dot(axis)) > std::cos(10.0 * M_PI / 180.0)) {
      ++stats.axis_within_10deg;
    }
    if (frame.normal.dot(-p) > 0.0f) ++stats.facing_sensor;
    EXPECT_TRUE(frame.basis().isUnitary(1e-4f));
    EXPECT_NEAR(frame.basis().determinant(), 1.0f, 1e-4f);
  }
  return stats;
}

class CylinderAxisTest : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(CylinderAxisTest, CurvatureAxisIsTheCylinderAxis) {
  const auto [diameter, noise] = GetParam();
  const Eigen::Vector3d centre(0.05, 0.0, 0.6);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 1.0, 0.2).normalized();
  ShapeOptions options;
  options.noise_m = noise;
  const Cloud cloud = voxelize(cylinder_cloud(centre, axis, diameter, 0.2, options), 0.003f);
  const FrameStats stats = cylinder_frames(cloud, centre, axis, 0.1);
  ASSERT_GT(stats.frames, 20);
  EXPECT_GE(stats.axis_within_10deg, stats.frames * 9 / 10)
      << stats.axis_within_10deg << " of " << stats.frames;
  EXPECT_EQ(stats.facing_sensor, stats.frames);
}

INSTANTIATE_TEST_SUITE_P(DiametersAndNoise, CylinderAxisTest,
                         ::testing::Combine(::testing::Values(0.04, 0.06),
                                            ::testing::Values(0.0, 0.001)));

std::vector<std::int32_t> all_of(const std::vector<Eigen::Vector3f>& points) {
  std::vector<std::int32_t> indices(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) indices[i] = static_cast<std::int32_t>(i);
  return indices;
}

TEST(LocalFrameTest, FlatNeighbourhoodFallsBackToPrincipalComponents) {
  std::vector<Eigen::Vector3f> points;
  for (int i = -8; i <= 8; ++i) {
    for (int j = -4; j <= 4; ++j) points.emplace_back(0.003f * i, 0.003f * j, 0.5f);
  }
  const Eigen::Vector3f sample(0, 0, 0.5f);
  const LocalFrame frame =
      estimate_local_frame(points, all_of(points), sample, Eigen::Vector3f(0, 0, -1));
  EXPECT_EQ(frame.status, FrameStatus::kPlanar);
  EXPECT_TRUE(frame.normal.isApprox(Eigen::Vector3f(0, 0, -1), 1e-4f));
  EXPECT_NEAR(std::abs(frame.axis.x()), 1.0f, 1e-4f);  // the longer extent
  EXPECT_TRUE(frame.binormal.isApprox(frame.axis.cross(frame.normal), 1e-5f));
}

TEST(LocalFrameTest, LinesAndTinyNeighbourhoodsHaveNoFrame) {
  std::vector<Eigen::Vector3f> line;
  for (int i = 0; i < 30; ++i) line.emplace_back(0.001f * i, 0.002f * i, 0.5f);
  EXPECT_EQ(estimate_local_frame(line, all_of(line), line[0], Eigen::Vector3f::Zero()).status,
            FrameStatus::kCollinear);
  const std::vector<Eigen::Vector3f> few(line.begin(), line.begin() + 5);
  const LocalFrame frame = estimate_local_frame(few, all_of(few), few[0], Eigen::Vector3f::Zero());
  EXPECT_EQ(frame.status, FrameStatus::kTooFewPoints);
  EXPECT_FALSE(frame.usable());
  EXPECT_STREQ(to_string(FrameStatus::kCollinear), "collinear");
}

TEST(LocalFrameTest, SphereNormalsAreRadialAndFaceTheSensor) {
  const Eigen::Vector3d centre(0.0, 0.0, 0.5);
  const Cloud cloud = voxelize(testing::sphere_cloud(centre, 0.06), 0.003f);
  const PointIndex index(cloud.points_m);
  std::vector<std::int32_t> neighbours;
  int checked = 0;
  for (std::size_t i = 0; i < cloud.size(); i += 5) {
    const Eigen::Vector3f& p = cloud.points_m[i];
    index.radius_search(p, 0.03f, neighbours);
    const LocalFrame frame = estimate_local_frame(cloud.points_m, neighbours, p, -p.normalized());
    ASSERT_EQ(frame.status, FrameStatus::kQuadric);
    const Eigen::Vector3f radial = (p - centre.cast<float>()).normalized();
    EXPECT_GT(frame.normal.dot(radial), 0.98f) << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 30);
}

}  // namespace
}  // namespace antipode
