#pragma once
// Sharding a benchmark over machines: `--shard i/n` runs every task whose index is i - 1
// modulo n and writes a per-shard report; `antipode bench merge` joins the shards' reports
// into the report one process would have written (docs/cli.md, "Spreading a bench over
// machines").

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::cli {

/// Shard `index` (1-based) of `count`; 1/1 is the whole bench.
struct BenchShard {
  int index = 1;
  int count = 1;

  bool whole() const { return count == 1; }
  /// "shard 2/4".
  std::string str() const;
};

/// Parses "i/n" (1 <= i <= n <= 10000); empty text is the whole bench. Throws antipode::Error
/// naming --shard for anything else.
BenchShard parse_shard(const std::string& text);

/// The indices of tasks 0 .. total-1 that belong to `shard`, ascending.
std::vector<std::size_t> shard_tasks(std::size_t total, const BenchShard& shard);

/// The report entry of a shard: {"index", "count", "tasks": total tasks of the whole bench}.
nlohmann::ordered_json shard_json(const BenchShard& shard, std::size_t total);

/// Throws antipode::Error when a sharded bench has no --report to write its share to.
void require_shard_report(const BenchShard& shard, const std::string& report_path);

}  // namespace antipode::cli
