// The fast collision path: sphere covers hold their shapes and keep to their overshoot, the
// distance grid never calls a touching sphere clear, the float forward kinematics agrees with
// the chain's, and, over 100,000 random configurations per scene and robot, the spheres never
// call a contact free that FCL finds, disagree with it on few configurations, and spheres
// followed by FCL give FCL's own answer; checking 16 configurations at once gives the same
// answers whether or not the links' bounding spheres skip tests.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/robot_file.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "collision_pairs.hpp"
#include "distance_grid.hpp"
#include "screw_chain.hpp"
#include "sphere_cover.hpp"
#include "sphere_kernels.hpp"
#include "support/error_of.hpp"

namespace antipode::collision {
namespace {

using ::antipode::testing::error_of;

std::string source(const std::string& path) {
  return std::string(ANTIPODE_TEST_SOURCE_DIR) + "/" + path;
}

// Distance from p (in the shape's frame, centred) to a box of half sizes h, a cylinder (radius
// R, half length H, along z) or a sphere; 0 inside.
double outside_box(const Eigen::Vector3d& p, const Eigen::Vector3d& h) {
  return (p.cwiseAbs() - h).cwiseMax(0.0).norm();
}
double outside_cylinder(const Eigen::Vector3d& p, double R, double H) {
  return std::hypot(std::max(0.0, std::hypot(p.x(), p.y()) - R),
                    std::max(0.0, std::abs(p.z()) - H));
}
double outside(const CollisionPrimitive& s, const Eigen::Vector3d& p_link) {
  const Eigen::Vector3d p = s.X_LinkShape.inverse() * p_link;
  switch (s.kind) {
    case CollisionPrimitive::Kind::kBox:
      return outside_box(p, 0.5 * s.size_m);
    case CollisionPrimitive::Kind::kCylinder:
      return outside_cylinder(p, s.size_m.x(), 0.5 * s.size_m.y());
    case CollisionPrimitive::Kind::kSphere:
      return std::max(0.0, p.norm() - s.size_m.x());
  }
  return 0.0;
}

// Distance from p (in the link frame, inside the shape) to the shape's surface.
double depth(const CollisionPrimitive& s, const Eigen::Vector3d& p_link) {
  const Eigen::Vector3d p = s.X_LinkShape.inverse() * p_link;
  switch (s.kind) {
    case CollisionPrimitive::Kind::kBox:
      return (0.5 * s.size_m - p.cwiseAbs()).minCoeff();
    case CollisionPrimitive::Kind::kCylinder:
      return std::min(s.size_m.x() - std::hypot(p.x(), p.y()),
                      0.5 * s.size_m.y() - std::abs(p.z()));
    case CollisionPrimitive::Kind::kSphere:
      return s.size_m.x() - p.norm();
  }
  return 0.0;
}

CollisionPrimitive shape(CollisionPrimitive::Kind kind, const Eigen::Vector3d& size) {
  CollisionPrimitive s;
  s.kind = kind;
  s.size_m = size;
  s.X_LinkShape.translate(Eigen::Vector3d(0.1, -0.2, 0.3));
  s.X_LinkShape.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  return s;
}

// Every point of the shape lies in a sphere; no point of a sphere lies farther than the
// stated overshoot from the shape; the ball of a sphere's inner radius lies in the shape.
void expect_cover_holds(const CollisionPrimitive& s, double target_m) {
  const SphereCover cover = cover_with_spheres(s, target_m);
  ASSERT_FALSE(cover.spheres.empty());
  RandomStream random(3);
  const Eigen::Vector3d half = s.kind == CollisionPrimitive::Kind::kBox
                                   ? Eigen::Vector3d(0.5 * s.size_m)
                               : s.kind == CollisionPrimitive::Kind::kCylinder
                                   ? Eigen::Vector3d(s.size_m.x(), s.size_m.x(), 0.5 * s.size_m.y())
                                   : Eigen::Vector3d::Constant(s.size_m.x());
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d local(random.uniform(-half.x(), half.x()),
                                random.uniform(-half.y(), half.y()),
                                random.uniform(-half.z(), half.z()));
    const Eigen::Vector3d p = s.X_LinkShape * local;
    if (outside(s, p) > 0.0) continue;
    ++inside;
    bool held = false;
    for (const Sphere& sphere : cover.spheres)
      held = held || (p - sphere.center_m).norm() <= sphere.radius_m + 1e-12;
    ASSERT_TRUE(held) << "a point of the shape outside every sphere";
  }
  EXPECT_GT(inside, 5000);
  double worst = 0.0;
  for (const Sphere& sphere : cover.spheres)
    for (int i = 0; i < 2000; ++i) {
      Eigen::Vector3d u(random.normal(), random.normal(), random.normal());
      worst = std::max(worst, outside(s, sphere.center_m + sphere.radius_m * u.normalized()));
    }
  EXPECT_LE(worst, cover.overshoot_m + 1e-9);
  EXPECT_GT(worst, 0.5 * cover.overshoot_m);  // the bound is not loose
  // The ball of each sphere's inner radius lies inside the shape, and reaches its surface.
  for (const Sphere& sphere : cover.spheres) {
    ASSERT_GT(sphere.inner_m, 0.0);
    double nearest = 1e9;
    for (int i = 0; i < 2000; ++i) {
      Eigen::Vector3d u(random.normal(), random.normal(), random.normal());
      const Eigen::Vector3d p = sphere.center_m + sphere.inner_m * u.normalized();
      ASSERT_LE(outside(s, p), 1e-12) << "a point of the inner ball outside the shape";
      nearest = std::min(nearest, depth(s, p));
    }
    EXPECT_LT(nearest, 0.05 * sphere.inner_m + 1e-6);  // the inner radius is not loose
  }
}

TEST(SphereCover, HoldsBoxesAndKeepsToTheOvershoot) {
  expect_cover_holds(shape(CollisionPrimitive::Kind::kBox, {0.07, 0.18, 0.058}), 0.01);
  expect_cover_holds(shape(CollisionPrimitive::Kind::kBox, {0.01, 0.013, 0.108}), 0.01);
  expect_cover_holds(shape(CollisionPrimitive::Kind::kBox, {0.3, 0.3, 0.3}), 0.02);
  const SphereCover plate =
      cover_with_spheres(shape(CollisionPrimitive::Kind::kBox, {0.2, 0.2, 0.01}), 0.02);
  EXPECT_LE(plate.overshoot_m, 0.02);
  EXPECT_GT(plate.spheres.size(), 4U);
}

TEST(SphereCover, HoldsCylindersAndKeepsToTheOvershoot) {
  expect_cover_holds(shape(CollisionPrimitive::Kind::kCylinder, {0.06, 0.273, 0}), 0.01);
  expect_cover_holds(shape(CollisionPrimitive::Kind::kCylinder, {0.06, 0.1, 0}), 0.01);
  expect_cover_holds(shape(CollisionPrimitive::Kind::kCylinder, {0.008, 0.3, 0}), 0.002);
  // A flat end costs (sqrt(2) - 1) R whatever the target; a thin long one keeps to it.
  const SphereCover fat =
      cover_with_spheres(shape(CollisionPrimitive::Kind::kCylinder, {0.06, 0.5, 0}), 0.01);
  EXPECT_NEAR(fat.overshoot_m, (std::sqrt(2.0) - 1.0) * 0.06, 1e-9);
  const SphereCover thin =
      cover_with_spheres(shape(CollisionPrimitive::Kind::kCylinder, {0.01, 0.5, 0}), 0.005);
  EXPECT_LE(thin.overshoot_m, 0.005);
}

TEST(SphereCover, RefusesBadInput) {
  EXPECT_EQ(error_of([] {
              cover_with_spheres(shape(CollisionPrimitive::Kind::kBox, {0.1, 0, 0.1}), 0.01);
            }),
            "sphere cover: a box needs positive sizes");
  EXPECT_EQ(error_of([] {
              cover_with_spheres(shape(CollisionPrimitive::Kind::kSphere, {0.1, 0, 0}), 0.0);
            }),
            "sphere cover: the overshoot and the sphere budget must be positive");
}

TEST(DistanceGrid, NeverCallsASphereTouchingAnOccupiedCubeClear) {
  RandomStream random(11);
  std::vector<Eigen::Vector3f> points;
  points.reserve(3000);
  for (int i = 0; i < 3000; ++i)
    points.emplace_back(float(random.uniform(0.4, 0.6)), float(random.uniform(-0.3, -0.1)),
                        float(random.uniform(-0.3, -0.2)));
  const double resolution = 0.01;
  // Distances reach past the largest sphere tested (15 cm) and the grid's margin.
  const DistanceGrid grid(points, resolution, 0.2);
  // The occupied cubes, to measure against.
  std::vector<Eigen::Vector3d> cubes;
  cubes.reserve(points.size());
  for (const Eigen::Vector3f& p : points)
    cubes.push_back((p.cast<double>() * (1.0 / resolution)).array().floor().matrix() * resolution);
  int clear = 0, touching = 0, loose = 0;
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3f c(float(random.uniform(0.2, 0.8)), float(random.uniform(-0.5, 0.1)),
                            float(random.uniform(-0.45, 0.0)));
    const float r = float(random.uniform(0.0, 0.15));
    std::uint8_t marked = 0;
    grid.mark_touching(&c.x(), &c.y(), &c.z(), &r, 1, &marked);
    double nearest = 1e9;
    for (const Eigen::Vector3d& lo : cubes)
      nearest = std::min(
          nearest,
          outside_box(c.cast<double>() - (lo + Eigen::Vector3d::Constant(0.5 * resolution)),
                      Eigen::Vector3d::Constant(0.5 * resolution)));
    const bool touches = nearest <= r;
    touching += touches;
    if (!marked) {
      ++clear;
      ASSERT_FALSE(touches) << "sphere at " << c.transpose() << " radius " << r << " touches";
      EXPECT_GT(nearest - r, -1e-6);
    } else if (nearest - r > 1.5 * std::sqrt(3.0) * resolution + 2e-4) {
      ++loose;  // flagged farther than the grid's margin allows from the cell centres
    }
  }
  EXPECT_LT(loose, 10);  // the rest: spheres near the grid's border, read across a row
  EXPECT_GT(clear, 500);
  EXPECT_GT(touching, 500);
  EXPECT_EQ(error_of([] { DistanceGrid({}, 0.0, 0.1); }),
            "distance grid: the resolution and reach must be positive, got 0.000000 and 0.100000");
}

TEST(DistanceGrid, StaysSafeWhenItsCellsGrowOverAWideCloud) {
  // Two clusters 40 m apart: at 1 cm cubes the grid would exceed its cell budget, so its
  // cells span several cubes.
  RandomStream random(4);
  std::vector<Eigen::Vector3f> points;
  points.reserve(2000);
  for (int i = 0; i < 2000; ++i) {
    const float far = i % 2 ? 40.0f : 0.0f;
    points.emplace_back(far + float(random.uniform(0, 0.1)), float(random.uniform(0, 0.1)),
                        float(random.uniform(0, 0.1)));
  }
  const DistanceGrid grid(points, 0.01, 0.1);
  EXPECT_LE(grid.cells(), std::size_t(16e6));
  for (int i = 0; i < 2000; ++i) {
    const float far = i % 2 ? 40.0f : 0.0f;
    const Eigen::Vector3f c(far + float(random.uniform(-0.2, 0.3)),
                            float(random.uniform(-0.2, 0.3)), float(random.uniform(-0.2, 0.3)));
    const float r = float(random.uniform(0.0, 0.1));
    std::uint8_t marked = 0;
    grid.mark_touching(&c.x(), &c.y(), &c.z(), &r, 1, &marked);
    if (marked) continue;
    for (const Eigen::Vector3f& p : points) {
      const Eigen::Vector3d lo = (p.cast<double>() * 100.0).array().floor().matrix() * 0.01;
      ASSERT_GT(outside_box(c.cast<double>() - (lo + Eigen::Vector3d::Constant(0.005)),
                            Eigen::Vector3d::Constant(0.005)),
                r);
    }
  }
}

TEST(ScrewChain, AgreesWithTheChainsForwardKinematics) {
  for (const char* file :
       {"robots/baxter/baxter.yaml", "robots/panda/panda.yaml", "robots/ur5e/ur5e.yaml"}) {
    const RobotFile robot_file = read_robot_file(source(file));
    const RobotModel robot = RobotModel::load(robot_file.urdf_path);
    const KinematicChain arm = robot.chain(robot.root_link(), robot_file.arm_tip);
    const ScrewChain fast(arm);
    RandomStream random(5);
    std::vector<Pose3f> joints(fast.dof());
    std::vector<Eigen::Isometry3d> in_double(fast.links());
    double worst = 0.0, worst_double = 0.0;
    for (int i = 0; i < 1000; ++i) {
      const Eigen::VectorXd q = arm.random_configuration(random);
      fast.joint_poses(q.data(), joints.data());
      fast.link_poses(q.data(), in_double.data());
      const std::vector<Eigen::Isometry3d> links = arm.link_poses(q);
      ASSERT_EQ(links.size(), fast.links());
      for (std::size_t s = 0; s < links.size(); ++s) {
        worst_double =
            std::max({worst_double, (in_double[s].translation() - links[s].translation()).norm(),
                      (in_double[s].linear() - links[s].linear()).cwiseAbs().maxCoeff()});
        const int j = fast.joint_of(s);
        Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
        if (j >= 0)
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) X.linear()(a, b) = joints[std::size_t(j)].R[3 * a + b];
            X.translation()(a) = joints[std::size_t(j)].t[a];
          }
        X = X * fast.X_JointLink(s);
        worst = std::max(worst, (X.translation() - links[s].translation()).norm());
      }
    }
    EXPECT_LT(worst, 1e-5) << file;
    EXPECT_LT(worst_double, 1e-12) << file;  // the exact checks' poses: KDL's to rounding
  }
}

TEST(ScrewChain, TurnsByWholeTurnsAsTheChainDoes) {
  // Far outside any limit (a continuous joint's angle can be): reduced in double first.
  const RobotFile robot_file = read_robot_file(source("robots/baxter/baxter.yaml"));
  const RobotModel robot = RobotModel::load(robot_file.urdf_path);
  const ScrewChain fast(robot.chain(robot.root_link(), robot_file.arm_tip));
  Eigen::VectorXd q(7), turned(7);
  q << 0.3, -0.5, 1.1, 1.2, -0.4, 0.9, 2.0;
  turned = q.array() + 2.0 * M_PI * 1e5;
  std::vector<Pose3f> a(fast.dof()), b(fast.dof());
  fast.joint_poses(q.data(), a.data());
  fast.joint_poses(turned.data(), b.data());
  for (std::size_t j = 0; j < fast.dof(); ++j)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[j].t[i], b[j].t[i], 1e-5) << "joint " << j;
}

// A robot's arm in a scene, in the three check modes.
struct Scene {
  std::vector<std::pair<Eigen::Isometry3d, Eigen::Vector3d>> boxes;
  std::vector<Eigen::Vector3f> points;
};

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(x, y, z);
  return X;
}

// The table and the clutter box of the cell's scenes, a pile of points in the box and three
// clouds of points in the arm's way above it.
Scene cell_scene() {
  Scene s;
  const double top = -0.295;
  s.boxes.push_back({at(0.725, -0.135, top - 0.025), {0.9, 1.0, 0.05}});
  s.boxes.push_back({at(0.44, -0.2, top + 0.03), {0.01, 0.3, 0.06}});
  s.boxes.push_back({at(0.74, -0.2, top + 0.03), {0.01, 0.3, 0.06}});
  s.boxes.push_back({at(0.59, -0.35, top + 0.03), {0.3, 0.01, 0.06}});
  s.boxes.push_back({at(0.59, -0.05, top + 0.03), {0.3, 0.01, 0.06}});
  RandomStream random(2);
  for (int i = 0; i < 10000; ++i)
    s.points.emplace_back(float(random.uniform(0.45, 0.73)), float(random.uniform(-0.34, -0.06)),
                          float(top + 0.1 * random.uniform() * random.uniform()));
  for (const Eigen::Vector3d& centre :
       {Eigen::Vector3d(0.6, 0.1, 0.1), Eigen::Vector3d(0.4, -0.5, 0.2),
        Eigen::Vector3d(0.8, -0.2, 0.3)})
    for (int i = 0; i < 2000; ++i)
      s.points.push_back(
          (centre + 0.08 * Eigen::Vector3d(random.normal(), random.normal(), random.normal()))
              .cast<float>());
  return s;
}

ArmCollisionWorld world_of(const RobotModel& robot, const RobotFile& file, const Scene& scene,
                           CheckMode mode) {
  CollisionOptions options;
  options.mode = mode;
  ArmCollisionWorld world(robot, robot.chain(robot.root_link(), file.arm_tip), {}, options);
  for (std::size_t b = 0; b < scene.boxes.size(); ++b)
    world.add_box("box" + std::to_string(b), scene.boxes[b].first, scene.boxes[b].second);
  if (!scene.points.empty())
    world.set_points(scene.points, 0.01, shaped_links_below(robot, file.points_unchecked));
  return world;
}

// 100,000 random configurations: the spheres alone never call free what FCL finds in
// contact, call at most `max_false_share` of FCL's free configurations in contact, and spheres
// then FCL give FCL's exact report.
void expect_conservative(const char* robot_path, const Scene& scene, double max_false_share) {
  const RobotFile file = read_robot_file(source(robot_path));
  const RobotModel robot = RobotModel::load(file.urdf_path);
  const ArmCollisionWorld exact = world_of(robot, file, scene, CheckMode::kExact);
  const ArmCollisionWorld spheres = world_of(robot, file, scene, CheckMode::kSpheres);
  const ArmCollisionWorld both = world_of(robot, file, scene, CheckMode::kSpheresThenExact);
  const KinematicChain arm = robot.chain(robot.root_link(), file.arm_tip);
  RandomStream random(17);
  int free = 0, false_contacts = 0;
  for (int i = 0; i < 100000; ++i) {
    const Eigen::VectorXd q = arm.random_configuration(random);
    const ContactReport truth = exact.check(q);
    const ContactReport fast = spheres.check(q);
    ASSERT_FALSE(fast.free() && !truth.free()) << "spheres call free: " << truth.str();
    ASSERT_EQ(both.check(q).str(), truth.str());
    free += truth.free();
    false_contacts += truth.free() && !fast.free();
  }
  EXPECT_GT(free, 10000);
  // In batches: the first configuration in contact is the one the checks one by one find.
  RandomStream again(17);
  for (int batch = 0; batch < 2000; ++batch) {
    std::vector<Eigen::VectorXd> qs;
    const int n = 1 + batch % 40;
    qs.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i) qs.push_back(arm.random_configuration(again));
    std::size_t first = qs.size();
    for (std::size_t i = 0; i < qs.size() && first == qs.size(); ++i)
      if (!exact.check(qs[i]).free()) first = i;
    ASSERT_EQ(both.first_contact(qs), first);
    ASSERT_EQ(exact.first_contact(qs), first);
    ASSERT_LE(spheres.first_contact(qs), first);  // conservative
  }
  const double share = double(false_contacts) / free;
  EXPECT_LE(share, max_false_share) << robot_path;
  std::printf("%s %s: %d free by FCL, the spheres call %.1f%% of them in contact\n", robot_path,
              scene.points.empty() ? "alone" : "in the cell", free, 100.0 * share);
  ::testing::Test::RecordProperty(
      std::string("false_contact_share_") + (scene.points.empty() ? "alone" : "cell"),
      std::to_string(share));
}

TEST(SphereCollision, BaxterAloneIsConservative) {
  expect_conservative("robots/baxter/baxter.yaml", {}, 0.15);
}
TEST(SphereCollision, BaxterInTheCellIsConservative) {
  expect_conservative("robots/baxter/baxter.yaml", cell_scene(), 0.3);
}
TEST(SphereCollision, PandaAloneIsConservative) {
  expect_conservative("robots/panda/panda.yaml", {}, 0.15);
}
TEST(SphereCollision, PandaInTheCellIsConservative) {
  expect_conservative("robots/panda/panda.yaml", cell_scene(), 0.3);
}

// Turns the batched check's culling back on when a test ends, even when an assertion fails.
struct CullingRestored {
  CullingRestored() = default;
  CullingRestored(const CullingRestored&) = delete;
  CullingRestored& operator=(const CullingRestored&) = delete;
  ~CullingRestored() { set_sphere_culling(true); }
};

// The batched check skips the sphere tests of a link pair, or a link and a box, whose bounding
// spheres are apart in all of a batch's configurations; it must flag the configurations that
// testing every pair flags: one at a time (every lane the same), and 16 different ones at a
// time (the first flagged, which a skip decided by one lane alone would miss).
void expect_culling_changes_nothing(const char* robot_path, const Scene& scene) {
  const RobotFile file = read_robot_file(source(robot_path));
  const RobotModel robot = RobotModel::load(file.urdf_path);
  const ArmCollisionWorld spheres = world_of(robot, file, scene, CheckMode::kSpheres);
  const KinematicChain arm = robot.chain(robot.root_link(), file.arm_tip);
  const CullingRestored restored;
  RandomStream random(29);
  int flagged = 0;
  const int batches = 800;  // 12,800 configurations
  for (int batch = 0; batch < batches; ++batch) {
    std::vector<Eigen::VectorXd> qs;
    for (int i = 0; i < kBatchLanes; ++i) qs.push_back(arm.random_configuration(random));
    set_sphere_culling(false);
    const std::size_t dense = spheres.first_contact(qs);
    std::vector<std::size_t> dense_one;
    for (const Eigen::VectorXd& q : qs) dense_one.push_back(spheres.first_contact({q}));
    set_sphere_culling(true);
    ASSERT_EQ(spheres.first_contact(qs), dense) << "batch " << batch;
    for (std::size_t i = 0; i < qs.size(); ++i) {
      ASSERT_EQ(spheres.first_contact({qs[i]}), dense_one[i]) << "batch " << batch << ", " << i;
      flagged += dense_one[i] == 0;
    }
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(flagged, batches / 2);
  EXPECT_LT(flagged, batches * 29 / 2);  // 14.5 of a batch's 16, as with 2,000 batches
}

// More boxes than the spheres' record names one by one (from the 31st on they share a bit):
// spheres then FCL still find FCL's first contact in every batch, culled or not.
TEST(SphereCollision, ManyBoxesAreConfirmedAsFclFindsThem) {
  const RobotFile file = read_robot_file(source("robots/baxter/baxter.yaml"));
  const RobotModel robot = RobotModel::load(file.urdf_path);
  Scene scene;
  RandomStream random(31);
  for (int b = 0; b < 40; ++b)
    scene.boxes.push_back(
        {at(random.uniform(0.3, 1.0), random.uniform(-0.9, 0.1), random.uniform(-0.3, 0.6)),
         Eigen::Vector3d(random.uniform(0.03, 0.15), random.uniform(0.03, 0.15),
                         random.uniform(0.03, 0.15))});
  const ArmCollisionWorld exact = world_of(robot, file, scene, CheckMode::kExact);
  const ArmCollisionWorld both = world_of(robot, file, scene, CheckMode::kSpheresThenExact);
  const KinematicChain arm = robot.chain(robot.root_link(), file.arm_tip);
  const CullingRestored restored;
  int free = 0, late_boxes = 0;
  for (int batch = 0; batch < 1500; ++batch) {
    std::vector<Eigen::VectorXd> qs;
    for (int i = 0, n = 1 + batch % kBatchLanes; i < n; ++i)
      qs.push_back(arm.random_configuration(random));
    const std::size_t first = exact.first_contact(qs);
    for (const bool cull : {true, false}) {
      set_sphere_culling(cull);
      ASSERT_EQ(both.first_contact(qs), first) << "batch " << batch << (cull ? "" : ", dense");
    }
    free += first == qs.size();
    if (first < qs.size()) {
      const std::string other = exact.check(qs[first]).other;
      late_boxes += other.size() == 5 && other.rfind("box3", 0) == 0;  // box30 ... box39
    }
  }
  // Both answers occur, and first contacts with the boxes that share a bit.
  EXPECT_GT(free, 20);
  EXPECT_GT(late_boxes, 10);
  std::printf("%d of 1500 batches free, %d first contacts with box30 ... box39\n", free,
              late_boxes);
}

TEST(SphereCollision, BaxterSkipsOnlyTestsThatCannotHit) {
  Scene boxes = cell_scene();
  boxes.points.clear();
  expect_culling_changes_nothing("robots/baxter/baxter.yaml", boxes);
  expect_culling_changes_nothing("robots/baxter/baxter.yaml", cell_scene());
}
TEST(SphereCollision, PandaSkipsOnlyTestsThatCannotHit) {
  Scene boxes = cell_scene();
  boxes.points.clear();
  expect_culling_changes_nothing("robots/panda/panda.yaml", boxes);
}

}  // namespace
}  // namespace antipode::collision
