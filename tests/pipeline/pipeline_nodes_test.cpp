// The pipeline nodes (plugins/nodes/pipeline) driving the fixture components through a tree.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/geometry/hand_body.hpp"
#include "antipode/interfaces/clearing_run.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"
#include "antipode/interfaces/hand_set.hpp"
#include "antipode/io/load_cloud.hpp"
#include "antipode/plugin/plugin_host.hpp"

namespace antipode {
namespace {

class PipelineNodesTest : public ::testing::Test {
 public:
  void SetUp() override {
    host_ = std::make_unique<PluginHost>(
        std::vector<std::string>{std::string(FIXTURE_DIR) + "/good", ANTIPODE_TEST_PLUGIN_DIR});
    host_->load_search_path();
    registry_ = bt::builtin_node_registry();
    host_->register_nodes(registry_);
  }

  bt::Tree load(const std::string& yaml) {
    bt::LoadOptions options;
    options.registry = &registry_;
    options.components = host_.get();
    return bt::load_tree_string(yaml, "pipeline.yaml", options);
  }

 private:
  std::unique_ptr<PluginHost> host_;
  bt::NodeRegistry registry_;
};

constexpr const char* kComponents = R"(
components:
  cell: { plugin: line_cell, points: 5 }
  sampler: { plugin: point_sampler }
  classifier: { plugin: height_classifier }
  selector: { plugin: best_first }
  planner: { plugin: still_planner }
main: pick
)";

TEST_F(PipelineNodesTest, WholePipelinePicksTheBestGrasp) {
  bt::Tree tree = load(std::string(kComponents) + R"(
trees:
  pick:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
      - ClassifyHands: { classifier: classifier, hands: "{hands}", classified: "{scored}" }
      - SelectGrasps: { selector: selector, hands: "{scored}", grasps: "{grasps}", best: "{best}" }
      - PlanReach: { planner: planner, cell: cell, grasps: "{grasps}", trajectory: "{path}", planned: "{planned}" }
      - ExecuteGrasp:
          cell: cell
          grasps: "{planned}"
          trajectory: "{path}"
          outcome: "{outcome}"
          attempt: "{attempt}"
          grasp: "{executed}"
)");
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  const auto& board = tree.blackboard();
  EXPECT_EQ(board.get<CloudPtr>("cloud")->size(), 5u);
  EXPECT_EQ(board.get<HandSetPtr>("hands")->hands.size(), 5u);
  // The sampler's set is left untouched; the classifier wrote a new one.
  EXPECT_EQ(board.get<HandSetPtr>("hands")->hands[4].score, 0.0);
  const auto grasps = board.get<HandSetPtr>("grasps");
  ASSERT_EQ(grasps->hands.size(), 5u);
  EXPECT_NEAR(board.get<Hand>("best").position_m().z(), 0.04, 1e-6);  // the highest point
  EXPECT_EQ(board.get<Trajectory>("path").positions_rad.size(), 2u);
  EXPECT_EQ(board.get<std::string>("outcome"), "success");
  // The cell's record of the attempt, and the grasp it executed: the best one.
  EXPECT_TRUE(board.get_ref<GraspAttempt>("attempt").reached_pose);
  EXPECT_NEAR(board.get<Hand>("executed").position_m().z(), 0.04, 1e-6);
}

// A classifier that throws (an antipode::Error, or a standard exception: a bug of its plugin,
// named with the component) or returns something that is not a classification of the hands
// given fails ClassifyHands with the reason: nothing wrong is passed on, nothing crashes.
TEST_F(PipelineNodesTest, AMisbehavingClassifierFailsItsNodeWithTheReason) {
  for (const auto& [garbage, reason] :
       {std::pair<std::string, std::string>{"nan", "gave hand 0 a score that is not a number"},
        {"drop", "returned 4 hands for 5"},
        {"probability", "called its scores probabilities but gave hand 0 1.5, outside [0, 1]"},
        {"throw", "the classifier failed: the model file vanished"},
        {"std",
         "ClassifyHands's code or its classifier 'classifier' (plugin garbage_classifier) "
         "threw std::out_of_range: vector::_M_range_check"}}) {
    bt::Tree tree = load(R"(
components:
  cell: { plugin: line_cell, points: 5 }
  sampler: { plugin: point_sampler }
  classifier: { plugin: garbage_classifier, garbage: )" +
                         garbage + R"( }
main: t
trees:
  t:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
      - ClassifyHands:
          { name: classify, classifier: classifier, hands: "{hands}", classified: "{scored}" }
)");
    tree.set_log_sink([](const bt::Node&, const std::string&) {});
    EXPECT_EQ(tree.tick_while_running(), bt::Status::kFailure) << garbage;
    EXPECT_FALSE(tree.blackboard().has("scored")) << garbage;
    std::string failure;
    tree.visit([&](const bt::Node& node, int) {
      if (node.name() == "classify") failure = node.failure_reason();
    });
    EXPECT_NE(failure.find(reason), std::string::npos) << garbage << ": " << failure;
  }
}

// The failure reason of the node named `name` after running `tree`, which must fail.
std::string failure_of(bt::Tree& tree, const std::string& name) {
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  EXPECT_EQ(tree.tick_while_running(), bt::Status::kFailure);
  std::string failure;
  tree.visit([&](const bt::Node& node, int) {
    if (node.name() == name) failure = node.failure_reason();
  });
  return failure;
}

// A tree capture -> sample -> select -> plan in which the component `kind` ("sampler",
// "selector" or "planner") is the garbage_KIND fixture misbehaving as `garbage` says, the
// others behave.
std::string pipeline_tree(const std::string& kind, const std::string& garbage) {
  const auto component = [&](const std::string& name, const std::string& good) {
    return "  " + name +
           ": { plugin: " + (name == kind ? "garbage_" + kind + ", garbage: " + garbage : good) +
           " }\n";
  };
  return "components:\n  cell: { plugin: line_cell, points: 5 }\n" +
         component("sampler", "point_sampler") + component("selector", "best_first") +
         component("planner", "still_planner") + R"(main: t
trees:
  t:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SampleHands: { name: sample, sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
      - SelectGrasps: { name: select, selector: selector, hands: "{hands}", grasps: "{grasps}" }
      - PlanReach: { name: plan, planner: planner, cell: cell, grasps: "{grasps}", trajectory: "{path}" }
)";
}

using Cases = std::vector<std::pair<std::string, std::string>>;

// For each (garbage, reason): with the `kind` component misbehaving so, the node `node` fails
// with exactly `reason` and its output `entry` is never written.
void expect_failures(PipelineNodesTest& test, const std::string& kind, const std::string& node,
                     const std::string& entry, const Cases& cases) {
  for (const auto& [garbage, reason] : cases) {
    bt::Tree tree = test.load(pipeline_tree(kind, garbage));
    EXPECT_EQ(failure_of(tree, node), reason) << garbage;
    EXPECT_FALSE(tree.blackboard().has(entry)) << garbage;
  }
}

// A sampler whose hands are broken fails SampleHands with the reason; nothing is passed on.
TEST_F(PipelineNodesTest, AMisbehavingSamplerFailsItsNodeWithTheReason) {
  expect_failures(*this, "sampler", "sample", "hands",
                  {{"nan", "the sampler gave hand 0 a pose that is not finite"},
                   {"frame", "the sampler put hand 0 in frame 'camera', not its cloud's 'base'"},
                   {"index", "the sampler gave hand 0 closing point 5 of a cloud of 5"},
                   {"cloud", "the sampler returned hands without the cloud they index"}});
}

// A selector that throws or chooses what it was not given fails SelectGrasps with the reason.
TEST_F(PipelineNodesTest, AMisbehavingSelectorFailsItsNodeWithTheReason) {
  expect_failures(*this, "selector", "select", "grasps",
                  {{"throw", "the selector failed: the robot file vanished"},
                   {"far",
                    "the selector chose grasp 0 at (0, 0, 1), away from every hand it was given "
                    "to choose from"},
                   {"cloud", "the selector returned its selection with another cloud"},
                   {"nan", "the selector gave grasp 0 a pose that is not finite"}});
}

// A planner that throws or solves with a broken trajectory fails PlanReach: a broken
// trajectory never reaches the arm.
TEST_F(PipelineNodesTest, AMisbehavingPlannerFailsItsNodeWithTheReason) {
  expect_failures(*this, "planner", "plan", "path",
                  {{"throw", "the planner failed: the collision world vanished"},
                   {"nan", "the planner returned waypoint 1 with a position that is not finite"},
                   {"times", "the planner returned 1 times for 2 waypoints"},
                   {"empty", "the planner returned a solved plan without waypoints"}});
}

// ScreenHands marks what the selector rules out before classification; ClassifyHands then
// classifies only the other hands and passes the screened ones on as they were.
TEST_F(PipelineNodesTest, ScreenedHandsAreNotClassified) {
  bt::Tree tree = load(R"(
components:
  cell: { plugin: line_cell, points: 5 }
  sampler: { plugin: point_sampler }
  classifier: { plugin: height_classifier }
  selector: { plugin: best_first, screen_below_m: 0.025 }
main: t
trees:
  t:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
      - ScreenHands: { selector: selector, hands: "{hands}", screened: "{screened}" }
      - ClassifyHands: { classifier: classifier, hands: "{screened}", classified: "{scored}" }
)");
  std::vector<std::string> lines;
  tree.set_log_sink([&](const bt::Node&, const std::string& line) { lines.push_back(line); });
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  const auto scored = tree.blackboard().get<HandSetPtr>("scored");
  ASSERT_EQ(scored->hands.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const Hand& hand = scored->hands[i];
    const bool screened = i < 3;  // at z = 0, 0.01 and 0.02
    EXPECT_EQ(hand.rejection, screened ? Rejection::kOutOfWorkspace : Rejection::kNone) << i;
    EXPECT_EQ(hand.label, screened ? HandLabel::kUnknown : HandLabel::kPositive) << i;
    EXPECT_DOUBLE_EQ(hand.score, screened ? 0.0 : hand.position_m().z()) << i;
  }
  EXPECT_NE(
      std::find(lines.begin(), lines.end(), "2 of 5 hands left to classify (3 out of workspace)"),
      lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(),
                      "2 of 2 hands classified as grasps (3 rejected before, not classified)"),
            lines.end());
}

// A screen that leaves nothing, or a selector whose screen misbehaves, fails ScreenHands with
// the reason; nothing is passed on.
TEST_F(PipelineNodesTest, ScreenHandsFailsWithTheReason) {
  const auto tree_with = [&](const std::string& selector) {
    return load(R"(
components:
  cell: { plugin: line_cell, points: 5 }
  sampler: { plugin: point_sampler }
  selector: )" + selector +
                R"(
main: t
trees:
  t:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
      - ScreenHands: { name: screen, selector: selector, hands: "{hands}", screened: "{screened}" }
)");
  };
  for (const auto& [selector, reason] :
       {std::pair<std::string, std::string>{"{ plugin: best_first, screen_below_m: 1 }",
                                            "the selector's screen left no hand (5 out of "
                                            "workspace)"},
        {"{ plugin: garbage_selector, garbage: drop }", "the selector returned 4 hands for 5"},
        {"{ plugin: garbage_selector, garbage: score }",
         "the selector changed hand 0 (a screen only sets rejections)"},
        {"{ plugin: garbage_selector, garbage: throw }",
         "the selector failed: the robot file vanished"}}) {
    bt::Tree tree = tree_with(selector);
    EXPECT_EQ(failure_of(tree, "screen"), reason) << selector;
    EXPECT_EQ(tree.blackboard().has("screened"), reason.find("left no hand") != std::string::npos)
        << selector;
  }
}

TEST_F(PipelineNodesTest, LoopOverScenesCountsSeedsAndOutcomes) {
  bt::Tree tree = load(std::string(kComponents) + R"yaml(
trees:
  pick:
    Repeat:
      num_cycles: 3
      child:
        Sequence:
          - ResetScene: { cell: cell, first_seed: 5, seed: "{seed}", objects: "{objects}" }
          - CaptureCloud: { cell: cell, cloud: "{cloud}" }
          - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
          - SelectGrasps: { selector: selector, hands: "{hands}", grasps: "{grasps}" }
          - ExecuteGrasp: { cell: cell, grasps: "{grasps}", outcome: "{outcome}" }
          - RecordOutcome: { outcome: "{outcome}", label: "scene {seed} ({objects})", successes: "{ok}", attempts: "{n}" }
)yaml");
  std::vector<std::string> lines;
  tree.set_log_sink([&](const bt::Node& node, const std::string& line) {
    if (node.type() == "RecordOutcome") lines.push_back(line);
  });
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  EXPECT_EQ(tree.blackboard().get<std::uint64_t>("seed"), 7u);
  EXPECT_EQ(tree.blackboard().get<int>("n"), 3);
  EXPECT_EQ(tree.blackboard().get<int>("ok"), 3);
  ASSERT_EQ(lines.size(), 3u);
  // The line cell knows no ground truth: its objects go unnamed.
  EXPECT_EQ(lines[0], "scene 5 (objects unknown): success - 1 of 1 succeeded (100%)");
  EXPECT_EQ(lines[2], "scene 7 (objects unknown): success - 3 of 3 succeeded (100%)");
}

// A clear-the-box tree over a line cell with parameters `cell`: ClearBox with the port
// `limit` (a "port: value" line, may be empty) around `child`, one pick that reports
// {outcome}.
std::string clearing_tree(const std::string& cell, const std::string& limit,
                          const std::string& child) {
  return "components:\n  cell: " + cell + R"(
  sampler: { plugin: point_sampler }
  selector: { plugin: best_first }
main: pick
trees:
  pick:
    ClearBox:
      cell: cell
      outcome: "{outcome}"
      attempt: "{attempt}"
      grasp: "{grasp}"
      run: "{run}"
      )" +
         limit + R"(
      child:
        )" +
         child + "\n";
}

// One pick: capture, sample, select, execute.
constexpr const char* kPickOne = R"(Sequence:
          - CaptureCloud: { cell: cell, cloud: "{cloud}" }
          - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
          - SelectGrasps: { selector: selector, hands: "{hands}", grasps: "{grasps}" }
          - ExecuteGrasp:
              { cell: cell, grasps: "{grasps}", outcome: "{outcome}", attempt: "{attempt}",
                grasp: "{grasp}" })";

// Runs a clear-the-box tree to its end (it must succeed) and returns its run record.
ClearingRun run_clearing(bt::Tree tree) {
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  EXPECT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  return tree.blackboard().get<ClearingRun>("run");
}

TEST_F(PipelineNodesTest, ClearBoxPicksUntilTheCellHasNoObjectLeft) {
  bt::Tree tree = load(clearing_tree("{ plugin: line_cell, objects: 3 }", "", kPickOne));
  std::vector<std::string> lines;
  tree.set_log_sink([&](const bt::Node& node, const std::string& line) {
    if (node.type() == "ClearBox") lines.push_back(line);
  });
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  const auto& run = tree.blackboard().get_ref<ClearingRun>("run");
  EXPECT_EQ(run.stop, ClearingStop::kCleared);
  EXPECT_EQ(run.objects_at_start, 3);
  ASSERT_EQ(run.cycles.size(), 3u);
  EXPECT_EQ(run.cycles[0].objects_before, 3);
  EXPECT_EQ(run.cycles[2].objects_after, 0);
  ASSERT_TRUE(run.cycles[1].attempt.has_value());
  EXPECT_EQ(run.cycles[1].attempt->pinched_object, "object 2");
  EXPECT_TRUE(run.cycles[1].grasp.has_value());
  ASSERT_EQ(lines.size(), 6u);  // start, three cycles, why it stopped, the summary
  EXPECT_EQ(lines[0], "clearing 3 objects, at most 6 cycles");
  EXPECT_EQ(lines[1].rfind("cycle 1: success (object 3); 2 left [", 0), 0u) << lines[1];
  EXPECT_EQ(lines[4], "stopped: the box is empty");
  EXPECT_EQ(lines[5], "cleared 3 of 3 objects; 3 of 3 attempts succeeded");
}

// With a selection prefix, each cycle may write the cloud it captured and where the cell's
// objects lay beside its selection: the files `antipode view` shows a run from.
TEST_F(PipelineNodesTest, ClearBoxNamesEachCyclesCloudAndObjectsFiles) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("clear_box_files_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string prefix = (dir / "run-").string();
  const std::string child = std::string(R"(Sequence:
          - WriteObjects: { cell: cell, file: "{objects_file}" }
          - CaptureCloud: { cell: cell, cloud: "{cloud}" }
          - WriteCloud: { cloud: "{cloud}", file: "{cloud_file}" }
          )") + (std::string(kPickOne).substr(std::string(kPickOne).find("- SampleHands")));
  const ClearingRun run =
      run_clearing(load(clearing_tree("{ plugin: line_cell, objects: 3, points: 5 }",
                                      "selection_prefix: \"" + prefix +
                                          "\"\n      cloud_file: \"{cloud_file}\"\n"
                                          "      objects_file: \"{objects_file}\"",
                                      child)));
  ASSERT_EQ(run.cycles.size(), 3u);
  for (const char* cycle : {"01", "02", "03"}) {
    const std::string stem = prefix + "cycle-" + cycle;
    EXPECT_EQ(load_cloud(stem + ".pcd").size(), 5u) << stem;
    std::ifstream objects(stem + "-objects.json");
    const auto document = nlohmann::json::parse(objects);
    EXPECT_EQ(document["frame"], "base");
    EXPECT_TRUE(document["objects"].is_array() && document["objects"].empty())
        << "the line cell knows no ground truth";
  }
  EXPECT_FALSE(std::filesystem::exists(prefix + "cycle-04.pcd"));
  std::filesystem::remove_all(dir);
}

// WriteArmPath: where Baxter's links are along a motion, by forward kinematics - the tip at
// the check values of shared/reference/baxter.md (right_hand in base, at q = 0 and neutral).
TEST_F(PipelineNodesTest, WriteArmPathPutsTheLinksWhereForwardKinematicsDoes) {
  const auto file =
      std::filesystem::temp_directory_path() / ("arm_path_" + std::to_string(::getpid()) + ".json");
  bt::Tree tree = load(std::string(R"(
main: t
trees:
  t:
    WriteArmPath: { trajectory: "{motion}", robot: ")") +
                       ANTIPODE_TEST_SOURCE_DIR + R"(/robots/baxter/baxter.yaml",
                    file: "{file}" }
)");
  Trajectory motion;
  motion.joint_names = {"right_s0", "right_s1", "right_e0", "right_e1",
                        "right_w0", "right_w1", "right_w2"};
  motion.positions_rad = {{0, 0, 0, 0, 0, 0, 0}, {0, -0.55, 0, 0.75, 0, 1.26, 0}};
  motion.times_s = {0.0, 1.5};
  tree.blackboard().set<Trajectory>("motion", motion);
  tree.blackboard().set<std::string>("file", file.string());
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  std::ifstream in(file);
  const auto path = nlohmann::json::parse(in);
  ASSERT_EQ(path["waypoints"].size(), 2u);
  EXPECT_EQ(path["links"].back(), "right_gripper");
  EXPECT_EQ(path["waypoints"][1]["time_s"], 1.5);
  const auto expect_at = [](const nlohmann::json& p, double x, double y, double z) {
    EXPECT_NEAR(p[0].get<double>(), x, 1e-4) << p;
    EXPECT_NEAR(p[1].get<double>(), y, 1e-4) << p;
    EXPECT_NEAR(p[2].get<double>(), z, 1e-4) << p;
  };
  const auto& links = path["links"];
  const auto hand = std::find(links.begin(), links.end(), "right_hand");
  ASSERT_NE(hand, links.end());
  const std::size_t at_hand = std::size_t(hand - links.begin());
  expect_at(path["waypoints"][0]["links_m"][at_hand], 0.79746, -0.99246, 0.32098);
  expect_at(path["waypoints"][1]["links_m"][at_hand], 0.63393, -0.82893, 0.21935);
  const auto shoulder = std::find(links.begin(), links.end(), "right_upper_shoulder");
  ASSERT_NE(shoulder, links.end());
  expect_at(path["waypoints"][0]["links_m"][std::size_t(shoulder - links.begin())], 0.06403,
            -0.25903, 0.12963);
  std::filesystem::remove(file);
}

TEST_F(PipelineNodesTest, ClearBoxStopsAfterConsecutiveCyclesWithoutAGrasp) {
  const ClearingRun run = run_clearing(
      load(clearing_tree("{ plugin: line_cell, objects: 4 }", "max_misses: 2",
                         R"(SetBlackboard: { key: outcome, value: "no grasp found" })")));
  EXPECT_EQ(run.stop, ClearingStop::kMissStreak);
  EXPECT_EQ(run.cycles.size(), 2u);
  EXPECT_EQ(run.attempts(), 0);
  EXPECT_EQ(run.objects_left(), 4);
  EXPECT_EQ(run.summary(), "cleared 0 of 4 objects; 0 of 0 attempts succeeded");
}

// Objects the cell placed outside the workspace (fell out while the box was filled) are
// reported when the run starts and in its summary, apart from the objects it had to clear.
TEST_F(PipelineNodesTest, ClearBoxSaysHowManyObjectsFellOutWhileTheBoxWasFilled) {
  bt::Tree tree =
      load(clearing_tree("{ plugin: line_cell, objects: 3, placed: 5 }", "max_misses: 1",
                         R"(SetBlackboard: { key: outcome, value: "no grasp found" })"));
  std::vector<std::string> lines;
  tree.set_log_sink([&](const bt::Node& node, const std::string& line) {
    if (node.type() == "ClearBox") lines.push_back(line);
  });
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  const auto& run = tree.blackboard().get_ref<ClearingRun>("run");
  EXPECT_EQ(run.objects_placed, 5);
  EXPECT_EQ(run.missed_at_filling(), 2);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.front(),
            "clearing 3 objects (2 of the 5 placed fell out while the box was filled), at most 6 "
            "cycles");
  EXPECT_EQ(lines.back(),
            "cleared 0 of 3 objects (2 more fell out while the box was filled); 0 of 0 attempts "
            "succeeded");
}

// A cycle whose classifier predicted nothing to hold ends the run at once, with that reason.
TEST_F(PipelineNodesTest, ClearBoxStopsWhenNothingIsPredictedToHold) {
  const ClearingRun run = run_clearing(load(
      clearing_tree("{ plugin: line_cell, objects: 4 }", "max_misses: 3",
                    R"(SetBlackboard: { key: outcome, value: "no grasp predicted to hold" })")));
  EXPECT_EQ(run.stop, ClearingStop::kNothingHolds);
  EXPECT_EQ(run.cycles.size(), 1u);
  EXPECT_EQ(run.attempts(), 0);
  EXPECT_EQ(run.trailing_misses(), 1);
  EXPECT_EQ(std::string(to_string(run.stop)), "no grasp was predicted to hold");
}

// VGN's rule: two consecutive failed attempts end the round.
TEST_F(PipelineNodesTest, ClearBoxStopsAfterConsecutiveFailedAttempts) {
  const ClearingRun run = run_clearing(
      load(clearing_tree("{ plugin: line_cell, objects: 4 }", "max_failures: 2",
                         R"(SetBlackboard: { key: outcome, value: "no motion plan" })")));
  EXPECT_EQ(run.stop, ClearingStop::kFailureStreak);
  EXPECT_EQ(run.cycles.size(), 2u);
  EXPECT_EQ(run.trailing_failures(), 2);
  EXPECT_EQ(std::string(to_string(run.stop)), "consecutive attempts failed");
}

TEST_F(PipelineNodesTest, ClearBoxEndsAfterItsCyclesWhenTheCellCannotCount) {
  const ClearingRun run = run_clearing(
      load(clearing_tree("{ plugin: line_cell }", "max_cycles: 4",
                         R"(SetBlackboard: { key: outcome, value: "no motion plan" })")));
  EXPECT_EQ(run.stop, ClearingStop::kCycleLimit);
  EXPECT_EQ(run.cycles.size(), 4u);
  EXPECT_EQ(run.attempts(), 4);  // a grasp was chosen each time, though not reached
  EXPECT_FALSE(run.cycles[0].attempt.has_value());
  EXPECT_EQ(run.objects_lost(), -1);
  EXPECT_EQ(run.summary(), "cleared 0 of ? objects; 0 of 4 attempts succeeded");
}

TEST_F(PipelineNodesTest, ClearBoxFailsWhenItsChildFails) {
  bt::Tree tree = load(clearing_tree("{ plugin: line_cell, objects: 2 }", "", "AlwaysFailure: {}"));
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  EXPECT_EQ(tree.tick_while_running(), bt::Status::kFailure);
}

TEST_F(PipelineNodesTest, ClearBoxRejectsBadLimitsAtTheirPort) {
  bt::Tree tree =
      load(clearing_tree("{ plugin: line_cell, objects: 2 }", "max_misses: 0",
                         R"(SetBlackboard: { key: outcome, value: "no grasp found" })"));
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  try {
    tree.tick_while_running();
    FAIL() << "max_misses 0 was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("max_misses' of ClearBox must be 1 or more"),
              std::string::npos)
        << error.what();
  }
}

// Up to the planning of the selection's grasps, with a planner that searches for a minute
// unless its stop token asks it to stop.
// A cycle of a clearing run that executed `grasp` (a hand at `x_m` on the x axis).
ClearingCycle executed_cycle(const std::string& outcome, double x_m, int before, int after) {
  ClearingCycle cycle;
  cycle.outcome = outcome;
  cycle.attempt = GraspAttempt{};
  Hand grasp;
  grasp.X_FrameHand.translation() = Eigen::Vector3d(x_m, 0.0, 0.0);
  cycle.grasp = grasp;
  cycle.objects_before = before;
  cycle.objects_after = after;
  return cycle;
}

class AvoidFailedGraspsTest : public PipelineNodesTest {
 protected:
  // The x coordinates of the hands AvoidFailedGrasps keeps of hands at x = 0, 0.01, 0.03,
  // 0.1 after the cycles of `run`; empty when it fails. The scene is segmented into two
  // objects: the first three hands close on object 0, the last on object 1 (a cloud point at
  // each hand's grasp centre).
  std::vector<double> kept_after(const ClearingRun& run, int failures_per_object = 0);
};

std::vector<double> AvoidFailedGraspsTest::kept_after(const ClearingRun& run,
                                                      int failures_per_object) {
  bt::Tree tree = load(R"(
main: avoid
trees:
  avoid:
    AvoidFailedGrasps: { hands: "{hands}", run: "{run}", failures_per_object: "{per_object}", kept: "{kept}" }
)");
  auto hands = std::make_shared<HandSet>();
  auto cloud = std::make_shared<Cloud>();
  hands->objects.resize(2);
  hands->objects[1].id = 1;
  for (double x : {0.0, 0.01, 0.03, 0.1}) {
    Hand hand;
    hand.X_FrameHand.translation() = Eigen::Vector3d(x, 0.0, 0.0);
    hand.object = x < 0.05 ? 0 : 1;
    hands->objects[std::size_t(hand.object)].points.push_back(std::int32_t(cloud->size()));
    cloud->points_m.push_back(grasp_centre(hand, hands->geometry).cast<float>());
    hands->hands.push_back(hand);
  }
  hands->cloud = cloud;
  tree.blackboard().set<int>("per_object", failures_per_object);
  tree.blackboard().set<HandSetPtr>("hands", hands);
  tree.blackboard().set<ClearingRun>("run", run);
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  if (tree.tick_while_running() != bt::Status::kSuccess) return {};
  std::vector<double> xs;
  for (const Hand& hand : tree.blackboard().get<HandSetPtr>("kept")->hands)
    xs.push_back(hand.position_m().x());
  return xs;
}

TEST_F(AvoidFailedGraspsTest, DropsHandsWhereAGraspFailedSinceTheLastRemoval) {
  ClearingRun run;
  EXPECT_EQ(kept_after(run), (std::vector<double>{0.0, 0.01, 0.03, 0.1}));
  run.cycles.push_back(executed_cycle("empty grasp", 0.0, 4, 4));
  run.cycles.push_back(executed_cycle("no grasp found", 0.0, 4, 4));
  run.cycles.back().attempt.reset();  // a cycle without a grasp: nothing to avoid
  EXPECT_EQ(kept_after(run), (std::vector<double>{0.03, 0.1}));  // within 2 cm of 0
  run.cycles.push_back(executed_cycle("success", 0.1, 4, 3));    // the scene changed
  EXPECT_EQ(kept_after(run), (std::vector<double>{0.0, 0.01, 0.03, 0.1}));
  run.cycles.push_back(executed_cycle("slipped", 0.1, 3, 3));
  EXPECT_EQ(kept_after(run), (std::vector<double>{0.0, 0.01, 0.03}));
  run.cycles.push_back(executed_cycle("empty grasp", 0.015, 3, 3));
  EXPECT_EQ(kept_after(run), (std::vector<double>{}));  // every hand dropped: FAILURE
}

TEST_F(AvoidFailedGraspsTest, GivesUpAnObjectAfterRepeatedFailuresOnIt) {
  ClearingRun run;
  run.cycles.push_back(executed_cycle("empty grasp", 0.0, 4, 4));  // on object 0
  run.cycles.push_back(executed_cycle("success", 0.1, 4, 3));      // the scene changed
  run.cycles.push_back(executed_cycle("slipped", 0.005, 3, 3));    // object 0 again
  EXPECT_EQ(kept_after(run), (std::vector<double>{0.03, 0.1}));    // near the last failure only
  EXPECT_EQ(kept_after(run, 3), (std::vector<double>{0.03, 0.1}));
  EXPECT_EQ(kept_after(run, 2), (std::vector<double>{0.1}));  // every hand on object 0 dropped
  // A failure far from every object's points (the object has moved away) counts for none.
  ClearingRun moved;
  moved.cycles.push_back(executed_cycle("slipped", 0.5, 4, 4));
  moved.cycles.push_back(executed_cycle("success", 0.1, 4, 3));
  moved.cycles.push_back(executed_cycle("slipped", 0.0, 3, 3));
  EXPECT_EQ(kept_after(moved, 2), (std::vector<double>{0.03, 0.1}));
  EXPECT_EQ(kept_after(moved, 1), (std::vector<double>{0.1}));
}

constexpr const char* kEndlessPlanning = R"(
components:
  cell: { plugin: line_cell, points: 5 }
  sampler: { plugin: point_sampler }
  selector: { plugin: best_first }
  planner: { plugin: endless_planner }
main: pick
trees:
  pick:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
      - SelectGrasps: { selector: selector, hands: "{hands}", grasps: "{grasps}" }
)";

TEST_F(PipelineNodesTest, ATimeoutStopsAPlannerCall) {
  // The endless planner searches for a minute unless its stop token asks it to stop: the
  // Timeout's deadline reaches it through PlanReach, which fails as cancelled.
  bt::Tree tree = load(std::string(kEndlessPlanning) + R"(
      - Timeout:
          msec: 50
          child:
            PlanReach: { name: reach, planner: planner, cell: cell, grasps: "{grasps}" }
)");
  std::string reason;
  struct Failures : bt::TreeObserver {
    std::string* reason;
    void on_status_change(const bt::Node& node, bt::Status, bt::Status now,
                          std::chrono::steady_clock::time_point) override {
      if (node.name() == "reach" && now == bt::Status::kFailure) *reason = node.failure_reason();
    }
  } failures;
  failures.reason = &reason;
  tree.add_observer(&failures);
  EXPECT_EQ(tree.tick_while_running(), bt::Status::kFailure);
  EXPECT_EQ(reason, "planning cancelled");
  tree.remove_observer(&failures);
}

TEST_F(PipelineNodesTest, ARequestToStopTheTreeStopsAPlannerCall) {
  bt::Tree tree = load(std::string(kEndlessPlanning) + R"(
      - PlanReach: { name: reach, planner: planner, cell: cell, grasps: "{grasps}" }
)");
  tree.request_stop();  // e.g. from a signal handler; the endless planner sees it
  EXPECT_EQ(tree.tick_while_running(), bt::Status::kFailure);
  const bt::Node* reach = nullptr;
  tree.visit([&](const bt::Node& node, int) {
    if (node.name() == "reach") reach = &node;
  });
  ASSERT_NE(reach, nullptr);
  EXPECT_EQ(reach->failure_reason(), "planning cancelled");
}

TEST_F(PipelineNodesTest, GraspsWrittenAndReadBackKeepTheirPoses) {
  const std::string file =
      (std::filesystem::temp_directory_path() / ("grasps_" + std::to_string(::getpid()) + ".json"))
          .string();
  bt::Tree tree = load(std::string(kComponents) + R"(
trees:
  pick:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SampleHands: { sampler: sampler, cloud: "{cloud}", hands: "{hands}" }
      - WriteGrasps: { hands: "{hands}", file: "{file}" }
      - ReadGrasps: { cloud: "{cloud}", file: "{file}", hands: "{read}" }
)");
  tree.blackboard().set<std::string>("file", file);
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  const auto& written = tree.blackboard().get<HandSetPtr>("hands")->hands;
  const auto& read = tree.blackboard().get<HandSetPtr>("read")->hands;
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_TRUE(read[i].X_FrameHand.isApprox(written[i].X_FrameHand, 1e-9));
    EXPECT_DOUBLE_EQ(read[i].width_m, written[i].width_m);
  }
  std::filesystem::remove(file);
}

TEST_F(PipelineNodesTest, ReadGraspsRejectsAFileThatIsNotGrasps) {
  const std::string file =
      (std::filesystem::temp_directory_path() / ("bad_" + std::to_string(::getpid()) + ".json"))
          .string();
  std::ofstream(file) << "{\"frame\": \"base\", \"hands\": [{\"position_m\": [1, 2]}]}";
  bt::Tree tree = load(std::string(kComponents) + R"(
trees:
  pick:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - ReadGrasps: { cloud: "{cloud}", file: "{file}", hands: "{read}" }
)");
  tree.blackboard().set<std::string>("file", file);
  try {
    tree.tick_while_running();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("is not a grasps file"), std::string::npos)
        << error.what();
  }
  std::filesystem::remove(file);
}

TEST_F(PipelineNodesTest, EmptyCaptureFailsWithReason) {
  bt::Tree tree = load(R"(
components:
  cell: { plugin: line_cell, points: 0 }
main: t
trees:
  t:
    CaptureCloud: { cell: cell, cloud: "{cloud}" }
)");
  EXPECT_EQ(tree.tick_while_running(), bt::Status::kFailure);
}

TEST_F(PipelineNodesTest, SelectViewsKeepsAViewsPointsAndRefusesMissingViews) {
  const std::string tree_text = R"(
components:
  cell: { plugin: line_cell, points: 5 }
main: t
trees:
  t:
    Sequence:
      - CaptureCloud: { cell: cell, cloud: "{cloud}" }
      - SelectViews: { cloud: "{cloud}", views: VIEWS, selected: "{one}" }
)";
  bt::Tree tree = load(std::regex_replace(tree_text, std::regex("VIEWS"), "[0]"));
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  ASSERT_EQ(tree.tick_while_running(), bt::Status::kSuccess);
  const CloudPtr one = tree.blackboard().get<CloudPtr>("one");
  EXPECT_EQ(one->size(), 5u);
  EXPECT_TRUE(one->view_masks.empty());  // a cloud without view origins stays one view
  bt::Tree wrong = load(std::regex_replace(tree_text, std::regex("VIEWS"), "[0, 1]"));
  wrong.set_log_sink([](const bt::Node&, const std::string&) {});
  try {
    wrong.tick_while_running();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("view 1 is not in the cloud, which has 1 view(s)"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(PipelineNodesTest, ComponentOfWrongKindIsRejectedAtLoad) {
  try {
    load(std::string(kComponents) + R"(
trees:
  pick:
    SampleHands: { sampler: classifier, cloud: "{cloud}", hands: "{hands}" }
)");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "pipeline.yaml:12:29: component 'classifier' is a classifier, but port "
                 "'sampler' of SampleHands needs a sampler");
  }
}

TEST_F(PipelineNodesTest, LoadCloudReportsAMissingFile) {
  bt::Tree tree = load(R"(
main: t
trees:
  t:
    LoadCloud: { file: /nonexistent/cloud.pcd, cloud: "{cloud}" }
)");
  try {
    tree.tick_while_running();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/cloud.pcd"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace antipode
