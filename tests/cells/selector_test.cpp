#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/plugin/plugin_host.hpp"

namespace antipode {
namespace {

class TableTopSelectorTest : public ::testing::Test {
 protected:
  TableTopSelectorTest() : host_(std::vector<std::string>{}) {
    host_.load_library(std::string(ANTIPODE_TEST_PLUGIN_DIR) + "/" +
                       plugin_file_name("table_top_selector"));
  }

  std::shared_ptr<GraspSelector> create(const std::string& yaml) {
    const Parameters params(YAML::Load(yaml), "component 'selector'", "tree.yaml");
    return std::dynamic_pointer_cast<GraspSelector>(host_.create("table_top_selector", params));
  }

  PluginHost host_;
};

// A hand approaching straight down with its palm face at height z.
Hand top_down(double z, double score) {
  Hand hand;
  Eigen::Matrix3d r;
  r << 0, 1, 0, 0, 0, -1, -1, 0, 0;
  hand.X_FrameHand.linear() = r;
  hand.X_FrameHand.translation() << 0.7, -0.1, z;
  hand.score = score;
  return hand;
}

TEST_F(TableTopSelectorTest, RanksByScoreAndDropsHandsThatReachIntoTheTable) {
  const auto selector = create("table_z_m: -0.3\nmax_grasps: 2");
  HandSet set;
  set.hands = {top_down(-0.2, 0.01), top_down(-0.25, 0.05), top_down(-0.22, 0.03),
               top_down(-0.1, 0.04)};
  set.hands[3].rejection = Rejection::kInCollision;
  const std::vector<Hand> chosen = selector->select(set);
  ASSERT_EQ(chosen.size(), 2u);  // -0.25: fingertips at -0.31, below the table
  EXPECT_DOUBLE_EQ(chosen[0].score, 0.03);
  EXPECT_DOUBLE_EQ(chosen[1].score, 0.01);
}

TEST_F(TableTopSelectorTest, ChecksTheStandOffPoseToo) {
  const auto selector = create("table_z_m: -0.3");
  HandSet set;
  Hand upwards = top_down(-0.2, 1.0);
  upwards.X_FrameHand.linear() = Eigen::Matrix3d(
      Eigen::AngleAxisd(3.14159265358979, Eigen::Vector3d::UnitY()) * upwards.X_FrameHand.linear());
  set.hands = {upwards};  // approaching from below: 10 cm back is under the table
  EXPECT_TRUE(selector->select(set).empty());
}

TEST_F(TableTopSelectorTest, RejectsBadParameters) {
  EXPECT_THROW(create(""), Error);
  EXPECT_THROW(create("table_z_m: -0.3\nstandof_m: 0.1"), Error);
  EXPECT_THROW(create("table_z_m: -0.3\nmax_grasps: 0"), Error);
}

}  // namespace
}  // namespace antipode
