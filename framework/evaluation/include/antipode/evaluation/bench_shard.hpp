#pragma once
// Sharding a benchmark over machines: `--shard i/n` runs every task whose index is i - 1
// modulo n and writes a per-shard report; `antipode bench merge` joins the shards' reports
// into the report one process would have written (docs/cli.md, "Spreading a bench over
// machines").

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

/// Shard `index` (1-based) of `count`; 1/1 is the whole bench.
struct BenchShard {
  int index = 1;
  int count = 1;

  bool whole() const { return count == 1; }
  /// "shard 2/4".
  std::string str() const;
};

/// An environment variable's value, or nothing when it is not set.
using Environment = std::function<std::optional<std::string>(const std::string& name)>;

/// The process's own environment (std::getenv).
std::optional<std::string> process_environment(const std::string& name);

/// The shard a scheduler gave this process, from its environment:
/// - a Slurm job array's task: SLURM_ARRAY_TASK_ID among SLURM_ARRAY_TASK_MIN,
///   SLURM_ARRAY_TASK_COUNT and SLURM_ARRAY_TASK_STEP (1 when unset), so any contiguous or
///   stepped range maps to shards 1..count (`--array=0-9`, `--array=1-19:2`); a list that is no
///   such range (`--array=1,4,9`: SLURM_ARRAY_TASK_MAX disagrees) is refused;
/// - a Kubernetes Indexed Job's pod: JOB_COMPLETION_INDEX (0-based) of ANTIPODE_SHARD_COUNT.
/// Throws antipode::Error naming `--shard auto` when neither is there, both are, or the
/// values disagree.
BenchShard shard_from_environment(const Environment& environment);

/// Parses "i/n" (1 <= i <= n <= 10000), or "auto" (shard_from_environment); empty text is
/// the whole bench. Throws antipode::Error naming --shard for anything else.
BenchShard parse_shard(const std::string& text,
                       const Environment& environment = process_environment);

/// The indices of tasks 0 .. total-1 that belong to `shard`, ascending.
std::vector<std::size_t> shard_tasks(std::size_t total, const BenchShard& shard);

/// The report entry of a shard: {"index", "count", "tasks": total tasks of the whole bench}.
nlohmann::ordered_json shard_json(const BenchShard& shard, std::size_t total);

/// Throws antipode::Error when a sharded bench has no --report to write its share to.
void require_shard_report(const BenchShard& shard, const std::string& report_path);

}  // namespace antipode::evaluation
