// Decorators and the built-in leaves: result mapping, counts, time limits and halting.
#include <chrono>

#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

using DecoratorTest = TreeTest;
using Clock = std::chrono::steady_clock;

std::string one(const std::string& node) { return "main: t\ntrees:\n  t:\n" + node; }

TEST_F(DecoratorTest, InverterSwapsSuccessAndFailureAndPassesRunning) {
  Tree tree =
      load(one("    Inverter: { Scripted: { id: a, script: [SUCCESS, FAILURE, RUNNING] } }"));
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
}

TEST_F(DecoratorTest, ForceSuccessAndForceFailureOverrideCompletedResults) {
  Tree success =
      load(one("    ForceSuccess: { child: { Scripted: { id: a, script: [FAILURE, RUNNING] } } }"));
  EXPECT_EQ(success.tick_once(), Status::kSuccess);
  EXPECT_EQ(success.tick_once(), Status::kRunning);
  Tree failure = load(one("    ForceFailure: { child: AlwaysSuccess }"));
  EXPECT_EQ(failure.tick_once(), Status::kFailure);
}

TEST_F(DecoratorTest, RetryRunsAFailingChildUpToNumAttempts) {
  Tree tree = load(
      one("    Retry: { num_attempts: 3, child: { Scripted: { id: a, script: [FAILURE, FAILURE, "
          "SUCCESS] } } }"));
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 3);
}

TEST_F(DecoratorTest, RetryGivesUpAfterNumAttemptsAndStartsAfreshNextRun) {
  Tree tree = load(
      one("    Retry: { num_attempts: 2, child: { Scripted: { id: a, script: [FAILURE] } } }"));
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["a"].ticks, 2);
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["a"].ticks, 4);
}

TEST_F(DecoratorTest, UnboundedRetryYieldsBetweenAttempts) {
  Tree tree = load(
      one("    Retry: { num_attempts: -1, child: { Scripted: { id: a, script: [FAILURE, FAILURE, "
          "SUCCESS] } } }"));
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 3);
}

TEST_F(DecoratorTest, HaltingRetryHaltsItsRunningChild) {
  Tree tree = load(
      one("    Retry: { num_attempts: 2, child: { Scripted: { id: a, script: [RUNNING] } } }"));
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  tree.halt();
  EXPECT_EQ(probes()["a"].halts, 1);
}

TEST_F(DecoratorTest, RepeatRunsASucceedingChildNumCyclesTimes) {
  Tree tree = load(one("    Repeat: { num_cycles: 3, child: { Scripted: { id: a } } }"));
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(probes()["a"].ticks, 3);
}

TEST_F(DecoratorTest, RepeatWithALabelReportsEachRunAsProgress) {
  Tree tree = load(
      one("    Sequence:\n"
          "      - Repeat: { num_cycles: 3, progress: scenes, child: { Scripted: { id: a } } }\n"
          "      - Repeat: { num_cycles: 2, child: { Scripted: { id: b } } }"));
  std::vector<std::string> reports;
  tree.set_progress_sink(
      [&](const Node&, std::size_t done, std::size_t total, const std::string& what) {
        reports.push_back(what + " " + std::to_string(done) + "/" + std::to_string(total));
      });
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(reports, (std::vector<std::string>{"scenes 1/3", "scenes 2/3", "scenes 3/3"}));
}

TEST_F(DecoratorTest, RepeatStopsAtTheFirstFailure) {
  Tree tree = load(one(
      "    Repeat: { num_cycles: 3, child: { Scripted: { id: a, script: [SUCCESS, FAILURE] } } }"));
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["a"].ticks, 2);
}

TEST_F(DecoratorTest, RepeatRejectsACountBelowMinusOne) {
  Tree tree = load(one("    Repeat: { num_cycles: -2, child: AlwaysSuccess }"));
  try {
    tree.tick_once();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "trees/t.yaml:4:27: port 'num_cycles' of Repeat must be -1 or more");
  }
}

TEST_F(DecoratorTest, KeepRunningUntilFailureRunsWhileTheChildSucceeds) {
  for (const char* type : {"KeepRunningUntilFailure", "RetryUntilFailure"}) {
    probes().clear();
    Tree tree = load(one("    " + std::string(type) +
                         ":\n      Scripted: { id: a, script: [SUCCESS, SUCCESS, FAILURE] }"));
    EXPECT_EQ(tree.tick_once(), Status::kRunning) << type;
    EXPECT_EQ(tree.tick_once(), Status::kRunning) << type;
    EXPECT_EQ(tree.tick_once(), Status::kFailure) << type;
    EXPECT_EQ(probes()["a"].ticks, 3) << type;
  }
}

TEST_F(DecoratorTest, TimeoutHaltsASlowChildAndFails) {
  Tree tree =
      load(one("    Timeout: { msec: 20, child: { Scripted: { id: a, script: [RUNNING] } } }"));
  const auto start = Clock::now();
  EXPECT_EQ(tree.tick_while_running(), Status::kFailure);
  EXPECT_GE(Clock::now() - start, std::chrono::milliseconds(20));
  EXPECT_EQ(probes()["a"].halts, 1);
  EXPECT_EQ(tree.root().failure_reason(), "timed out after 20 ms");
}

TEST_F(DecoratorTest, TimeoutPassesOnAChildThatFinishesInTime) {
  Tree tree = load(one("    Timeout: { msec: 2000, child: { Wait: { msec: 5 } } }"));
  EXPECT_EQ(tree.tick_while_running(), Status::kSuccess);
}

TEST_F(DecoratorTest, ZeroTimeoutFailsWithoutTickingTheChild) {
  Tree tree = load(one("    Timeout: { msec: 0, child: { Scripted: { id: a } } }"));
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  EXPECT_EQ(probes()["a"].ticks, 0);
}

TEST_F(DecoratorTest, WaitRunsForItsDurationAndCanBeHalted) {
  Tree tree = load(one("    Wait: { msec: 15 }"));
  const auto start = Clock::now();
  EXPECT_EQ(tree.tick_while_running(), Status::kSuccess);
  EXPECT_GE(Clock::now() - start, std::chrono::milliseconds(15));
  Tree halted = load(one("    Wait: { msec: 10000 }"));
  EXPECT_EQ(halted.tick_once(), Status::kRunning);
  halted.halt();
  EXPECT_EQ(halted.root().status(), Status::kIdle);
}

TEST_F(DecoratorTest, SetBlackboardAndLogShareEntries) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - SetBlackboard: { key: answer, value: "42" }
      - SetBlackboard: { key: "{copy}", value: "{answer}" }
      - ReadInt: { in: "{copy}", expect: 42 }
      - Log: { message: "answer={answer}, missing={nothing}, braces={not a key}" }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.blackboard().get<std::string>("answer"), "42");
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0], "answer=42, missing=<unset>, braces={not a key}");
}

TEST_F(DecoratorTest, AlwaysNodesMayBeWrittenAsBareNames) {
  Tree tree = load(one("    Sequence: [AlwaysSuccess, {Inverter: {child: AlwaysFailure}}]"));
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
}

}  // namespace
}  // namespace antipode::bt::testing
