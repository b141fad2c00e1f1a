#include "antipode/evaluation/bench_shard.hpp"

#include <charconv>
#include <cstdlib>

#include "antipode/core/error.hpp"

namespace antipode::evaluation {
namespace {

// The whole of `text` as a number in [0, 2^31), or nothing.
std::optional<long> whole_number(const std::string& text) {
  long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || value < 0 || value > 0x7fffffffL) return std::nullopt;
  return value;
}

// The whole of `text` as a number in [1, 10000], or 0.
int shard_number(const std::string& text) {
  const std::optional<long> value = whole_number(text);
  return value && *value >= 1 && *value <= 10000 ? int(*value) : 0;
}

// Reads the environment's numbers for --shard auto, each naming its variable when it is bad.
class ShardVariables {
 public:
  explicit ShardVariables(const Environment& environment) : environment_(environment) {}

  bool has(const std::string& name) const { return environment_(name).has_value(); }

  // The variable's value as a whole number; `fallback` when unset, or an error when there is
  // none.
  long number(const std::string& name, std::optional<long> fallback = std::nullopt) const {
    const std::optional<std::string> text = environment_(name);
    if (!text) {
      if (fallback) return *fallback;
      throw Error("--shard auto: " + name + " is not set (" + scheduler_ + ")");
    }
    const std::optional<long> value = whole_number(*text);
    if (!value) throw Error("--shard auto: " + name + "='" + *text + "' is not a whole number");
    return *value;
  }

  void set_scheduler(std::string scheduler) { scheduler_ = std::move(scheduler); }

 private:
  const Environment& environment_;
  std::string scheduler_;
};

// The shard of a Slurm array task: its place in the range MIN, MIN + STEP, ...
BenchShard slurm_shard(ShardVariables& v) {
  v.set_scheduler("a Slurm job array sets it for each task");
  const long id = v.number("SLURM_ARRAY_TASK_ID");
  const long min = v.number("SLURM_ARRAY_TASK_MIN");
  const long count = v.number("SLURM_ARRAY_TASK_COUNT");
  const long step = v.number("SLURM_ARRAY_TASK_STEP", 1);
  const long max = v.number("SLURM_ARRAY_TASK_MAX", min + (count - 1) * step);
  if (step < 1 || count < 1 || count > 10000)
    throw Error("--shard auto: a Slurm array of " + std::to_string(count) + " tasks in steps of " +
                std::to_string(step) + " (1 to 10000 tasks, steps of 1 or more)");
  if (max != min + (count - 1) * step)
    throw Error("--shard auto: the Slurm array's " + std::to_string(count) + " tasks from " +
                std::to_string(min) + " to " + std::to_string(max) + " are no range in steps of " +
                std::to_string(step) +
                ", which the shards need: give --array a range (0-9, or 1-19:2), not a list");
  if (id < min || id > max || (id - min) % step != 0)
    throw Error("--shard auto: SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
                " is not in the array's range " + std::to_string(min) + "-" + std::to_string(max) +
                ":" + std::to_string(step));
  return {int((id - min) / step + 1), int(count)};
}

// The shard of a Kubernetes Indexed Job's pod: index JOB_COMPLETION_INDEX of
// ANTIPODE_SHARD_COUNT.
BenchShard indexed_job_shard(ShardVariables& v) {
  v.set_scheduler("give the Indexed Job's completions in the pod's environment");
  const long index = v.number("JOB_COMPLETION_INDEX");
  const long count = v.number("ANTIPODE_SHARD_COUNT");
  if (count < 1 || count > 10000)
    throw Error("--shard auto: ANTIPODE_SHARD_COUNT=" + std::to_string(count) +
                " is not in 1..10000");
  if (index >= count)
    throw Error("--shard auto: JOB_COMPLETION_INDEX=" + std::to_string(index) +
                " is not below ANTIPODE_SHARD_COUNT=" + std::to_string(count) +
                " (the Job's completions and ANTIPODE_SHARD_COUNT must agree)");
  return {int(index + 1), int(count)};
}

}  // namespace

std::optional<std::string> process_environment(const std::string& name) {
  const char* value = std::getenv(name.c_str());  // NOLINT(concurrency-mt-unsafe): read once
  return value != nullptr ? std::optional<std::string>(value) : std::nullopt;
}

BenchShard shard_from_environment(const Environment& environment) {
  ShardVariables variables(environment);
  const bool slurm = variables.has("SLURM_ARRAY_TASK_ID");
  const bool indexed_job = variables.has("JOB_COMPLETION_INDEX");
  if (slurm && indexed_job)
    throw Error(
        "--shard auto: both SLURM_ARRAY_TASK_ID and JOB_COMPLETION_INDEX are set, so the "
        "scheduler is unclear: give the shard as --shard i/n");
  if (slurm) return slurm_shard(variables);
  if (indexed_job) return indexed_job_shard(variables);
  throw Error(
      "--shard auto: no scheduler's shard in the environment (SLURM_ARRAY_TASK_ID of a Slurm "
      "job array, or JOB_COMPLETION_INDEX of a Kubernetes Indexed Job with "
      "ANTIPODE_SHARD_COUNT); give the shard as --shard i/n");
}

std::string BenchShard::str() const {
  return "shard " + std::to_string(index) + "/" + std::to_string(count);
}

BenchShard parse_shard(const std::string& text, const Environment& environment) {
  if (text.empty()) return {};
  if (text == "auto") return shard_from_environment(environment);
  const std::size_t slash = text.find('/');
  const int index = slash == std::string::npos ? 0 : shard_number(text.substr(0, slash));
  const int count = slash == std::string::npos ? 0 : shard_number(text.substr(slash + 1));
  if (index == 0 || count == 0 || index > count)
    throw Error("--shard: '" + text +
                "' is not i/n with 1 <= i <= n <= 10000 (e.g. --shard 2/4), nor auto");
  return {index, count};
}

std::vector<std::size_t> shard_tasks(std::size_t total, const BenchShard& shard) {
  std::vector<std::size_t> tasks;
  for (std::size_t i = std::size_t(shard.index - 1); i < total; i += std::size_t(shard.count))
    tasks.push_back(i);
  return tasks;
}

nlohmann::ordered_json shard_json(const BenchShard& shard, std::size_t total) {
  return {{"index", shard.index}, {"count", shard.count}, {"tasks", total}};
}

void require_shard_report(const BenchShard& shard, const std::string& report_path) {
  if (!shard.whole() && report_path.empty())
    throw Error("--shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                " needs --report: a shard's records are merged from its report "
                "(antipode bench merge)");
}

}  // namespace antipode::evaluation
