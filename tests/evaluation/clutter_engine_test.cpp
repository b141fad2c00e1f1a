// The clear-the-box bench's engine called in this process, as the `antipode` command calls
// it: it returns the report (writing nothing itself), its shards merge into the whole bench,
// and bad options are refused before any run starts.
#include "antipode/evaluation/clutter_bench.hpp"

#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "antipode/evaluation/bench_merge.hpp"
#include "support/error_of.hpp"
#include "support/without_seconds.hpp"

namespace antipode::evaluation {
namespace {

namespace fs = std::filesystem;
using antipode::testing::error_of;
using antipode::testing::without_seconds;

class ClutterEngineTest : public ::testing::Test {
 protected:
  // The engine reads the shipped trees from the working folder, as the command does.
  void SetUp() override {
    previous_ = fs::current_path();
    fs::current_path(ANTIPODE_TEST_SOURCE_DIR);
    dir_ = fs::temp_directory_path() / ("antipode_clutter_engine_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::current_path(previous_);
    fs::remove_all(dir_);
  }

  static ClutterBenchOptions small_bench() {
    ClutterBenchOptions options;
    options.runs = 3;
    options.objects_per_run = 2;
    options.seed = 7;
    return options;
  }

  fs::path previous_, dir_;
};

TEST_F(ClutterEngineTest, ShardsMergeIntoTheReportOfTheWholeBench) {
  const nlohmann::ordered_json whole = run_clutter_bench(small_bench());
  const auto& records = whole.at("run_records");
  ASSERT_EQ(records.size(), 3u);
  int attempts = 0;
  for (const auto& run : records) attempts += run.at("attempts").get<int>();
  EXPECT_EQ(whole["summary"]["attempts"], attempts);
  EXPECT_GT(attempts, 0);
  EXPECT_FALSE(whole.contains("shard"));

  std::vector<nlohmann::ordered_json> shards;
  for (const char* shard : {"2/2", "1/2"}) {
    ClutterBenchOptions options = small_bench();
    options.shard = shard;
    options.report_path = (dir_ / "shard.json").string();  // a shard must name one
    shards.push_back(run_clutter_bench(options));
  }
  EXPECT_EQ(shards[0]["run_records"].size(), 1u);  // run 2 of 1, 2, 3
  EXPECT_TRUE(fs::is_empty(dir_)) << "the engine returns the report; the command writes it";
  const nlohmann::ordered_json merged = merge_shard_reports(shards, {"2.json", "1.json"});
  EXPECT_EQ(without_seconds(merged["summary"]), without_seconds(whole["summary"]));
  EXPECT_EQ(without_seconds(merged["run_records"]), without_seconds(records));
}

// Replicates run every seed again after the first draw, with execution noise: the first draw
// is the bench without replicates, and the summary tallies each draw and resamples seeds.
TEST_F(ClutterEngineTest, ReplicatesRunEverySeedAgainAfterTheFirstDraw) {
  ClutterBenchOptions once = small_bench();
  once.runs = 2;
  ClutterBenchOptions twice = once;
  twice.replicates = 2;
  const nlohmann::ordered_json first = run_clutter_bench(once);
  const nlohmann::ordered_json both = run_clutter_bench(twice);
  const auto& records = both.at("run_records");
  ASSERT_EQ(records.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(records[i]["seed"], 7 + i % 2);
    EXPECT_EQ(records[i]["replicate"], i / 2);
  }
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_EQ(without_seconds(records[i]), without_seconds(first["run_records"][i]));
  EXPECT_FALSE(first["summary"].contains("by_replicate"));
  const auto& tallies = both["summary"]["by_replicate"];
  ASSERT_EQ(tallies.size(), 2u);
  EXPECT_EQ(tallies[0]["attempts"], first["summary"]["attempts"]);
  EXPECT_EQ(tallies[0]["attempts"].get<int>() + tallies[1]["attempts"].get<int>(),
            both["summary"]["attempts"].get<int>());
  EXPECT_EQ(tallies[1]["runs"], 2);
  EXPECT_EQ(between_runs_intervals(records)["runs"], 2) << "one count per seed";
}

TEST_F(ClutterEngineTest, BadOptionsAreRefusedBeforeAnyRun) {
  ClutterBenchOptions no_runs = small_bench();
  no_runs.runs = 0;
  EXPECT_NE(error_of([&] { run_clutter_bench(no_runs); }).find("--runs must be in 1..100000"),
            std::string::npos);
  ClutterBenchOptions no_replicates = small_bench();
  no_replicates.replicates = 0;
  EXPECT_NE(
      error_of([&] { run_clutter_bench(no_replicates); }).find("--replicates must be in 1..100"),
      std::string::npos);
  ClutterBenchOptions no_protocol = small_bench();
  no_protocol.protocol = "vgn-heap";
  EXPECT_NE(error_of([&] { run_clutter_bench(no_protocol); }).find("vgn-heap"), std::string::npos);
  ClutterBenchOptions no_folder = small_bench();
  no_folder.report_path = (dir_ / "missing" / "report.json").string();
  EXPECT_NE(error_of([&] { run_clutter_bench(no_folder); }).find("missing"), std::string::npos);
  ClutterBenchOptions sharded = small_bench();
  sharded.shard = "1/2";
  EXPECT_NE(error_of([&] { run_clutter_bench(sharded); }).find("--report"), std::string::npos);
}

}  // namespace
}  // namespace antipode::evaluation
