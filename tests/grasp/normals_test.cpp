#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/grasp/normals.hpp"
#include "synthetic_shapes.hpp"
#include "views.hpp"

namespace antipode {
namespace {

using testing::seen_from;

const Eigen::Vector3d kLeft(-0.5, 0.0, 0.3);
const Eigen::Vector3d kRight(0.5, 0.0, 0.3);

Cloud box_seen_from(const std::vector<Eigen::Vector3d>& sensors) {
  return seen_from([](const Eigen::Vector3d& c) {
    return testing::box_cloud(c, Eigen::Matrix3d::Identity(), {0.05, 0.05, 0.1});
  }, Eigen::Vector3d::Zero(), sensors);
}

TEST(NormalsTest, OutwardOnEveryFaceAwayFromEdges) {
  const Cloud cloud = box_seen_from({kLeft, kRight});
  NormalEstimationOptions options;
  options.threads = 2;
  const auto normals = estimate_normals(cloud, options);
  ASSERT_EQ(normals.size(), cloud.size());
  int checked = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f& p = cloud.points_m[i];
    // Points at least 1.2 cm from every edge of their face.
    Eigen::Vector3f outward = Eigen::Vector3f::Zero();
    if (std::abs(std::abs(p.x()) - 0.025f) < 1e-4f && std::abs(p.z()) < 0.038f &&
        std::abs(p.y()) < 0.013f) {
      outward = Eigen::Vector3f(p.x() > 0 ? 1.0f : -1.0f, 0.0f, 0.0f);
    } else if (std::abs(p.z() - 0.05f) < 1e-4f && std::abs(p.x()) < 0.013f &&
               std::abs(p.y()) < 0.013f) {
      outward = Eigen::Vector3f::UnitZ();
    } else {
      continue;
    }
    ASSERT_NEAR(normals[i].norm(), 1.0f, 1e-4f);
    EXPECT_GT(normals[i].dot(outward), std::cos(2.0 * M_PI / 180.0)) << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

TEST(NormalsTest, OrientedTowardsTheSensorOnACylinder) {
  const Eigen::Vector3d centre(0.0, 0.0, 0.6);
  const Cloud cloud = testing::cylinder_cloud(centre, Eigen::Vector3d::UnitY(), 0.06, 0.15);
  const auto normals = estimate_normals(cloud, NormalEstimationOptions{});
  int checked = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.points_m[i].cast<double>();
    if (std::abs(p.y()) > 0.06) continue;  // the curved side only, away from the caps
    Eigen::Vector3d radial = p - centre;
    radial.y() = 0.0;
    // Near the silhouette the ball holds a one-sided strip of surface: not checked there.
    if (radial.normalized().dot(-p.normalized()) < 0.5) continue;
    EXPECT_GT(normals[i].cast<double>().dot(radial.normalized()), std::cos(5.0 * M_PI / 180.0))
        << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 500);
}

TEST(NormalsTest, OnlyTheListedPointsAndTheSameForAnyThreadCount) {
  const Cloud cloud = box_seen_from({kLeft, kRight});
  std::vector<std::int32_t> which;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); i += 3) which.push_back(i);
  which.push_back(0);  // repeated: estimated once
  NormalEstimationOptions one;
  one.threads = 1;
  NormalEstimationOptions two;
  two.threads = 2;
  const auto a = estimate_normals(cloud, one, &which);
  const auto b = estimate_normals(cloud, two, &which);
  const auto all = estimate_normals(cloud, two);
  ASSERT_EQ(a.size(), cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_EQ(a[i], b[i]);
    if (i % 3 == 0) {
      EXPECT_EQ(a[i], all[i]);
    } else {
      EXPECT_TRUE(a[i].isZero());
    }
  }
}

TEST(NormalsTest, CloudWithoutViewOriginsPointsAwayFromItsCentroid) {
  Cloud cloud = box_seen_from({kLeft, kRight});
  cloud.view_origins_m.clear();
  cloud.view_masks.clear();
  const auto normals = estimate_normals(cloud, NormalEstimationOptions{});
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f& p = cloud.points_m[i];
    if (std::abs(p.x() + 0.025f) < 1e-4f && std::abs(p.z()) < 0.03f && std::abs(p.y()) < 0.01f) {
      EXPECT_LT(normals[i].x(), -0.99f) << p.transpose();
    }
  }
}

TEST(NormalsTest, SparsePointsGetNoNormal) {
  Cloud cloud;
  cloud.points_m = {{0, 0, 1}, {0.1f, 0, 1}, {0, 0.1f, 1}};
  for (const auto& n : estimate_normals(cloud, NormalEstimationOptions{})) EXPECT_TRUE(n.isZero());
}

TEST(NormalsTest, BadInputIsAnError) {
  const Cloud cloud = box_seen_from({kLeft});
  NormalEstimationOptions options;
  options.radius_m = 0.0;
  EXPECT_THROW(estimate_normals(cloud, options), Error);
  options = {};
  options.min_neighbours = 3;
  EXPECT_THROW(estimate_normals(cloud, options), Error);
  const std::vector<std::int32_t> outside{static_cast<std::int32_t>(cloud.size())};
  EXPECT_THROW(estimate_normals(cloud, NormalEstimationOptions{}, &outside), Error);
}

}  // namespace
}  // namespace antipode
