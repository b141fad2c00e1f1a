#pragma once
// `antipode bench merge`: joins the reports of a bench's shards (`--shard i/n`, run anywhere)
// into the report one process would have written, and prints its tables (docs/cli.md).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

struct BenchMergeOptions {
  std::vector<std::string> reports;  ///< the shards' JSON reports, any order
  std::string report_path;           ///< the merged report ("" = print only)
};

/// Checks that `shards` (read from the files `paths`, which name them in errors) are the
/// shards 1..n of one bench with the same settings (every entry but the shard's own: its
/// records, summary, wall time, processes), each exactly once, and joins their records in
/// task order, summarised as the bench does: the report one process would have written, with
/// `wall_s` the sum of the shards' and "shards" their count. Throws antipode::Error naming the
/// file and entry at fault.
nlohmann::ordered_json merge_shard_reports(const std::vector<nlohmann::ordered_json>& shards,
                                           const std::vector<std::string>& paths);

/// The text `antipode bench merge` prints for a merged report: the shards and records, the
/// bench's tables and the summed wall time. `first_path` names the shards in errors.
std::string merged_tables(const nlohmann::ordered_json& merged, const std::string& first_path);

/// Reads the shards' reports, merges them (merge_shard_reports()), prints merged_tables() and
/// returns the merged report, which the caller writes to `report_path` (checked first).
nlohmann::ordered_json run_bench_merge(const BenchMergeOptions& options);

}  // namespace antipode::evaluation
