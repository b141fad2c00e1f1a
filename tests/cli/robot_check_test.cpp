// `antipode robot check` as a robot's author runs it: the shipped robots pass; a robot whose
// shape is too big and whose gripper file is another gripper's fails, naming both; bad input
// is one error line.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/command_output.hpp"

namespace {
namespace fs = std::filesystem;

const std::string kSource = ANTIPODE_TEST_SOURCE_DIR;

antipode::testing::CommandResult check(const std::string& arguments) {
  return antipode::testing::run_command("cd '" + kSource + "' && " + std::string(ANTIPODE_CLI) +
                                        " robot check " + arguments);
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("antipode_robot_check_" + std::to_string(::getpid()) + "_" + name);
  fs::create_directories(dir);
  return dir;
}

TEST(RobotCheck, ThePandaPassesEveryCheck) {
  const fs::path dir = scratch("panda");
  const auto result =
      check("robots/panda/panda.yaml --configurations 300 --report " + (dir / "r.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("all checks passed"), std::string::npos) << result.out;
  std::ifstream in(dir / "r.json");
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["self_collision"]["home"], "free");
  EXPECT_EQ(report["self_collision"]["configurations"], 300);
  // The Panda's published reach is 0.855 m to the flange; the grasp frame is 6 cm beyond it.
  EXPECT_GT(report["reach_m"].get<double>(), 0.85);
  EXPECT_LT(report["reach_m"].get<double>(), 0.95);
  for (const auto& m : report["gripper"])
    if (m["required"].get<bool>()) EXPECT_TRUE(m["ok"].get<bool>()) << m;
  const auto& box = report["reach"][0];
  EXPECT_EQ(box["region"], "box floor");
  EXPECT_EQ(box["points"], 25);
  EXPECT_GE(box["points_reachable"].get<int>() + box["points_hand_blocked"].get<int>(), 23);
  fs::remove_all(dir);
}

TEST(RobotCheck, BaxterPassesEveryCheck) {
  const auto result = check("robots/baxter/baxter.yaml --configurations 200");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("reach from above, box floor: 25 of 25 points"), std::string::npos)
      << result.out;
}

// The UR5e, written by following docs/robot.md's guide from public numbers: six joints of
// +-2 pi, and its 2F-85-like fingers match their gripper file.
TEST(RobotCheck, TheGuidesUr5ePassesEveryCheck) {
  const auto result = check("robots/ur5e/ur5e.yaml --configurations 200");
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("arm 'base' -> 'ur5e_grasp', 6 joints"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("open aperture: URDF 0.0850 m, file 0.0850 m\n"), std::string::npos)
      << result.out;
}

// The Panda with its upper arm's housing ten times too wide and Baxter's gripper file.
TEST(RobotCheck, ABadShapeAndAnotherGrippersFileAreProblems) {
  const fs::path dir = scratch("bad");
  std::ifstream in(kSource + "/robots/panda/panda.urdf");
  std::stringstream text;
  text << in.rdbuf();
  std::string urdf = text.str();
  const std::string housing = R"(<cylinder radius="0.06" length="0.12"/>)";
  const auto at = urdf.find(housing, urdf.find(R"(<link name="panda_link3">)"));
  ASSERT_NE(at, std::string::npos);
  urdf.replace(at, housing.size(), R"(<cylinder radius="0.6" length="0.12"/>)");
  std::ofstream(dir / "bad.urdf") << urdf;
  std::ofstream(dir / "bad.yaml") << "urdf: bad.urdf\narm_tip: panda_grasp\n"
                                  << "gripper_from: panda_hand\n"
                                  << "home_rad: [0, -0.785, 0, -2.356, 0, 1.571, 0.785]\n"
                                  << "gripper: " << kSource
                                  << "/robots/grippers/baxter_electric.yaml\n";
  const auto result = check((dir / "bad.yaml").string() + " --configurations 100");
  EXPECT_EQ(result.exit_code, 1) << result.out;
  // Home collides with the oversized housing, and it leads the histogram of first contacts.
  EXPECT_NE(result.out.find("the home configuration is in self-collision: panda_link3 with"),
            std::string::npos)
      << result.out;
  const auto histogram = result.out.find("first pairs found:\n");
  ASSERT_NE(histogram, std::string::npos) << result.out;
  const std::string top =
      result.out.substr(histogram, result.out.find('\n', histogram + 20) - histogram);
  EXPECT_NE(top.find("panda_link3"), std::string::npos) << top;
  EXPECT_NE(result.out.find("open aperture: URDF 0.0800 m, file 0.0720 m  <- does not match"),
            std::string::npos)
      << result.out;
  fs::remove_all(dir);
}

TEST(RobotCheck, BadInputGivesOneLineAndExitCode2) {
  auto r = check("/nonexistent.yaml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("robot file '/nonexistent.yaml'"), std::string::npos) << r.out;
  r = check("robots/panda/panda.urdf");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("a URDF, not a robot file"), std::string::npos) << r.out;
  r = check("robots/panda/panda.yaml --configurations 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("--configurations must be at least 1"), std::string::npos) << r.out;
}

}  // namespace
