// docs/your-own-data.md as a user runs it: every ```sh block of the page, in order, from an
// empty folder outside the source tree, then checks of what the commands wrote - grasps in
// the robot's frame that are the camera frame's grasps moved, ranked, with the poses a
// robot needs, and the message that names the command training a model for a new gripper.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "support/command_output.hpp"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

std::string text_of(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The page's ```sh blocks, in order.
std::vector<std::string> shell_blocks(const std::string& page) {
  std::vector<std::string> blocks;
  const std::regex block("```sh\n([\\s\\S]*?)```");
  for (std::sregex_iterator it(page.begin(), page.end(), block), end; it != end; ++it)
    blocks.push_back((*it)[1].str());
  return blocks;
}

// Replaces every `from` in `text` with `to`; fails the test when there is none.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  EXPECT_NE(text.find(from), std::string::npos) << "the page no longer says " << from;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
    text.replace(at, from.size(), to), at += to.size();
  return text;
}

Eigen::Vector3d vec(const json& v) {
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

json read_json(const fs::path& path) {
  std::ifstream in(path);
  return json::parse(in);
}

class YourOwnDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("antipode_your_own_data_" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "bin");
    fs::create_symlink(ANTIPODE_CLI, dir_ / "bin" / "antipode");
    fs::create_directories(dir_ / "work");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `block` with bash in the work folder, `antipode` on the PATH and CLOUD set.
  antipode::testing::CommandResult run_block(const std::string& block, const std::string& cloud) {
    const fs::path script = dir_ / "block.sh";
    std::ofstream(script) << "set -e\n" << block;
    return antipode::testing::run_command("cd " + (dir_ / "work").string() +
                                          " && PATH=" + (dir_ / "bin").string() +
                                          ":$PATH CLOUD=" + cloud + " bash " + script.string());
  }

  fs::path dir_;
};

TEST_F(YourOwnDataTest, TheFirstHourAsCommands) {
  const std::string cloud = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/table_mug.pcd";
  if (!fs::exists(cloud)) GTEST_SKIP() << "no " << cloud << " (../shared/data is absent)";
  const std::vector<std::string> blocks =
      shell_blocks(text_of(fs::path(ANTIPODE_TEST_SOURCE_DIR) / "docs/your-own-data.md"));
  ASSERT_GE(blocks.size(), 5u);
  std::string all_output;
  for (std::size_t i = 1; i < blocks.size(); ++i) {  // block 0 sets CLOUD, as the test does
    std::string block = blocks[i];
    // The quick training as written renders 50 scenes; the same command with 3 here.
    if (block.find("antipode train") != std::string::npos) {
      block = replaced(block, "procedural_scenes=30", "procedural_scenes=2");
      block = replaced(block, "blob_scenes=20", "blob_scenes=1");
    }
    const auto result = run_block(block, cloud);
    EXPECT_EQ(result.exit_code, 0) << "block " << i << ":\n" << block << "\n" << result.out;
    all_output += result.out;
  }
  const fs::path work = dir_ / "work";

  // The model names the command that trains one for the new gripper.
  EXPECT_NE(all_output.find("train a model for this hand: antipode train --out my.model --set "
                            "sampler.hand=GRIPPER.yaml"),
            std::string::npos)
      << all_output;
  EXPECT_TRUE(fs::exists(work / "2f85.model"));
  EXPECT_TRUE(fs::exists(work / "grasps.png"));

  // Ranked grasps in the base frame, with the poses and opening a robot needs.
  const json camera = read_json(work / "camera.json");
  const json base = read_json(work / "grasps.json");
  EXPECT_EQ(camera["frame"], "sensor");
  EXPECT_EQ(base["frame"], "base");
  ASSERT_GE(base["count"].get<int>(), 1);
  EXPECT_LE(base["count"].get<int>(), 5);
  const Eigen::Isometry3d X_BaseCamera =
      Eigen::Translation3d(0.3, -0.6, 0.9) * Eigen::Quaterniond(-0.4763, 0.8793, 0, 0).normalized();
  std::vector<double> distances, angles;
  int rank = 0;
  for (const json& hand : base["hands"]) {
    EXPECT_EQ(hand["rank"].get<int>(), ++rank);
    const Eigen::Vector3d tcp = vec(hand["tcp"]["position_m"]);
    const Eigen::Vector3d approach = vec(hand["approach"]);
    EXPECT_LT((vec(hand["pre_grasp"]["position_m"]) - (tcp - 0.1 * approach)).norm(), 1e-9);
    EXPECT_LT((tcp - (vec(hand["position_m"]) + 0.06 * approach)).norm(), 1e-9);
    EXPECT_GT(tcp.z(), 0.36) << "below the table (z 0.376 in the base frame)";
    EXPECT_NEAR(hand["open_width_m"].get<double>(),
                std::min(0.072, hand["width_m"].get<double>() + 0.02), 1e-12);
    // The nearest of the camera frame's grasps, moved into the base frame.
    double best = 1e9, angle = 180.0;
    for (const json& seen : camera["hands"]) {
      const double d = (X_BaseCamera * vec(seen["position_m"]) - vec(hand["position_m"])).norm();
      if (d >= best) continue;
      best = d;
      const double c = (X_BaseCamera.linear() * vec(seen["approach"])).dot(approach);
      angle = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
    }
    distances.push_back(best), angles.push_back(angle);
  }
  std::sort(distances.begin(), distances.end());
  std::sort(angles.begin(), angles.end());
  EXPECT_LT(distances[distances.size() / 2], 0.01) << "grasps are not the camera frame's, moved";
  EXPECT_LT(angles[angles.size() / 2], 10.0);

  // The inline pose gives the same frame; --per-object 2 keeps at most 2 on the one object.
  const json inline_pose = read_json(work / "inline.json");
  EXPECT_EQ(inline_pose["frame"], "base");
  EXPECT_GE(inline_pose["count"].get<int>(), 1);
  EXPECT_LE(inline_pose["count"].get<int>(), 2);
}

}  // namespace
