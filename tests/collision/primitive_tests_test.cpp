// The primitives' quick tests: where they answer, FCL answers the same, over random pairs of
// boxes, cylinders and spheres near each other; they answer for most pairs; and known cases
// near a cylinder's curved side, where a box bounding the cylinder would meet what the cylinder
// does not.

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <gtest/gtest.h>

#include "antipode/core/random.hpp"
#include "primitive_tests.hpp"

namespace antipode::collision {
namespace {

using Kind = CollisionPrimitive::Kind;

std::shared_ptr<fcl::CollisionGeometryd> geometry(const PlacedPrimitive& p) {
  switch (p.kind) {
    case Kind::kBox:
      return std::make_shared<fcl::Boxd>(p.size_m.x(), p.size_m.y(), p.size_m.z());
    case Kind::kCylinder:
      return std::make_shared<fcl::Cylinderd>(p.size_m.x(), p.size_m.y());
    case Kind::kSphere:
      return std::make_shared<fcl::Sphered>(p.size_m.x());
  }
  return nullptr;
}

bool fcl_meet(const PlacedPrimitive& a, const PlacedPrimitive& b) {
  const fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(geometry(a).get(), a.X_FrameShape, geometry(b).get(), b.X_FrameShape, request,
               result);
  return result.isCollision();
}

PlacedPrimitive random_primitive(Kind kind, RandomStream& random, const Eigen::Vector3d& at) {
  PlacedPrimitive p;
  p.kind = kind;
  switch (kind) {
    case Kind::kBox:
      p.size_m = Eigen::Vector3d(random.uniform(0.01, 0.3), random.uniform(0.01, 0.3),
                                 random.uniform(0.01, 0.3));
      break;
    case Kind::kCylinder:
      p.size_m = Eigen::Vector3d(random.uniform(0.01, 0.1), random.uniform(0.02, 0.3), 0.0);
      break;
    case Kind::kSphere:
      p.size_m = Eigen::Vector3d(random.uniform(0.01, 0.15), 0.0, 0.0);
      break;
  }
  p.X_FrameShape.translation() = at;
  p.X_FrameShape.linear() =
      Eigen::Quaterniond(random.normal(), random.normal(), random.normal(), random.normal())
          .normalized()
          .toRotationMatrix();
  return p;
}

const char* name(Kind kind) {
  return kind == Kind::kBox ? "box" : kind == Kind::kCylinder ? "cylinder" : "sphere";
}

TEST(PrimitiveTests, AnswerAsFclDoesAndAnswerMostPairs) {
  RandomStream random(5);
  const Kind kinds[] = {Kind::kBox, Kind::kCylinder, Kind::kSphere};
  for (const Kind ka : kinds)
    for (const Kind kb : kinds) {
      int decided = 0, met = 0;
      const int pairs = 4000;
      for (int i = 0; i < pairs; ++i) {
        const PlacedPrimitive a = random_primitive(ka, random, Eigen::Vector3d::Zero());
        const Eigen::Vector3d offset(random.normal(), random.normal(), random.normal());
        const PlacedPrimitive b =
            random_primitive(kb, random, offset.normalized() * random.uniform(0.0, 0.3));
        const bool truth = fcl_meet(a, b);
        met += truth;
        const Verdict verdict = quick_test(a, b);
        if (verdict == Verdict::kUndecided) continue;
        ++decided;
        ASSERT_EQ(verdict == Verdict::kMeet, truth)
            << name(ka) << " with " << name(kb) << ", pair " << i;
        ASSERT_EQ(quick_test(b, a), verdict) << name(ka) << " with " << name(kb) << ", pair " << i;
      }
      // Both answers occur, and the tests leave few pairs to FCL.
      EXPECT_GT(met, pairs / 10) << name(ka) << " with " << name(kb);
      EXPECT_LT(met, pairs * 9 / 10) << name(ka) << " with " << name(kb);
      EXPECT_GT(decided, pairs * 95 / 100) << name(ka) << " with " << name(kb);
      std::printf("%s with %s: %d of %d pairs meet by FCL, %d decided\n", name(ka), name(kb), met,
                  pairs, decided);
    }
}

// A cylinder of radius 6 cm, 20 cm long, along z, and a 10 cm cube turned 45 degrees about z
// beside it (an edge towards the axis), its edge 3 mm outside the side or 3 mm inside it; and
// a cube over the flat end.
TEST(PrimitiveTests, TellTheCurvedSideAndTheFlatEnd) {
  PlacedPrimitive cylinder;
  cylinder.kind = Kind::kCylinder;
  cylinder.size_m = Eigen::Vector3d(0.06, 0.2, 0.0);
  const auto cube_at = [](const Eigen::Vector3d& direction, double edge_from_axis_m) {
    PlacedPrimitive cube;
    cube.size_m = Eigen::Vector3d::Constant(0.1);
    cube.X_FrameShape.linear() =
        Eigen::AngleAxisd(std::atan2(direction.y(), direction.x()) + M_PI / 4,
                          Eigen::Vector3d::UnitZ())
            .toRotationMatrix();
    cube.X_FrameShape.translation() =
        direction.normalized() * (edge_from_axis_m + 0.05 * std::sqrt(2.0));
    return cube;
  };
  // Along a diagonal of the cylinder's bounding box, whose corner reaches 8.5 cm out.
  const Eigen::Vector3d diagonal(1, 1, 0);
  EXPECT_EQ(quick_test(cylinder, cube_at(diagonal, 0.063)), Verdict::kApart);
  EXPECT_EQ(quick_test(cylinder, cube_at(diagonal, 0.057)), Verdict::kMeet);
  EXPECT_FALSE(fcl_meet(cylinder, cube_at(diagonal, 0.063)));
  EXPECT_TRUE(fcl_meet(cylinder, cube_at(diagonal, 0.057)));
  // Past the flat end: the cube above the axis, tilted 0.3 rad about x, its lowest edge (3.3 cm
  // from the axis) 3 mm above the end face, then 3 mm below it.
  PlacedPrimitive over;
  over.size_m = Eigen::Vector3d::Constant(0.1);
  over.X_FrameShape.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const double lowest = 0.05 * (std::cos(0.3) + std::sin(0.3));
  over.X_FrameShape.translation() = Eigen::Vector3d(0, 0, 0.1 + lowest + 0.003);
  EXPECT_EQ(quick_test(cylinder, over), Verdict::kApart);
  over.X_FrameShape.translation().z() -= 0.006;
  EXPECT_EQ(quick_test(cylinder, over), Verdict::kMeet);
  EXPECT_TRUE(fcl_meet(cylinder, over));
}

}  // namespace
}  // namespace antipode::collision
