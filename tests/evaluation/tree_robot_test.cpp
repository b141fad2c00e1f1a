// Which robot a pick tree runs with (tree_robot_path), and how reports name a robot put in
// the tree's place (robot_words): the benches take the holdable range and the titles from it.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "antipode/evaluation/report_markdown.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"

namespace antipode::evaluation {
namespace {

namespace fs = std::filesystem;
const std::string kSource = ANTIPODE_TEST_SOURCE_DIR;

TEST(TreeRobotTest, TheLastSetRobotElseTheTreesSettingElseNone) {
  const std::string tree = kSource + "/trees/clear_box.yaml";
  EXPECT_EQ(fs::path(tree_robot_path(tree, {})).filename(), "baxter.yaml");
  EXPECT_TRUE(fs::exists(tree_robot_path(tree, {})));
  EXPECT_EQ(fs::path(tree_robot_path(tree, {"robot=robots/ur5e/ur5e.yaml", "cell.seed=3",
                                            "robot=" + kSource + "/robots/panda/panda.yaml"}))
                .filename(),
            "panda.yaml");
  EXPECT_EQ(tree_robot_path(kSource + "/trees/detect.yaml", {}), "");  // no robot setting
  const fs::path broken = fs::temp_directory_path() / ("tree_robot_" + std::to_string(::getpid()));
  std::ofstream(broken) << "settings: [robot\n";
  EXPECT_EQ(tree_robot_path(broken.string(), {}), "");  // loading the tree reports it
  fs::remove(broken);
}

// A setting as a run sees it: the last override, else the tree's own, as written.
TEST(TreeRobotTest, TreeSettingTakesTheLastOverrideElseTheTreesValue) {
  const std::string tree = kSource + "/trees/clear_box.yaml";
  EXPECT_EQ(tree_setting(tree, {}, "labels"), "outcome_or_antipodal");
  EXPECT_EQ(tree_setting(tree, {"labels=outcome", "labels=antipodal"}, "labels"), "antipodal");
  EXPECT_EQ(tree_setting(tree, {"labelsx=outcome"}, "labels"), "outcome_or_antipodal");
  EXPECT_EQ(tree_setting(tree, {}, "no_such_setting"), "");
}

TEST(TreeRobotTest, ReportsNameTheRobotASetPutInTheTreesPlace) {
  nlohmann::ordered_json report = {{"tree", "trees/clear_box.yaml"},
                                   {"overrides", {"cell.seed=3"}}};
  EXPECT_EQ(robot_words(report), "");
  report["overrides"].push_back("robot=" + kSource + "/robots/panda/panda.yaml");
  EXPECT_EQ(robot_words(report), "Franka Emika Panda");  // read from the robot file
  report["robot"] = {{"file", "x"}, {"name", "A robot"}};
  EXPECT_EQ(robot_words(report), "A robot");  // the report's own name first
  report.erase("robot");
  report["overrides"] = {"robot=/gone/arm7.yaml"};
  EXPECT_EQ(robot_words(report), "arm7");  // the report outlived its file
}

}  // namespace
}  // namespace antipode::evaluation
