#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <utility>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "mesh_io.hpp"
#include "mesh_objects.hpp"
#include "physics_world.hpp"
#include "primitive_meshes.hpp"
#include "procedural_objects.hpp"
#include "scene_builder.hpp"

namespace antipode::cells {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(PrimitiveMeshes, EncloseTheirVolumes) {
  EXPECT_NEAR(box_mesh({0.01f, 0.02f, 0.03f}).volume(), 0.02 * 0.04 * 0.06, 1e-9);
  EXPECT_NEAR(cylinder_mesh(0.025f, 0.1f, 64).volume(), kPi * 0.025 * 0.025 * 0.1, 2e-6);
  EXPECT_NEAR(ellipsoid_mesh(Eigen::Vector3f::Constant(0.03f), 48).volume(),
              4.0 / 3.0 * kPi * 0.03 * 0.03 * 0.03, 3e-6);
  const double r = 0.02, h = 0.05;
  EXPECT_NEAR(capsule_mesh(float(r), float(h), 48).volume(),
              kPi * r * r * h + 4.0 / 3.0 * kPi * r * r * r, 3e-6);
  EXPECT_TRUE(cylinder_mesh(0.02f, 0.1f).volume_centroid().norm() < 1e-6);
}

TEST(ProceduralObjects, MostAreGraspableSomeAreNot) {
  RandomStream random(3);
  int graspable = 0;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    const auto& shapes = procedural_shapes();
    const ObjectModel m = make_random_object(shapes[i % shapes.size()], ProceduralRanges{}, random);
    const double density = m.mass_kg / m.visual->volume();
    EXPECT_GT(m.mass_kg, 0.0);
    if (m.mass_kg > 0.006) {
      EXPECT_GE(density, 399.0);
      EXPECT_LE(density, 1001.0);
    }
    EXPECT_LE(m.friction, 1.0);
    if (m.graspable_width_m >= 0.03 && m.graspable_width_m <= 0.07) ++graspable;
  }
  EXPECT_GT(graspable, n * 6 / 10);
  EXPECT_LT(graspable, n);
}

TEST(ProceduralObjects, SameSeedSameObject) {
  RandomStream a(11), b(11);
  const ObjectModel x = make_random_object("box", ProceduralRanges{}, a);
  const ObjectModel y = make_random_object("box", ProceduralRanges{}, b);
  EXPECT_EQ(x.mass_kg, y.mass_kg);
  EXPECT_EQ(x.collision.half_extents_m, y.collision.half_extents_m);
}

TEST(ProceduralObjects, RejectsUnknownShapesAndBadSizes) {
  EXPECT_THROW(make_object("torus", {0.05}, 500, 0.8), Error);
  EXPECT_THROW(make_object("box", {0.05, 0.05}, 500, 0.8), Error);
  EXPECT_THROW(make_object("cylinder", {-0.05, 0.1}, 500, 0.8), Error);
}

// Every edge is used once in each direction: closed, and consistently oriented.
bool closed_and_consistent(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    if (count != 1) return false;
    const auto back = edges.find({edge.second, edge.first});
    if (back == edges.end() || back->second != 1) return false;
  }
  return !edges.empty();
}

Eigen::Vector3d extents(const ObjectModel& m) { return m.visual->bounds().sizes().cast<double>(); }

void expect_sound(const ObjectModel& m, double density) {
  EXPECT_TRUE(closed_and_consistent(*m.visual)) << m.name;
  EXPECT_GT(m.visual->volume(), 0.0) << m.name;
  EXPECT_NEAR(m.mass_kg, m.visual->volume() * density, 1e-9) << m.name;
  EXPECT_LT(m.visual->volume_centroid().norm(), 1e-5) << m.name;  // frame at the centre of mass
  EXPECT_GT(m.collision.hulls.size(), 1u) << m.name;              // a compound of convex parts
  for (const auto& hull : m.collision.hulls) {
    EXPECT_TRUE(closed_and_consistent(hull)) << m.name;
    EXPECT_TRUE(m.visual->bounds().isApprox(m.visual->bounds().merged(hull.bounds()), 1e-4f))
        << m.name << ": a collision part sticks out of the visual mesh";
  }
}

TEST(ProceduralShapes, BottleHasBodyShoulderAndNeck) {
  const ObjectModel m = make_object("bottle", {0.06, 0.2, 0.025, 0.04}, 800, 0.8);
  expect_sound(m, 800);
  EXPECT_TRUE(extents(m).isApprox(Eigen::Vector3d(0.06, 0.06, 0.2), 1e-3));
  // Body cylinder + cone frustum + neck cylinder (the 32-gon's area is 0.6% under the circle).
  const double R = 0.03, r = 0.0125, shoulder = R - r, body = 0.2 - 0.04 - shoulder;
  const double exact = kPi * (R * R * body + r * r * 0.04 + shoulder / 3 * (R * R + R * r + r * r));
  EXPECT_NEAR(m.visual->volume(), exact, 0.01 * exact);
  EXPECT_EQ(m.collision.hulls.size(), 2u);
  EXPECT_DOUBLE_EQ(m.graspable_width_m, 0.06);
  EXPECT_THROW(make_object("bottle", {0.06, 0.2, 0.07, 0.04}, 800, 0.8), Error);
  EXPECT_THROW(make_object("bottle", {0.06, 0.05, 0.02, 0.04}, 800, 0.8), Error);
}

TEST(ProceduralShapes, MugHasBodyAndHandle) {
  const ObjectModel m = make_object("mug", {0.07, 0.09}, 600, 0.8);
  expect_sound(m, 600);
  const Eigen::Vector3d e = extents(m);
  EXPECT_NEAR(e.y(), 0.07, 1e-3);
  EXPECT_NEAR(e.z(), 0.09, 1e-3);
  EXPECT_GT(e.x(), 0.07 + 0.02);  // the handle sticks out on +x
  EXPECT_LT(e.x(), 0.07 + 0.05);
  const double body = kPi * 0.035 * 0.035 * 0.09;
  EXPECT_GT(m.visual->volume(), body * 0.99);
  EXPECT_LT(m.visual->volume(), body * 1.15);
  EXPECT_THROW(make_object("mug", {0.07, 0.02}, 600, 0.8), Error);
}

TEST(ProceduralShapes, BananaIsACurvedCapsule) {
  const double d = 0.035, length = 0.18, bend = 0.12;
  const ObjectModel m = make_object("banana", {d, length, bend}, 900, 0.8);
  expect_sound(m, 900);
  const Eigen::Vector3d e = extents(m);
  EXPECT_NEAR(e.z(), d, 1e-3);  // lies flat, curved in xy
  const double angle = (length - d) / bend;
  EXPECT_NEAR(e.x(), 2 * (bend * std::sin(angle / 2) + d / 2), 1e-3);  // across the ends
  EXPECT_GT(e.y(), d + 0.01);                                          // and it bends
  // Pappus: a tube of cross-section pi r^2 along the arc, plus a ball from the two ends.
  const double exact = kPi * d * d / 4 * (length - d) + kPi * d * d * d / 6;
  EXPECT_NEAR(m.visual->volume(), exact, 0.04 * exact);
  EXPECT_THROW(make_object("banana", {0.05, 0.04, 0.1}, 900, 0.8), Error);
  EXPECT_THROW(make_object("banana", {0.05, 0.6, 0.1}, 900, 0.8), Error);
}

TEST(ProceduralShapes, LAndTAreTwoBars) {
  const ObjectModel l = make_object("l_shape", {0.04, 0.12, 0.09, 0.05}, 500, 0.8);
  expect_sound(l, 500);
  EXPECT_TRUE(extents(l).isApprox(Eigen::Vector3d(0.09, 0.12, 0.05), 1e-4));
  EXPECT_NEAR(l.visual->volume(), (0.04 * 0.12 + 0.05 * 0.04) * 0.05, 1e-9);
  const ObjectModel t = make_object("t_shape", {0.03, 0.12, 0.08, 0.04}, 500, 0.8);
  expect_sound(t, 500);
  EXPECT_TRUE(extents(t).isApprox(Eigen::Vector3d(0.12, 0.11, 0.04), 1e-4));
  EXPECT_NEAR(t.visual->volume(), (0.03 * 0.08 + 0.12 * 0.03) * 0.04, 1e-9);
  EXPECT_THROW(make_object("l_shape", {0.04, 0.03, 0.09, 0.05}, 500, 0.8), Error);
}

TEST(ProceduralShapes, RandomOnesAreSoundAndDeterministic) {
  for (const char* shape : {"bottle", "mug", "banana", "l_shape", "t_shape"}) {
    int graspable = 0;
    for (int i = 0; i < 40; ++i) {
      RandomStream a(100 + i), b(100 + i);
      const ObjectModel x = make_random_object(shape, ProceduralRanges{}, a);
      const ObjectModel y = make_random_object(shape, ProceduralRanges{}, b);
      EXPECT_EQ(x.mass_kg, y.mass_kg);
      EXPECT_EQ(x.visual->vertices, y.visual->vertices);
      EXPECT_TRUE(closed_and_consistent(*x.visual)) << shape;
      EXPECT_GT(x.visual->volume(), 0.0) << shape;
      EXPECT_LT(extents(x).maxCoeff(), 0.3) << shape;
      if (x.graspable_width_m >= 0.03 && x.graspable_width_m <= 0.07) ++graspable;
    }
    EXPECT_GT(graspable, 20) << shape;
    EXPECT_LT(graspable, 40) << shape;
  }
}

TEST(ProceduralShapes, UnknownNamesSuggestTheNearestShape) {
  try {
    make_object("bottel", {0.05}, 500, 0.8);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'bottle'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("t_shape"), std::string::npos) << e.what();
  }
}

// Mesh files a user may get wrong: a face index past what an int holds, a vertex at 1e30, a
// face naming a vertex that does not exist - each one clear error naming the file.
TEST(MeshObjects, BadObjFilesAreClearErrors) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("bad_mesh_" + std::to_string(::getpid()) + ".obj"))
          .string();
  const auto error_of = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      read_obj(path);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(error_of(triangle + "f 1 2 3\n"), "no error");
  EXPECT_NE(
      error_of(triangle + "f 1 2 99999999999\n").find("face refers to vertex 99999999999 of 3"),
      std::string::npos);
  EXPECT_NE(error_of(triangle + "f 1 2 x\n").find("is not a vertex number"), std::string::npos);
  EXPECT_NE(error_of("v 1e30 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("beyond 1000 m"),
            std::string::npos);
  std::filesystem::remove(path);
}

// A folder of its own under the temporary directory, removed when the test ends however it
// ends.
struct ScratchFolder {
  explicit ScratchFolder(const std::string& name)
      : path(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~ScratchFolder() { std::filesystem::remove_all(path); }
  std::filesystem::path path;
};

// A mesh in millimetres (a 60 mm cube written as 60 units) is named as such, not dropped on
// the table 60 m wide; scaled by 0.001 it loads.
TEST(MeshObjects, AMeshInMillimetresIsAClearError) {
  const ScratchFolder scratch("mm_meshes");
  const std::filesystem::path& folder = scratch.path;
  std::ofstream obj(folder / "cube.obj");
  for (int corner = 0; corner < 8; ++corner)
    obj << "v " << (corner & 1) * 60 << ' ' << (corner >> 1 & 1) * 60 << ' ' << (corner >> 2) * 60
        << '\n';
  obj << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  obj.close();
  try {
    load_mesh_object(folder.string(), "cube", 1.0, 700, 0.8);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("object 'cube' of '" + folder.string() +
                                         "' is 60 m across at scale 1: object meshes must "
                                         "be in metres"),
              std::string::npos)
        << e.what();
  }
  const ObjectModel cube = load_mesh_object(folder.string(), "cube", 0.001, 700, 0.8);
  EXPECT_NEAR(cube.graspable_width_m, 0.06, 1e-6);
}

// A scan left open at the top with faces wound both ways - as scans often come - has a
// signed volume near zero: its centre of mass comes from its hulls, inside the object, and it
// stands on the table like any other.
TEST(MeshObjects, AnOpenScanWoundBothWaysStandsOnTheTable) {
  const ScratchFolder scratch("open_scan");
  const std::filesystem::path& folder = scratch.path;
  {
    // A 6.6 cm can 10 cm tall (48 sides, 4 rings), its bottom closed, its top open, each
    // triangle's winding flipped by a seeded coin: its signed volume is under 1% of its box
    // and its volume centroid 40 cm away.
    std::ofstream obj(folder / "can.obj");
    const int sides = 48, rings = 4, column = rings + 1;
    for (int i = 0; i < sides; ++i)
      for (int r = 0; r <= rings; ++r) {
        const double a = 2.0 * M_PI * i / sides;
        obj << "v " << 0.033 * std::cos(a) << ' ' << 0.033 * std::sin(a) << ' ' << 0.1 * r / rings
            << '\n';
      }
    obj << "v 0 0 0\n";
    std::uint64_t state = 21;
    const auto face = [&](int a, int b, int c) {  // 0-based corners; OBJ counts from 1
      state = (state * 1103515245u + 12345u) % (1u << 31);
      if ((state >> 16) & 1u) std::swap(b, c);
      obj << "f " << a + 1 << ' ' << b + 1 << ' ' << c + 1 << '\n';
    };
    for (int i = 0; i < sides; ++i) {
      const int j = (i + 1) % sides;
      for (int r = 0; r < rings; ++r) {
        const int a = i * column + r, b = j * column + r;
        face(a, b, b + 1);
        face(a, b + 1, a + 1);
      }
      face(sides * column, j * column, i * column);
    }
  }
  const ObjectModel can = load_mesh_object(folder.string(), "can", 1.0, 700, 0.8);
  EXPECT_TRUE(can.visual->bounds().contains(Eigen::Vector3f::Zero())) << "its centre of mass";
  EXPECT_LT(can.visual->bounds().center().head<2>().norm(), 0.02) << "near its axis";
  const SceneSpec spec =
      parse_scene(Parameters(YAML::Load("placement: isolated\nobjects:\n  - { mesh: can, folder: " +
                                        folder.string() + ", position_m: [0.72, -0.12] }\n"),
                             "scene 'test.yaml'", "test.yaml"));
  PhysicsWorld world(PhysicsOptions{});
  MeshCache meshes;
  const std::vector<int> ids = build_scene(spec, 0, meshes, world);
  ASSERT_EQ(ids.size(), 1u) << "the can stayed on the table";
  EXPECT_NEAR(world.pose(ids[0]).translation().x(), 0.72, 0.02);
}

TEST(MeshObjects, LoadsYcbAndBlobsWhenTheDataIsThere) {
  const std::string data = ANTIPODE_TEST_DATA_DIR;
  if (!std::filesystem::exists(data + "/objects/ycb/025_mug/visual.obj"))
    GTEST_SKIP() << "shared data not found at " << data;
  const ObjectModel mug = load_mesh_object(data + "/objects/ycb", "025_mug", 1.0, 700, 0.8);
  EXPECT_GT(mug.collision.hulls.size(), 8u) << "its cavity stays open (convex_decomposition)";
  EXPECT_GT(mug.visual->triangles.size(), 10000u);
  EXPECT_LT(mug.visual->bounds().center().norm(), 0.03f);
  const ObjectModel blob = load_mesh_object(data + "/objects/blobs", "007", 0.015, 700, 0.8);
  EXPECT_GE(blob.collision.hulls.size(), 1u);
  const Eigen::AlignedBox3f around = blob.visual->bounds();
  for (const auto& hull : blob.collision.hulls)  // pieces of the visual mesh, not beyond it
    EXPECT_TRUE(around.contains(hull.bounds().min()) && around.contains(hull.bounds().max()));
  EXPECT_GT(blob.visual->bounds().sizes().maxCoeff(), 0.01f);
  EXPECT_LT(blob.visual->bounds().sizes().maxCoeff(), 0.2f);
  EXPECT_EQ(list_mesh_objects(data + "/objects/ycb").size(), 15u);
}

}  // namespace
}  // namespace antipode::cells
