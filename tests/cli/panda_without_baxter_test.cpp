// The Panda's trees with Baxter gone: a copy of the shipped trees, scenes, the Panda's robot
// and gripper files and its model - no robots/baxter/, no Baxter model - where clearing the
// box, planning a reach and checking the robot all run with `--set robot=...` alone. Any
// Baxter default left in code or trees would fail here (a missing file, or a Baxter-sized
// hand the Franka model refuses).
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "support/command_output.hpp"

namespace {
namespace fs = std::filesystem;

class PandaWithoutBaxterTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const fs::path source = ANTIPODE_TEST_SOURCE_DIR;
    root_ = fs::temp_directory_path() / ("antipode_panda_only_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "robots");
    fs::create_directories(root_ / "models");
    for (const char* folder : {"trees", "scenes"})
      fs::copy(source / folder, root_ / folder, fs::copy_options::recursive);
    for (const char* folder : {"robots/panda", "robots/grippers"})
      fs::copy(source / folder, root_ / folder, fs::copy_options::recursive);
    for (const char* model : {"hog_svm_franka.model", "hog_svm_franka_outcome.model"})
      fs::copy(source / "models" / model, root_ / "models" / model);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static antipode::testing::CommandResult antipode(const std::string& arguments) {
    return antipode::testing::run_command("cd '" + root_.string() + "' && " +
                                          std::string(ANTIPODE_CLI) + " " + arguments);
  }
  static fs::path root_;
};

fs::path PandaWithoutBaxterTest::root_;

TEST_F(PandaWithoutBaxterTest, ClearsASeededBoxOfFourObjects) {
  const auto r = antipode(
      "run trees/clear_box.yaml --set robot=robots/panda/panda.yaml --set cell.object_count=4 "
      "--set cell.seed=3");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // Seed 3 clears all four in four attempts (six with `labels=antipodal`); a floor of three
  // leaves room for other CPUs.
  int cleared = -1;
  const auto at = r.out.find("cleared ");
  ASSERT_NE(at, std::string::npos) << r.out;
  cleared = std::stoi(r.out.substr(at + 8));
  EXPECT_GE(cleared, 3) << r.out;
}

TEST_F(PandaWithoutBaxterTest, PlansAReachIntoTheClutterBox) {
  const auto r = antipode("run trees/plan_reach.yaml --set robot=robots/panda/panda.yaml");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("grasps selected"), std::string::npos) << r.out;
}

TEST_F(PandaWithoutBaxterTest, PassesItsChecks) {
  const auto r = antipode("robot check robots/panda/panda.yaml --configurations 100");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("all checks passed"), std::string::npos) << r.out;
}

}  // namespace
