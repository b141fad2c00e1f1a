// Merging a clutter bench's shards, on records made here: the merge must give the records and
// summary of the whole bench in task order, whatever order the shards come in, and name the
// file and entry of shards that are not one bench.
#include "antipode/evaluation/bench_merge.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "antipode/evaluation/clutter_bench.hpp"
#include "support/error_of.hpp"

namespace antipode::evaluation {
namespace {

using antipode::testing::error_of;
using Json = nlohmann::ordered_json;

// Run `task`'s record: `attempts` cycles, the first `successes` of them held.
Json run_record(int task, int attempts, int successes) {
  Json cycles = Json::array();
  for (int i = 0; i < attempts; ++i)
    cycles.push_back({{"outcome", i < successes ? "success" : "dropped"},
                      {"reason", i < successes ? "success" : "slipped"},
                      {"seconds", 0.5}});
  return {{"task", task},
          {"seed", 3 + task},
          {"objects", 4},
          {"attempts", attempts},
          {"successes", successes},
          {"removed", successes},
          {"lost", 0},
          {"stop", "the run used all its cycles"},
          {"cycles", cycles},
          {"wall_s", 2.0}};
}

const std::vector<std::pair<int, int>> kRuns = {{4, 3}, {5, 4}, {3, 3}, {6, 2}, {4, 4}};

// Shard `index` of `count` of a bench of the kRuns, as `--shard index/count` writes it.
Json shard_report(int index, int count) {
  Json records = Json::array();
  for (int task = index - 1; task < int(kRuns.size()); task += count)
    records.push_back(run_record(task, kRuns[task].first, kRuns[task].second));
  return {{"bench", "clutter"},
          {"protocol", "paper"},
          {"runs", kRuns.size()},
          {"seed", 3},
          {"jobs", 1},
          {"wall_s", 10.0 * index},
          {"summary", summarise_clutter(records)},
          {"run_records", records},
          {"shard", {{"index", index}, {"count", count}, {"tasks", kRuns.size()}}}};
}

TEST(MergeTest, ShardsInAnyOrderGiveTheWholeBenchsRecordsAndSummary) {
  Json whole = Json::array();
  for (std::size_t task = 0; task < kRuns.size(); ++task)
    whole.push_back(run_record(int(task), kRuns[task].first, kRuns[task].second));
  const Json merged = merge_shard_reports(
      {shard_report(3, 3), shard_report(1, 3), shard_report(2, 3)}, {"c.json", "a.json", "b.json"});
  EXPECT_EQ(merged["run_records"], whole);
  EXPECT_EQ(merged["summary"], summarise_clutter(whole));
  EXPECT_EQ(merged["summary"]["attempts"], 22);
  EXPECT_EQ(merged["summary"]["successes"], 16);
  EXPECT_EQ(merged["shards"], 3);
  EXPECT_DOUBLE_EQ(merged["wall_s"].get<double>(), 60.0);  // the shards' sum
  EXPECT_FALSE(merged.contains("shard"));
  const std::string tables = merged_tables(merged, "a.json");
  EXPECT_NE(tables.find("3 shards, 5 records"), std::string::npos) << tables;
  EXPECT_NE(tables.find("grasp success 16 / 22"), std::string::npos) << tables;
}

TEST(MergeTest, AShardGivenTwiceOrMissingIsNamed) {
  const std::string twice = error_of([] {
    merge_shard_reports({shard_report(1, 3), shard_report(1, 3), shard_report(3, 3)},
                        {"a.json", "again.json", "c.json"});
  });
  EXPECT_NE(twice.find("again.json: shard 1 given twice"), std::string::npos) << twice;
  const std::string missing = error_of([] {
    merge_shard_reports({shard_report(1, 3), shard_report(3, 3)}, {"a.json", "c.json"});
  });
  EXPECT_NE(missing.find("shards 2 of 3 are missing"), std::string::npos) << missing;
}

TEST(MergeTest, ShardsOfAnotherBenchAreRefusedByFileAndEntry) {
  Json other = shard_report(2, 2);
  other["seed"] = 4;
  const std::string error = error_of([&] {
    merge_shard_reports({shard_report(1, 2), other}, {"a.json", "b.json"});
  });
  EXPECT_NE(error.find("b.json: entry \"seed\" differs from a.json's"), std::string::npos) << error;
  Json unsharded = shard_report(1, 1);
  unsharded.erase("shard");
  const std::string not_a_shard =
      error_of([&] { merge_shard_reports({unsharded}, {"whole.json"}); });
  EXPECT_NE(not_a_shard.find("whole.json: not a shard's report"), std::string::npos) << not_a_shard;
}

}  // namespace
}  // namespace antipode::evaluation
