// Control nodes: order of ticks, memory of RUNNING children, halting and thresholds.
#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

using ControlTest = TreeTest;

TEST_F(ControlTest, SequenceTicksChildrenInOrderAndSucceeds) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - Scripted: { id: a }
      - Scripted: { id: b }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 1);
  EXPECT_EQ(probes()["b"].ticks, 1);
  EXPECT_EQ(tree.root().status(), Status::kIdle);
}

TEST_F(ControlTest, SequenceResumesItsRunningChild) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - Scripted: { id: a }
      - Scripted: { id: b, script: [RUNNING, SUCCESS] }
      - Scripted: { id: c }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(probes()["c"].ticks, 0);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 1);
  EXPECT_EQ(probes()["b"].ticks, 2);
  EXPECT_EQ(probes()["c"].ticks, 1);
}

TEST_F(ControlTest, SequenceStopsAtTheFirstFailureAndRestartsNextTime) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - Scripted: { id: a, script: [FAILURE, SUCCESS] }
      - Scripted: { id: b }
)");
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["b"].ticks, 0);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 2);
}

TEST_F(ControlTest, HaltingASequenceHaltsOnlyItsRunningChild) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - Scripted: { id: a }
      - Scripted: { id: b, script: [RUNNING] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  tree.halt();
  EXPECT_EQ(probes()["a"].halts, 0);
  EXPECT_EQ(probes()["b"].halts, 1);
  tree.visit([](const Node& node, int) { EXPECT_EQ(node.status(), Status::kIdle) << node.path(); });
  // Halting resets the memory: the next tick starts from the first child again.
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(probes()["a"].ticks, 2);
}

TEST_F(ControlTest, ReactiveSequenceReticksEarlierChildren) {
  Tree tree = load(R"(
main: t
trees:
  t:
    ReactiveSequence:
      - Scripted: { id: a }
      - Scripted: { id: b, script: [RUNNING] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(probes()["a"].ticks, 2);
  EXPECT_EQ(probes()["b"].ticks, 2);
  EXPECT_EQ(probes()["b"].halts, 0);
}

TEST_F(ControlTest, ReactiveSequenceHaltsARunningChildWhenAnEarlierOneFails) {
  Tree tree = load(R"(
main: t
trees:
  t:
    ReactiveSequence:
      - Scripted: { id: a, script: [SUCCESS, FAILURE] }
      - Scripted: { id: b, script: [RUNNING] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["b"].ticks, 1);
  EXPECT_EQ(probes()["b"].halts, 1);
}

TEST_F(ControlTest, ReactiveSequenceHaltsARunningChildWhenAnEarlierOneRuns) {
  Tree tree = load(R"(
main: t
trees:
  t:
    ReactiveSequence:
      - Scripted: { id: a, script: [SUCCESS, RUNNING] }
      - Scripted: { id: b, script: [RUNNING] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(probes()["b"].halts, 1);
  EXPECT_EQ(probes()["b"].ticks, 1);
}

TEST_F(ControlTest, FallbackStopsAtTheFirstSuccess) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Fallback:
      - Scripted: { id: a, script: [FAILURE] }
      - Scripted: { id: b }
      - Scripted: { id: c }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["b"].ticks, 1);
  EXPECT_EQ(probes()["c"].ticks, 0);
}

TEST_F(ControlTest, FallbackFailsWhenAllChildrenFailAndResumesARunningChild) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Fallback:
      - Scripted: { id: a, script: [FAILURE] }
      - Scripted: { id: b, script: [RUNNING, FAILURE] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["a"].ticks, 1);
  EXPECT_EQ(probes()["b"].ticks, 2);
}

TEST_F(ControlTest, ReactiveFallbackHaltsARunningChildWhenAnEarlierOneSucceeds) {
  Tree tree = load(R"(
main: t
trees:
  t:
    ReactiveFallback:
      - Scripted: { id: a, script: [FAILURE, SUCCESS] }
      - Scripted: { id: b, script: [RUNNING] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 2);
  EXPECT_EQ(probes()["b"].halts, 1);
}

TEST_F(ControlTest, ParallelByDefaultNeedsAllSuccessesAndSkipsCompletedChildren) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Parallel:
      - Scripted: { id: a }
      - Scripted: { id: b, script: [RUNNING, SUCCESS] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 1);
  EXPECT_EQ(probes()["b"].ticks, 2);
}

TEST_F(ControlTest, ParallelSucceedsAtItsThresholdAndHaltsTheRest) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Parallel:
      success_count: 1
      children:
        - Scripted: { id: a, script: [RUNNING] }
        - Scripted: { id: b }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].halts, 1);
}

TEST_F(ControlTest, ParallelFailsAtItsFailureThreshold) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Parallel:
      success_count: 1
      failure_count: 2
      children:
        - Scripted: { id: a, script: [FAILURE] }
        - Scripted: { id: b, script: [RUNNING] }
        - Scripted: { id: c, script: [RUNNING, FAILURE] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["a"].ticks, 1);
  EXPECT_EQ(probes()["b"].halts, 1);
  EXPECT_EQ(probes()["c"].halts, 0);
}

TEST_F(ControlTest, ParallelFailsWhenSuccessBecomesImpossible) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Parallel:
      failure_count: -1
      children:
        - Scripted: { id: b, script: [RUNNING] }
        - Scripted: { id: a, script: [FAILURE] }
)");
  // All children must succeed (the default), so one failure decides.
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["b"].halts, 1);
}

TEST_F(ControlTest, ParallelRejectsAThresholdAboveItsChildCount) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Parallel:
      success_count: 3
      children: [AlwaysSuccess, AlwaysSuccess]
)");
  try {
    tree.tick_once();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "trees/t.yaml:6:22: port 'success_count' of Parallel is 3, which does not fit "
                 "its 2 children");
  }
}

TEST_F(ControlTest, TreeHaltHaltsEveryRunningNode) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - Parallel:
          - Scripted: { id: a, script: [RUNNING] }
          - Inverter:
              child: { Scripted: { id: b, script: [RUNNING] } }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  tree.halt();
  EXPECT_EQ(probes()["a"].halts, 1);
  EXPECT_EQ(probes()["b"].halts, 1);
  tree.visit([](const Node& node, int) { EXPECT_EQ(node.status(), Status::kIdle) << node.path(); });
}

TEST_F(ControlTest, DestroyingATreeHaltsRunningNodes) {
  {
    Tree tree = load(R"(
main: t
trees:
  t: { Scripted: { id: a, script: [RUNNING] } }
)");
    EXPECT_EQ(tree.tick_once(), Status::kRunning);
  }
  EXPECT_EQ(probes()["a"].halts, 1);
}

}  // namespace
}  // namespace antipode::bt::testing
