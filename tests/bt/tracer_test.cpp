// Observers and tracers: which changes are reported, and the console and JSONL formats.
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

using TracerTest = TreeTest;

const char* kTree = R"(
main: t
trees:
  t:
    Sequence:
      - Scripted: { id: a, script: [RUNNING, SUCCESS], name: slow }
      - FailWithReason: { reason: no hands }
)";

TEST_F(TracerTest, ObserversSeeChangesButNotResetsAfterCompletion) {
  Tree tree = load(kTree);
  auto recorder = std::make_shared<Recorder>();
  tree.add_observer(recorder);
  EXPECT_EQ(tree.tick_while_running(), Status::kFailure);
  EXPECT_EQ(recorder->events, (std::vector<std::string>{
                                  "Sequence:IDLE->RUNNING",
                                  "slow:IDLE->RUNNING",
                                  "slow:RUNNING->SUCCESS",
                                  "FailWithReason:IDLE->FAILURE",
                                  "Sequence:RUNNING->FAILURE",
                              }));
}

TEST_F(TracerTest, HaltsAreReportedAsRunningToIdle) {
  Tree tree = load(kTree);
  Recorder recorder;
  tree.add_observer(&recorder);
  tree.tick_once();
  tree.halt();
  EXPECT_EQ(recorder.events.back(), "Sequence:RUNNING->IDLE");
  EXPECT_EQ(recorder.events[recorder.events.size() - 2], "slow:RUNNING->IDLE");
  tree.remove_observer(&recorder);
  tree.tick_once();
  EXPECT_EQ(recorder.events.size(), 4u);
}

TEST_F(TracerTest, ConsoleTracerWritesOneLinePerChange) {
  Tree tree = load(kTree);
  std::ostringstream out;
  ConsoleTracer tracer(out);
  tree.add_observer(&tracer);
  tree.tick_while_running();
  const std::regex line(
      R"(\[ +\d+\.\d{3}s\] (Scripted\(slow\)|Sequence|FailWithReason) (IDLE|RUNNING) -> )"
      R"((RUNNING|SUCCESS|FAILURE)(: no hands)?)");
  std::istringstream lines(out.str());
  int count = 0;
  for (std::string text; std::getline(lines, text); ++count) {
    EXPECT_TRUE(std::regex_match(text, line)) << text;
  }
  EXPECT_EQ(count, 5);
  EXPECT_NE(out.str().find("FailWithReason IDLE -> FAILURE: no hands\n"), std::string::npos);
  EXPECT_EQ(out.str().find('\033'), std::string::npos);
}

TEST_F(TracerTest, ConsoleTracerColoursOnlyWhenAsked) {
  Tree tree = load(kTree);
  std::ostringstream out;
  ConsoleTracer tracer(out, true);
  tree.add_observer(&tracer);
  tree.tick_while_running();
  EXPECT_NE(out.str().find("\033[31mFAILURE\033[0m"), std::string::npos);
}

TEST_F(TracerTest, FailureWitnessNamesTheLastLeafThatFailedWithAReason) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - Fallback:
          - FailWithReason: { reason: first try }
          - Scripted: { id: b, script: [SUCCESS] }
      - FailWithReason: { reason: no hands, name: sample }
)");
  FailureWitness witness;
  EXPECT_EQ(witness.last_failure(), "");
  tree.add_observer(&witness);
  EXPECT_EQ(tree.tick_while_running(), Status::kFailure);
  // The Fallback's recovered failure is superseded; the Sequence's own failure has no reason.
  EXPECT_EQ(witness.last_failure(), "FailWithReason 'sample' at trees/t.yaml:9:9: no hands");
}

TEST_F(TracerTest, JsonlTracerWritesValidJsonLines) {
  const std::string path = ::testing::TempDir() + "bt_trace_test.jsonl";
  {
    Tree tree = load(kTree);
    JsonlTracer tracer(path);
    tree.add_observer(&tracer);
    tree.tick_while_running();
  }
  std::ifstream in(path);
  std::vector<nlohmann::json> lines;
  std::string first;
  for (std::string text; std::getline(in, text);) {
    if (first.empty()) first = text;
    lines.push_back(nlohmann::json::parse(text));
  }
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(first.rfind("{\"time_s\":", 0), 0u) << first;
  // The parent starts first, then its children (BehaviorTree.CPP's order).
  EXPECT_EQ(lines[0]["node"], "Sequence");
  EXPECT_EQ(lines[0]["path"], "t/Sequence");
  EXPECT_EQ(lines[1]["node"], "slow");
  EXPECT_EQ(lines[1]["type"], "Scripted");
  EXPECT_EQ(lines[1]["path"], "t/Sequence/slow#0");  // named nodes are placed by name
  EXPECT_EQ(lines[1]["where"], "trees/t.yaml:6:9");
  EXPECT_EQ(lines[1]["from"], "IDLE");
  EXPECT_EQ(lines[1]["to"], "RUNNING");
  EXPECT_FALSE(lines[1].contains("reason"));
  EXPECT_EQ(lines[3]["node"], "FailWithReason");
  EXPECT_EQ(lines[3]["reason"], "no hands");
  EXPECT_LE(lines[0]["time_s"].get<double>(), lines[4]["time_s"].get<double>());
  std::remove(path.c_str());
}

TEST_F(TracerTest, JsonlTracerRefusesAnUnwritablePath) {
  EXPECT_THROW(JsonlTracer("/nonexistent/dir/trace.jsonl"), Error);
}

}  // namespace
}  // namespace antipode::bt::testing
