// Grasp detection in the cell's room scene (scenes/room.yaml, trees/detect_cell.yaml): the
// table is found though the floor and the wall are larger planes, its objects are
// segmented, and the best grasps lie on them - not on the room's edges.
#include <algorithm>
#include <fstream>
#include <set>

#include "support/bench_command.hpp"

namespace {

class RoomSceneTest : public antipode::testing::BenchCommandTest {
 protected:
  RoomSceneTest() : BenchCommandTest("room") {}

  // The grasps the tree wrote, best score first.
  std::vector<nlohmann::json> detect(const std::string& extra) {
    const std::string file = this->file("g.json");
    const auto result = antipode("run trees/detect_cell.yaml --set grasps_file=" + file +
                                 " --set image_file= --set sampler.samples=1500 " + extra);
    EXPECT_EQ(result.exit_code, 0) << result.out;
    last_output_ = result.out;
    std::ifstream in(file);
    std::vector<nlohmann::json> hands;
    const nlohmann::json document = nlohmann::json::parse(in);
    for (const auto& hand : document.at("hands")) hands.push_back(hand);
    std::stable_sort(hands.begin(), hands.end(), [](const auto& a, const auto& b) {
      return a["score"].template get<double>() > b["score"].template get<double>();
    });
    return hands;
  }
  std::string last_output_;
};

// On the table: above its top (z -0.295) and within its extent.
bool on_table(const nlohmann::json& hand) {
  const auto p = hand["position_m"];
  return p[0].get<double>() > 0.275 && p[0].get<double>() < 1.175 && p[2].get<double>() > -0.3;
}

TEST_F(RoomSceneTest, TheBestGraspsLieOnTheObjectsOnTheTable) {
  const auto hands = detect("");
  ASSERT_GE(hands.size(), 12u) << last_output_;
  std::set<int> objects;
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_GE(hands[i]["object"].get<int>(), 0) << hands[i].dump();
    EXPECT_TRUE(on_table(hands[i])) << hands[i].dump();
    objects.insert(hands[i]["object"].get<int>());
  }
  for (const auto& hand : hands) {
    EXPECT_TRUE(on_table(hand)) << hand.dump();
    objects.insert(hand["object"].get<int>());
  }
  EXPECT_EQ(objects.size(), 3u) << "each of the table's three objects has grasps";
}

// Without the scene stage the room is sampled too: its walls, floor and shelf take most of
// the samples, and few grasps are left on the objects.
TEST_F(RoomSceneTest, SamplingEverythingSpendsTheSamplesOnTheRoom) {
  const std::size_t on_objects = detect("").size();
  const std::size_t everywhere = detect("--set sampler.objects=all").size();
  EXPECT_LT(4 * everywhere, on_objects) << last_output_;
}

}  // namespace
