#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/interfaces/sampler.hpp"
#include "antipode/plugin/plugin_host.hpp"
#include "support/error_of.hpp"
#include "synthetic_shapes.hpp"

namespace antipode {
namespace {

Parameters params(const std::string& yaml) {
  return Parameters(YAML::Load(yaml), "component 'sampler'", "tree.yaml");
}

class AntipodalSamplerTest : public ::testing::Test {
 protected:
  AntipodalSamplerTest() : host_(std::vector<std::string>{}) {
    host_.load_library(std::string(ANTIPODE_TEST_PLUGIN_DIR) + "/" +
                       plugin_file_name("antipodal_sampler"));
  }

  std::shared_ptr<Sampler> create(const std::string& yaml) {
    return std::dynamic_pointer_cast<Sampler>(host_.create("antipodal_sampler", params(yaml)));
  }

  std::string creation_error(const std::string& yaml) {
    return testing::error_of([&] { create(yaml); });
  }

  PluginHost host_;
};

Cloud cylinder() { return testing::cylinder_cloud({0.0, 0.0, 0.6}, {0.1, 1.0, 0.0}, 0.05, 0.15); }

TEST_F(AntipodalSamplerTest, LoadsAsASampler) {
  ASSERT_EQ(host_.records().size(), 1u);
  EXPECT_EQ(host_.records()[0].state, PluginRecord::State::kLoaded) << host_.records()[0].reason;
  EXPECT_EQ(host_.kind_of("antipodal_sampler"), ComponentKind::kSampler);
  EXPECT_NE(create(""), nullptr);
}

TEST_F(AntipodalSamplerTest, SamplesHandsOnAPreprocessedCloud) {
  const auto sampler = create("samples: 300\nvoxel_size_m: 0.004\nthreads: 2");
  const Cloud raw = cylinder();
  const HandSet set = sampler->sample(raw, RandomStream(5), {});
  ASSERT_NE(set.cloud, nullptr);
  EXPECT_LT(set.cloud->size(), raw.size());
  ASSERT_GT(set.hands.size(), 20u);
  for (const Hand& hand : set.hands) {
    EXPECT_EQ(hand.frame, raw.frame);
    EXPECT_FALSE(hand.closing_points.empty());
    EXPECT_LT(static_cast<std::size_t>(hand.sample_index), set.cloud->size());
  }
}

TEST_F(AntipodalSamplerTest, SameResultAsTheFrameworkFunctionForAnyThreadCount) {
  const Cloud raw = cylinder();
  HandSamplingOptions options;
  options.search.samples = 200;
  options.search.threads = 1;
  const HandSet direct = sample_hands(raw, options, RandomStream(9));
  for (const char* threads : {"1", "2"}) {
    const HandSet via_plugin =
        create(std::string("samples: 200\nthreads: ") + threads)->sample(raw, RandomStream(9), {});
    ASSERT_EQ(via_plugin.hands.size(), direct.hands.size()) << threads << " threads";
    for (std::size_t i = 0; i < direct.hands.size(); ++i) {
      EXPECT_EQ(via_plugin.hands[i].X_FrameHand.matrix(), direct.hands[i].X_FrameHand.matrix());
      EXPECT_EQ(via_plugin.hands[i].closing_points, direct.hands[i].closing_points);
    }
  }
}

// The bites follow the hand's fingers unless set: half their depth, and half that where the
// support stopped the hand - the framework's search with those bites gives the same hands.
TEST_F(AntipodalSamplerTest, TheBitesFollowTheFingerDepthUnlessSet) {
  const Cloud raw = cylinder();
  HandSamplingOptions options;
  options.search.samples = 200;
  options.search.threads = 1;
  options.search.hand.depth_m = 0.04;
  options.search.min_bite_m = 0.02;
  options.search.min_bite_at_support_m = 0.01;
  const HandSet direct = sample_hands(raw, options, RandomStream(9));
  const std::string shorter = "samples: 200\nthreads: 1\nhand: {depth_m: 0.04}\n";
  const HandSet followed = create(shorter)->sample(raw, RandomStream(9), {});
  ASSERT_EQ(followed.hands.size(), direct.hands.size());
  for (std::size_t i = 0; i < direct.hands.size(); ++i)
    EXPECT_EQ(followed.hands[i].X_FrameHand.matrix(), direct.hands[i].X_FrameHand.matrix());
  // Baxter's 3 cm asked of 4 cm fingers: a 10 cm cylinder's shoulders stop more of them.
  const HandSet fixed = create(shorter + "min_bite_m: 0.03")->sample(raw, RandomStream(9), {});
  EXPECT_LT(fixed.hands.size(), followed.hands.size());
}

TEST_F(AntipodalSamplerTest, ReadsEveryDocumentedParameter) {
  const std::string yaml = R"(
samples: 100
voxel_size_m: 0.003
neighbourhood_radius_m: 0.03
min_neighbours: 12
orientations: 6
positions: 10
workspace: {min: [-0.5, -0.5, 0.0], max: [0.5, 0.5, 1.5]}
sample_region: {min: [-0.1, -0.1, 0.4], max: [0.1, 0.1, 0.8]}
hand: {finger_width_m: 0.01, outer_diameter_m: 0.1, depth_m: 0.06, height_m: 0.02,
       init_bite_m: 0.01, min_aperture_m: 0.02, max_aperture_m: 0.08, palm_thickness_m: 0.03}
min_bite_m: 0.02
clearance_m: 0.002
max_view_angle_deg: 80
reject_hidden_fingers: false
occlusion_margin_m: 0.02
point_radius_m: 0.003
keep_all_positions: true
threads: 1
view_origin: [0, 0, 0]
support_plane: auto
support_distance_m: 0.008
approach_tilts_deg: [30]
tilted_orientation_range_deg: 20
objects: auto
max_range_m: 3.0
scene: {max_planes: 3, max_object_height_m: 0.3, max_object_size_m: 0.4, max_gap_m: 0.02,
        cluster_tolerance_m: 0.005, min_object_points: 20, up: [0, -1, 0], max_tilt_deg: 40,
        fixtures: [[-1, -1, -1, -0.9, -0.9, -0.9]],
        bin: {center_m: [2, 2], inner_size_m: [0.3, 0.3], floor_z_m: 0}}
)";
  const auto sampler = create(yaml);
  ASSERT_NE(sampler, nullptr);
  EXPECT_FALSE(sampler->sample(cylinder(), RandomStream(1), {}).hands.empty());
}

TEST_F(AntipodalSamplerTest, BadParametersAreLocatedErrors) {
  EXPECT_EQ(creation_error("sampels: 10"),
            "tree.yaml:1:1: unknown parameter 'sampels' of component 'sampler' (did you mean "
            "'samples'?)");
  EXPECT_EQ(creation_error("a: 1\nsamples: 0"),
            "tree.yaml:2:1: parameter 'samples' must be at least 1, got 0");
  EXPECT_EQ(creation_error("workspace: {min: [0, 0], max: [1, 1, 1]}"),
            "tree.yaml:1:13: parameter 'min' must be a list [x, y, z]");
  EXPECT_EQ(creation_error("workspace: {min: [0, 2, 0], max: [1, 1, 1]}"),
            "tree.yaml:1:1: parameter 'workspace': min y is above max y");
  EXPECT_EQ(creation_error("hand: {max_aperture_m: 0.2}"),
            "tree.yaml:1:1: hand geometry: max_aperture_m + 2 * finger_width_m exceeds "
            "outer_diameter_m");
  EXPECT_EQ(creation_error("hand: {depht_m: 0.05}"),
            "tree.yaml:1:8: unknown parameter 'depht_m' of component 'sampler'.hand (did you "
            "mean 'depth_m'?)");
  EXPECT_EQ(creation_error("min_bite_m: 0.5"),
            "tree.yaml:1:1: hand search: min_bite_m must be in [0, depth_m], got 0.5");
  EXPECT_NE(creation_error("scene: {bin: {center_m: [0, 0]}}")
                .find("missing required parameter 'inner_size_m'"),
            std::string::npos);
  EXPECT_EQ(creation_error("support_plane: table"),
            "tree.yaml:1:1: parameter 'support_plane' must be 'auto' or 'none', got 'table'");
  EXPECT_EQ(creation_error("objects: some"),
            "tree.yaml:1:1: parameter 'objects' must be 'auto' or 'all', got 'some'");
  EXPECT_EQ(creation_error("scene: {max_planes: 0}"),
            "tree.yaml:1:9: parameter 'max_planes' must be at least 1, got 0");
  EXPECT_EQ(creation_error("support_distance_m: 0"),
            "tree.yaml:1:1: parameter 'support_distance_m' must be > 0.000000, got 0.000000");
  EXPECT_EQ(creation_error("support_distance_m: 0.5"),
            "tree.yaml:1:1: parameter 'support_distance_m' must be below 0.1, got 0.500000");
}

TEST_F(AntipodalSamplerTest, SupportPlaneModes) {
  // A table seen from above at 45 degrees, a 5 cm can standing on it; samples over all of it.
  const Eigen::Vector3d up = Eigen::Vector3d(0.0, -1.0, -1.0).normalized();
  const Eigen::Vector3d on_table(0.0, 0.0, 0.7);
  Cloud cloud = testing::plane_cloud(on_table, up, 0.3);
  testing::append(cloud, testing::cylinder_cloud(on_table + 0.06 * up, up, 0.05, 0.12));
  const auto on_the_table = [&](const HandSet& set) {
    std::size_t count = 0;
    for (const Hand& hand : set.hands) {
      const Eigen::Vector3d sample = set.cloud->points_m[hand.sample_index].cast<double>();
      count += (sample - on_table).dot(up) < 0.005;
    }
    return count;
  };
  const HandSet automatic = create("samples: 600")->sample(cloud, RandomStream(1), {});
  const HandSet none =
      create("samples: 600\nsupport_plane: none")->sample(cloud, RandomStream(1), {});
  ASSERT_FALSE(automatic.hands.empty());
  EXPECT_EQ(on_the_table(automatic), 0u);
  EXPECT_GT(on_the_table(none), 0u);  // the table's cut border looks like a plate's edge
}

TEST_F(AntipodalSamplerTest, ObjectsAutoSamplesTheObjectsAndNamesThemOnEachHand) {
  // A table seen from above at 45 degrees with two cans: only the cans are sampled, each
  // hand names its can.
  const Eigen::Vector3d up = Eigen::Vector3d(0.0, -1.0, -1.0).normalized();
  const Eigen::Vector3d on_table(0.0, 0.0, 0.7);
  Cloud cloud = testing::plane_cloud(on_table, up, 0.4);
  for (const double x : {-0.08, 0.08}) {
    testing::append(cloud, testing::cylinder_cloud(on_table + Eigen::Vector3d(x, 0, 0) + 0.06 * up,
                                                   up, 0.05, 0.12));
  }
  const HandSet set = create("samples: 600\nobjects: auto")->sample(cloud, RandomStream(2), {});
  ASSERT_EQ(set.objects.size(), 2u);
  ASSERT_GT(set.hands.size(), 20u);
  std::vector<char> on_object(set.cloud->size(), 0);
  for (const SceneObject& object : set.objects)
    for (const std::int32_t i : object.points) on_object[std::size_t(i)] = 1;
  std::size_t per_object[2] = {0, 0};
  for (const Hand& hand : set.hands) {
    EXPECT_TRUE(on_object[std::size_t(hand.sample_index)]) << "a sample off the objects";
    ASSERT_GE(hand.object, 0);
    ASSERT_LT(hand.object, 2);
    ++per_object[hand.object];
    const double x = hand.position_m().x();
    EXPECT_EQ(hand.object, x < 0.0 ? 0 : 1) << "hand at x = " << x;
  }
  EXPECT_GT(per_object[0], 5u);
  EXPECT_GT(per_object[1], 5u);
  const HandSet all = create("samples: 600\nobjects: all")->sample(cloud, RandomStream(2), {});
  EXPECT_TRUE(all.objects.empty());
  for (const Hand& hand : all.hands) EXPECT_EQ(hand.object, -1);
}

// A 30 cm box on a table seen from above, with a can as tall as the walls pressed against its
// -x wall and another against its +x wall: through the walls the cans are one segment; with
// `scene.bin` the walls are fixtures and each can is an object of its own.
TEST_F(AntipodalSamplerTest, ABinsWallsAreFixturesOfTheScene) {
  const double floor_z = -0.5;
  Cloud cloud = testing::plane_cloud({0, 0, floor_z}, Eigen::Vector3d::UnitZ(), 0.6);
  const Eigen::Matrix3d level = Eigen::Matrix3d::Identity();
  for (const double side : {-1.0, 1.0}) {
    testing::append(
        cloud, testing::box_cloud({side * 0.155, 0, floor_z + 0.03}, level, {0.01, 0.32, 0.06}));
    testing::append(
        cloud, testing::box_cloud({0, side * 0.155, floor_z + 0.03}, level, {0.30, 0.01, 0.06}));
    testing::append(cloud, testing::cylinder_cloud({side * 0.127, side * 0.05, floor_z + 0.03},
                                                   Eigen::Vector3d::UnitZ(), 0.05, 0.06));
  }
  const std::string yaml = "samples: 300\nobjects: auto\nview_origin: [0, 0, 0]\n";
  const HandSet walls_join = create(yaml)->sample(cloud, RandomStream(3), {});
  EXPECT_EQ(walls_join.objects.size(), 1u) << "the cans and the walls, one segment";
  const HandSet apart =
      create(yaml + "scene: {bin: {center_m: [0, 0], inner_size_m: [0.3, 0.3], floor_z_m: " +
             std::to_string(floor_z) + "}}")
          ->sample(cloud, RandomStream(3), {});
  ASSERT_EQ(apart.objects.size(), 2u);
  for (const SceneObject& object : apart.objects)
    EXPECT_NEAR(std::abs(object.centroid_m.x()), 0.127, 0.02) << "a can, not a wall";
}

TEST_F(AntipodalSamplerTest, UnusableCloudsAreErrors) {
  const auto sampler = create("workspace: {min: [5, 5, 5], max: [6, 6, 6]}");
  EXPECT_THROW(sampler->sample(cylinder(), RandomStream(1), {}), Error);
  EXPECT_THROW(create("")->sample(Cloud{}, RandomStream(1), {}), Error);
}

TEST_F(AntipodalSamplerTest, CloudsWithoutViewsUseTheConfiguredOrigin) {
  Cloud raw = cylinder();
  raw.view_origins_m.clear();
  raw.view_masks.clear();
  const HandSet seen_from_origin = create("samples: 200")->sample(raw, RandomStream(4), {});
  EXPECT_FALSE(seen_from_origin.hands.empty());
  ASSERT_EQ(seen_from_origin.cloud->view_origins_m.size(), 1u);
  const HandSet seen_from_elsewhere =
      create("samples: 200\nview_origin: [0, 0, 2]")->sample(raw, RandomStream(4), {});
  EXPECT_TRUE(seen_from_elsewhere.cloud->view_origins_m[0].isApprox(Eigen::Vector3f(0, 0, 2)));
}

}  // namespace
}  // namespace antipode
