// `antipode bench clutter` as a user runs it: seeded clear-the-box runs of
// trees/clear_box.yaml with a floor on what they remove, the same results for any number of
// processes, and one-line errors for bad options.
#include <gtest/gtest.h>

#include "support/bench_command.hpp"

namespace {

class ClutterBenchTest : public antipode::testing::BenchCommandTest {
 protected:
  ClutterBenchTest() : BenchCommandTest("clutter") {}
};

// Two runs of four objects: every run removes at least one object, and the report has the
// summary keys docs/cli.md promises.
TEST_F(ClutterBenchTest, EveryRunRemovesObjects) {
  const auto r = report("--runs 2 --objects-per-run 4 --jobs 2", "two.json");
  ASSERT_TRUE(r.contains("summary")) << r.dump();
  const auto& s = r["summary"];
  for (const char* key : {"attempts", "successes", "objects", "removed"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["errors"], 0);
  ASSERT_EQ(r["run_records"].size(), 2u);
  for (const auto& run : r["run_records"]) {
    EXPECT_GE(run["removed"].get<int>(), 1) << run.dump(1);
    EXPECT_LE(run["cycles"].size(), 2u * run["objects"].get<std::size_t>());
    for (const auto& cycle : run["cycles"]) {
      EXPECT_TRUE(cycle.contains("reason")) << cycle.dump();
      // The cell counts what is left: a success takes the held object out, nothing comes back.
      const int before = cycle["objects_before"], after = cycle["objects_after"];
      if (cycle["outcome"] == "success") {
        EXPECT_TRUE(cycle.contains("record")) << cycle.dump();
        EXPECT_LE(after, before - 1) << cycle.dump();
      } else {
        EXPECT_LE(after, before) << cycle.dump();
      }
    }
  }
  EXPECT_LE(s["successes"].get<int>(), s["attempts"].get<int>());
}

TEST_F(ClutterBenchTest, TheSameResultsForAnyNumberOfProcesses) {
  const std::string args = "--runs 2 --objects-per-run 3 --seed 7";
  const auto one = report(args + " --jobs 1", "one.json");
  const auto two = report(args + " --jobs 2", "two.json");
  ASSERT_EQ(one["run_records"].size(), 2u);
  ASSERT_EQ(two["run_records"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& a = one["run_records"][i]["cycles"];
    const auto& b = two["run_records"][i]["cycles"];
    ASSERT_EQ(a.size(), b.size()) << "run " << i;
    for (std::size_t c = 0; c < a.size(); ++c) {
      EXPECT_EQ(a[c]["outcome"], b[c]["outcome"]) << "run " << i << " cycle " << c;
      EXPECT_EQ(a[c].value("hand", nlohmann::json()), b[c].value("hand", nlohmann::json()));
    }
  }
  EXPECT_EQ(one["summary"]["successes"], two["summary"]["successes"]);
}

TEST_F(ClutterBenchTest, BadOptionsAreOneLineErrors) {
  expect_error("--runs 0", "--runs must be in 1..100000");
  expect_error("--objects-per-run 0", "--objects-per-run must be in 1..100");
  expect_error("--jobs 0", "--jobs must be in 1..64");
  expect_error("--objects /no/such/folder", "neither 'procedural' nor a folder");
  expect_error("--tree trees/none.yaml", "no tree file");
  expect_error("--set cell.object_count=0", "'object_count' must be in [1, 100]");
}

}  // namespace
