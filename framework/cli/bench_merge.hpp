#pragma once
// `antipode bench merge`: joins the reports of a bench's shards (`--shard i/n`, run anywhere)
// into the report one process would have written, and prints its tables (docs/cli.md).

#include <string>
#include <vector>

namespace antipode::cli {

struct BenchMergeOptions {
  std::vector<std::string> reports;  ///< the shards' JSON reports, any order
  std::string report_path;           ///< the merged report ("" = print only)
};

/// Checks that `reports` are the shards 1..n of one bench with the same settings (every entry
/// but the shard's own: its records, summary, wall time, processes), each exactly once;
/// joins their records in task order, summarises them as the bench does and prints and
/// writes the result. The merged report's `wall_s` is the sum of the shards'. Returns the exit
/// code; throws antipode::Error naming the file and entry at fault.
int bench_merge_command(const BenchMergeOptions& options);

}  // namespace antipode::cli
