// Shards of a bench: which tasks each runs, `--shard i/n`, and `--shard auto` read from a
// scheduler's environment (given here as a map, not the process's).
#include "antipode/evaluation/bench_shard.hpp"

#include <map>
#include <set>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "support/error_of.hpp"

namespace antipode::evaluation {
namespace {

using antipode::testing::error_of;

Environment environment(std::map<std::string, std::string> values) {
  return [values = std::move(values)](const std::string& name) -> std::optional<std::string> {
    const auto found = values.find(name);
    if (found == values.end()) return std::nullopt;
    return found->second;
  };
}

TEST(ShardTest, EveryTaskIsInExactlyOneShardInAscendingOrder) {
  for (std::size_t total = 0; total <= 25; ++total) {
    for (int count = 1; count <= 7; ++count) {
      std::set<std::size_t> seen;
      for (int index = 1; index <= count; ++index) {
        const std::vector<std::size_t> tasks = shard_tasks(total, {index, count});
        for (std::size_t i = 0; i < tasks.size(); ++i) {
          EXPECT_EQ(tasks[i] % std::size_t(count), std::size_t(index - 1));
          if (i > 0) {
            EXPECT_LT(tasks[i - 1], tasks[i]);
          }
          EXPECT_TRUE(seen.insert(tasks[i]).second) << "task " << tasks[i] << " twice";
        }
      }
      EXPECT_EQ(seen.size(), total) << total << " tasks in " << count << " shards";
    }
  }
}

TEST(ShardTest, ParsesAShardAndRefusesWhatIsNone) {
  const BenchShard shard = parse_shard("2/4");
  EXPECT_EQ(shard.index, 2);
  EXPECT_EQ(shard.count, 4);
  EXPECT_EQ(shard.str(), "shard 2/4");
  EXPECT_TRUE(parse_shard("").whole());
  for (const char* bad : {"0/4", "5/4", "1/0", "a/b", "2", "1/10001", "-1/3", "1/2/3"}) {
    const std::string error = error_of([&] { parse_shard(bad); });
    EXPECT_NE(error.find("--shard"), std::string::npos) << bad << ": " << error;
  }
}

// `--array=1-19:2` has ten tasks 1, 3, ..., 19: task 5 is the third.
TEST(ShardTest, ASteppedSlurmArrayMapsToShardsInOrder) {
  const BenchShard shard = parse_shard("auto", environment({{"SLURM_ARRAY_TASK_ID", "5"},
                                                            {"SLURM_ARRAY_TASK_MIN", "1"},
                                                            {"SLURM_ARRAY_TASK_MAX", "19"},
                                                            {"SLURM_ARRAY_TASK_COUNT", "10"},
                                                            {"SLURM_ARRAY_TASK_STEP", "2"}}));
  EXPECT_EQ(shard.index, 3);
  EXPECT_EQ(shard.count, 10);
}

// `--array=1,4,9`: three tasks whose range 1..9 is no step of 3 tasks.
TEST(ShardTest, ASlurmListThatIsNoRangeIsRefused) {
  const std::string error = error_of([] {
    parse_shard("auto", environment({{"SLURM_ARRAY_TASK_ID", "4"},
                                     {"SLURM_ARRAY_TASK_MIN", "1"},
                                     {"SLURM_ARRAY_TASK_MAX", "9"},
                                     {"SLURM_ARRAY_TASK_COUNT", "3"}}));
  });
  EXPECT_NE(error.find("--shard auto"), std::string::npos) << error;
}

TEST(ShardTest, AKubernetesIndexIsZeroBased) {
  const BenchShard shard = parse_shard(
      "auto", environment({{"JOB_COMPLETION_INDEX", "2"}, {"ANTIPODE_SHARD_COUNT", "4"}}));
  EXPECT_EQ(shard.index, 3);
  EXPECT_EQ(shard.count, 4);
}

TEST(ShardTest, NoSchedulerIsAnErrorNeverTheWholeBench) {
  const std::string none = error_of([] { parse_shard("auto", environment({})); });
  EXPECT_NE(none.find("--shard auto"), std::string::npos) << none;
  const std::string no_count = error_of([] {
    parse_shard("auto", environment({{"JOB_COMPLETION_INDEX", "0"}}));
  });
  EXPECT_NE(no_count.find("ANTIPODE_SHARD_COUNT"), std::string::npos) << no_count;
}

TEST(ShardTest, AShardedBenchNeedsAReportToWriteItsShareTo) {
  EXPECT_NO_THROW(require_shard_report({1, 1}, ""));
  EXPECT_NO_THROW(require_shard_report({1, 2}, "shard-1.json"));
  const std::string error = error_of([] { require_shard_report({1, 2}, ""); });
  EXPECT_NE(error.find("--report"), std::string::npos) << error;
}

}  // namespace
}  // namespace antipode::evaluation
