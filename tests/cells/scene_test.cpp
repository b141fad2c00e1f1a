#include <gtest/gtest.h>
#include <unistd.h>

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "scene_builder.hpp"

namespace antipode::cells {
namespace {

SceneSpec parse(const std::string& yaml) {
  return parse_scene(Parameters(YAML::Load(yaml), "scene 'test.yaml'", "test.yaml"));
}

const char* kPile = R"(
box: { inner_size_m: [0.3, 0.3], wall_height_m: 0.06 }
placement: pile
random_objects: { count: 6, shapes: [box, cylinder, sphere, capsule, ellipsoid] }
)";

TEST(Scene, PileSettlesInsideTheBoxWithoutInterpenetration) {
  const SceneSpec spec = parse(kPile);
  PhysicsWorld world(PhysicsOptions{});
  MeshCache meshes;
  const std::vector<int> ids = build_scene(spec, 5, meshes, world);
  ASSERT_EQ(ids.size(), 6u);
  world.step();
  EXPECT_LT(world.deepest_penetration(), 0.003);
  const Eigen::Vector2d lo = spec.box.center_m - spec.box.inner_size_m / 2;
  const Eigen::Vector2d hi = spec.box.center_m + spec.box.inner_size_m / 2;
  for (int id : ids) {
    const Eigen::Vector3d p = world.pose(id).translation();
    EXPECT_GT(p.x(), lo.x());
    EXPECT_LT(p.x(), hi.x());
    EXPECT_GT(p.y(), lo.y());
    EXPECT_LT(p.y(), hi.y());
    EXPECT_GT(p.z(), spec.table.top_z_m);
    EXPECT_LT(p.z(), spec.table.top_z_m + 0.25);
    EXPECT_LT(world.body(id).getLinearVelocity().length(), 0.05);
  }
}

// Balls dropped from high into a small, low box: some bounce out; with refills, each is
// dropped again until it stays in.
TEST(Scene, RefillsPutBackWhatBouncedOutOfTheBox) {
  SceneSpec spec = parse(R"(
box: { inner_size_m: [0.12, 0.12], wall_height_m: 0.02 }
placement: pile
drop_height_m: 0.4
random_objects: { count: 6, shapes: [sphere] }
)");
  const auto outside = [&](int refills) {
    spec.box.refills = refills;
    int count = 0;
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
      PhysicsWorld world(PhysicsOptions{});
      MeshCache meshes;
      for (int id : build_scene(spec, seed, meshes, world))
        count += !inside_box(spec.box, world.pose(id).translation());
    }
    return count;
  };
  EXPECT_GT(outside(0), 0);
  EXPECT_EQ(outside(5), 0);
}

// VGN's pile: the box is lifted away once the objects have settled; no wall is left and
// the objects stay on the table.
TEST(Scene, ABoxRemovedAfterTheDropLeavesThePileOnTheTable) {
  const SceneSpec spec =
      read_scene(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/scenes/vgn_pile.yaml");
  ASSERT_TRUE(spec.box.removed_after_drop);
  const auto walls_of = [](const PhysicsWorld& world) {
    int walls = 0;
    for (int id = 0; id < 1000; ++id) walls += world.has(id) && world.name(id) == "box wall";
    return walls;
  };
  SceneSpec kept = spec;
  kept.box.removed_after_drop = false;
  PhysicsWorld with_box(PhysicsOptions{});
  MeshCache meshes;
  build_scene(kept, 3, meshes, with_box);
  EXPECT_EQ(walls_of(with_box), 4);  // the same scene keeps its box without the key
  PhysicsWorld world(PhysicsOptions{});
  const std::vector<int> ids = build_scene(spec, 3, meshes, world);
  EXPECT_EQ(ids.size(), 5u);
  EXPECT_EQ(walls_of(world), 0);
  for (int id : ids) {
    EXPECT_GT(world.pose(id).translation().z(), spec.table.top_z_m);
    EXPECT_LT(world.body(id).getLinearVelocity().length(), 0.05);
  }
}

TEST(Scene, SameSeedSameSceneOtherSeedOtherScene) {
  const SceneSpec spec = parse(kPile);
  auto poses = [&](std::uint64_t seed) {
    PhysicsWorld world(PhysicsOptions{});
    MeshCache meshes;
    std::vector<Eigen::Matrix4d> out;
    for (int id : build_scene(spec, seed, meshes, world)) out.push_back(world.pose(id).matrix());
    return out;
  };
  const auto a = poses(9), b = poses(9), c = poses(10);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]);
  EXPECT_NE(a.front(), c.front());
}

TEST(Scene, PackedObjectsStandUprightOnTheTable) {
  const SceneSpec spec = parse(R"(
placement: packed
random_objects: { count: 4, shapes: [cylinder, box] }
)");
  PhysicsWorld world(PhysicsOptions{});
  MeshCache meshes;
  const std::vector<int> ids = build_scene(spec, 2, meshes, world);
  ASSERT_EQ(ids.size(), 4u);
  for (int id : ids) EXPECT_GT(world.pose(id).linear().col(2).z(), 0.95);
}

TEST(Scene, ListedObjectRestsWhereItIsPut) {
  const SceneSpec spec = parse(R"(
placement: isolated
objects:
  - { shape: cylinder, size_m: [0.05, 0.1], position_m: [0.7, -0.1] }
)");
  PhysicsWorld world(PhysicsOptions{});
  MeshCache meshes;
  const std::vector<int> ids = build_scene(spec, 0, meshes, world);
  ASSERT_EQ(ids.size(), 1u);
  const Eigen::Vector3d p = world.pose(ids[0]).translation();
  EXPECT_NEAR(p.x(), 0.7, 0.002);
  EXPECT_NEAR(p.y(), -0.1, 0.002);
  EXPECT_NEAR(p.z(), spec.table.top_z_m + 0.05, 0.003);
}

TEST(Scene, ReportsBadKeysWithTheirPlace) {
  try {
    parse("placement: pile\nrandom_objects: { count: 2, shapes: [box], shapez: [box] }\n");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("shapez"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse("placement: heap\n"), Error);
  EXPECT_THROW(parse("placement: isolated\nrandom_objects: { count: 2, shapes: [box] }\n"), Error);
  EXPECT_THROW(parse("objects:\n  - { shape: box, size_m: [0.1, 0.1, 0.1], friction: 1.5 }\n"),
               Error);
}

// Sizes that no table or box can have, and a scene file with nothing in it.
TEST(Scene, ImpossibleSizesAndAnEmptyFileAreErrors) {
  const auto error_of = [](const std::string& text) {
    try {
      parse(text);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("table: { size_m: [-0.9, 1.0] }\n").find("'size_m' must be two sizes"),
            std::string::npos);
  EXPECT_NE(error_of("box: { inner_size_m: [0.3, 0] }\n").find("'inner_size_m'"),
            std::string::npos);
  EXPECT_NE(error_of("table: { top_z_m: 1e30 }\n").find("'top_z_m'"), std::string::npos);
  // A NaN anywhere in a vector, not only first.
  for (const char* yaml :
       {"fixtures: [{ size_m: [0.1, 4.0, .nan] }]\n", "fixtures: [{ size_m: [.nan, 4.0, 0.1] }]\n",
        "box: { inner_size_m: [0.3, .nan] }\n", "table: { center_m: [0.7, .inf] }\n"})
    EXPECT_NE(error_of(yaml).find("must be finite numbers"), std::string::npos) << yaml;
  std::string crowd = "objects:\n";
  for (int i = 0; i < 101; ++i) crowd += "  - { shape: sphere, size_m: [0.05] }\n";
  EXPECT_NE(error_of(crowd).find("'objects' lists 101 objects; a scene holds at most 100"),
            std::string::npos)
      << error_of(crowd);
  const std::string empty = (std::filesystem::temp_directory_path() /
                             ("empty_scene_" + std::to_string(::getpid()) + ".yaml"))
                                .string();
  std::ofstream(empty).close();
  try {
    read_scene(empty);
    FAIL() << "an empty scene file was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the file is empty"), std::string::npos) << e.what();
  }
  std::filesystem::remove(empty);
}

TEST(Scene, MeshPilesFromTheSharedDataSettleInTheBox) {
  const std::string data = ANTIPODE_TEST_DATA_DIR;
  if (!std::filesystem::exists(data + "/objects/ycb") ||
      !std::filesystem::exists(data + "/objects/blobs"))
    GTEST_SKIP() << "shared data not found at " << data;
  for (const char* file : {"pile_ycb.yaml", "pile_blobs.yaml"}) {
    const SceneSpec spec = read_scene(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/scenes/" + file);
    PhysicsWorld world(PhysicsOptions{});
    MeshCache meshes;
    const std::vector<int> ids = build_scene(spec, spec.seed, meshes, world);
    EXPECT_GE(ids.size(), std::size_t(spec.random.count - 1)) << file;
    world.step();
    EXPECT_LT(world.deepest_penetration(), 0.003) << file;
    for (int id : ids) {
      const Eigen::Vector3d p = world.pose(id).translation();
      EXPECT_LT((p.head<2>() - spec.box.center_m).cwiseAbs().maxCoeff(), 0.16) << file;
    }
  }
}

TEST(Scene, EachNewShapeSettlesOnTheTable) {
  for (const char* shape : {"bottle", "mug", "banana", "l_shape", "t_shape"}) {
    const SceneSpec spec = parse(std::string("placement: isolated\nrandom_objects: { count: 1, "
                                             "shapes: [") +
                                 shape + "] }\n");
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      PhysicsWorld world(PhysicsOptions{});
      MeshCache meshes;
      const std::vector<int> ids = build_scene(spec, seed, meshes, world);
      ASSERT_EQ(ids.size(), 1u) << shape << " seed " << seed;
      world.step();
      EXPECT_LT(world.deepest_penetration(), 0.003) << shape << " seed " << seed;
      EXPECT_LT(world.body(ids[0]).getLinearVelocity().length(), 0.05) << shape;
      // Its lowest point rests on the table top (within the 1 mm margins).
      const ObjectModel model = scene_objects(spec, seed, meshes).at(0);
      double lowest = 1e9;
      for (const auto& v : model.visual->vertices)
        lowest = std::min(lowest, (world.pose(ids[0]) * v.cast<double>()).z());
      EXPECT_NEAR(lowest, spec.table.top_z_m, 0.003) << shape << " seed " << seed;
      // Same seed, same pose.
      PhysicsWorld again(PhysicsOptions{});
      const std::vector<int> ids2 = build_scene(spec, seed, meshes, again);
      again.step();
      EXPECT_EQ(world.pose(ids[0]).matrix(), again.pose(ids2.at(0)).matrix()) << shape;
    }
  }
}

TEST(Scene, PileOfNewShapesSettlesInsideTheBox) {
  const SceneSpec spec = parse(R"(
box: { inner_size_m: [0.3, 0.3], wall_height_m: 0.06 }
placement: pile
random_objects: { count: 8, shapes: [bottle, mug, banana, l_shape, t_shape] }
)");
  PhysicsWorld world(PhysicsOptions{});
  MeshCache meshes;
  const std::vector<int> ids = build_scene(spec, 4, meshes, world);
  EXPECT_GE(ids.size(), 7u);
  world.step();
  EXPECT_LT(world.deepest_penetration(), 0.003);
  // Long objects landing on the pile may tip over the 6 cm walls; nearly all stay inside.
  std::size_t inside = 0;
  for (int id : ids) {
    const Eigen::Vector3d p = world.pose(id).translation();
    if ((p.head<2>() - spec.box.center_m).cwiseAbs().maxCoeff() < 0.16) ++inside;
    EXPECT_GT(p.z(), spec.table.top_z_m);
  }
  EXPECT_GE(inside + 1, ids.size());
}

TEST(Scene, EveryShippedSceneParsesAndTheHouseholdPileSettles) {
  const std::filesystem::path folder = std::filesystem::path(ANTIPODE_TEST_SOURCE_DIR) / "scenes";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".yaml") continue;
    EXPECT_NO_THROW(read_scene(entry.path().string())) << entry.path();
    ++files;
  }
  EXPECT_GE(files, 8);
  const SceneSpec spec = read_scene((folder / "pile_household.yaml").string());
  PhysicsWorld world(PhysicsOptions{});
  MeshCache meshes;
  const std::vector<int> ids = build_scene(spec, spec.seed, meshes, world);
  EXPECT_GE(ids.size(), 9u);
  world.step();
  EXPECT_LT(world.deepest_penetration(), 0.003);
}

TEST(Scene, UnknownShapesAreReportedWithASuggestion) {
  try {
    parse("placement: pile\nrandom_objects: { count: 2, shapes: [box, banan] }\n");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'banana'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse("objects:\n  - { shape: l-shape, size_m: [0.1] }\n"), Error);
}

TEST(Scene, DefaultCamerasLookAtTheTableFromTwoSides) {
  const SceneSpec spec = parse("placement: pile\n");
  ASSERT_GE(spec.cameras.size(), 2u);
  EXPECT_EQ(spec.cameras[0].name, "left");
  EXPECT_EQ(spec.cameras[1].name, "right");
  EXPECT_GT(spec.cameras[0].position_m.y(), 0.2);
  EXPECT_LT(spec.cameras[1].position_m.y(), -0.4);
}

}  // namespace
}  // namespace antipode::cells
