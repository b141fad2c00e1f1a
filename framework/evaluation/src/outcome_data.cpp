#include "antipode/evaluation/outcome_data.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
#include "antipode/evaluation/bench_processes.hpp"
#include "antipode/evaluation/bench_shard.hpp"
#include "antipode/evaluation/bench_task.hpp"
#include "antipode/evaluation/json_file.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"

namespace fs = std::filesystem;

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

struct Settings {
  std::string tree_path;
  std::string tree_yaml;
  std::string folder;
  std::vector<std::pair<std::string, std::string>> entries;  ///< the same for every scene
};

// The near-antipodal labels a record gives its trials (CollectTrials), in the summary's order.
const char* const kAntipodalLabels[] = {"positive", "negative", "indeterminate"};

void check_options(const OutcomeDataOptions& o) {
  if (o.out_dir.empty()) throw Error("--out: give the folder the trial files go to");
  if (fs::exists(o.out_dir) && !fs::is_directory(o.out_dir))
    throw Error("--out: '" + o.out_dir + "' is not a folder");
  if (o.scenes < 1 || o.scenes > 10000000) throw Error("--scenes must be in 1..10000000");
  if (o.jobs < 1 || o.jobs > 64) throw Error("--jobs must be in 1..64");
  if (!fs::is_regular_file(o.tree_path)) throw Error("--tree: no tree file '" + o.tree_path + "'");
  require_cell_component(o.tree_path, "trees/outcomes.yaml");
  check_entries_are_read(o.tree_path, o.set);
}

bt::Tree load_scene_tree(const Session& session, const Settings& settings, std::uint64_t seed) {
  bt::LoadOptions load;
  load.registry = &session.registry;
  load.components = session.host.get();
  load.seed = seed;
  const fs::path folder(settings.folder);
  load.overrides = {{"seed", std::to_string(seed)},
                    {"records_file", (folder / outcome_records_name(seed)).string()},
                    {"data_file", (folder / outcome_data_name(seed)).string()}};
  for (const auto& entry : settings.entries) load.overrides.push_back(entry);
  return bt::load_tree_string(settings.tree_yaml, settings.tree_path, load);
}

// Counts of no trial: {"trials": 0, "held": 0, "positive": [0, 0], ...}.
Json no_trials() {
  Json counts = {{"trials", 0}, {"held", 0}};
  for (const char* label : kAntipodalLabels) counts[label] = {0, 0};
  return counts;
}

// Adds the counts of `part` (any of the keys of no_trials()) to `total`.
void add_counts(const Json& part, Json& total) {
  for (auto& item : total.items()) {
    if (!part.contains(item.key())) continue;
    const Json& add = part[item.key()];
    Json& value = item.value();
    value = value.is_array() ? Json{value[0].get<int>() + add[0].get<int>(),
                                    value[1].get<int>() + add[1].get<int>()}
                             : Json(value.get<int>() + add.get<int>());
  }
}

// The trials a finished scene wrote: how many and how many held, in all and per near-antipodal
// label ("trials", "held", and e.g. "positive": [trials, held]).
Json count_trials(const fs::path& records) {
  const Json file = read_json_file(records.string(), "a trial record file");
  if (!file.is_object() || !file.contains("trials") || !file["trials"].is_array())
    throw Error("'" + records.string() + "' is not a trial record file");
  Json counts = no_trials();
  for (const Json& trial : file["trials"]) {
    const std::string label = trial.value("antipodal", "");
    const int held = trial.value("held", false) ? 1 : 0;
    add_counts({{"trials", 1}, {"held", held}, {label, {1, held}}}, counts);
  }
  return counts;
}

Json run_scene(const Session& session, const Settings& settings, std::size_t task,
               std::uint64_t seed) {
  Json out = {{"task", task}, {"seed", seed}};
  const auto start = std::chrono::steady_clock::now();
  try {
    bt::Tree tree = load_scene_tree(session, settings, seed);
    tree.set_log_sink([](const bt::Node&, const std::string&) {});
    const bt::Status status = tree.tick_while_running(std::chrono::milliseconds(0));
    const fs::path records = fs::path(settings.folder) / outcome_records_name(seed);
    if (status != bt::Status::kSuccess || !fs::exists(records))
      throw Error("the tree did not write " + records.string());
    out.update(count_trials(records));
  } catch (const Error& error) {
    out["error"] = error.message();
  }
  out["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string progress_line(const Json& r) {
  if (r.contains("error"))
    return "scene " + std::to_string(r["seed"].get<std::uint64_t>()) +
           ": error: " + r["error"].get<std::string>() + "\n";
  char text[160];
  std::snprintf(text, sizeof(text), "scene %llu: %d of %d trials held (%.1f s)\n",
                static_cast<unsigned long long>(r["seed"].get<std::uint64_t>()),
                r["held"].get<int>(), r["trials"].get<int>(), r["wall_s"].get<double>());
  return text;
}

// "320 trials in 10 scenes, 177 held (55.3%); 64 s wall, 120 CPU-s: 2.66 trials per
// CPU-second", then how often the trials of each near-antipodal label held.
void print_summary(std::ostream& out, const Json& total, int scenes, double wall_s, double cpu_s) {
  const int trials = total["trials"].get<int>(), held = total["held"].get<int>();
  const auto percent = [](int part, int whole) { return whole > 0 ? 100.0 * part / whole : 0.0; };
  char text[240];
  std::snprintf(text, sizeof(text),
                "%d trials in %d scenes, %d held (%.1f%%); %.0f s wall, %.0f CPU-s: %.2f "
                "trials per CPU-second\n",
                trials, scenes, held, percent(held, trials), wall_s, cpu_s,
                cpu_s > 0 ? trials / cpu_s : 0.0);
  out << text << "held by near-antipodal label:";
  for (const char* label : kAntipodalLabels) {
    const int n = total[label][0].get<int>(), h = total[label][1].get<int>();
    std::snprintf(text, sizeof(text), " %s %d of %d (%.1f%%)", label, h, n, percent(h, n));
    out << text << (label == kAntipodalLabels[2] ? "\n" : ";");
  }
}

// CPU seconds used so far by this process and its finished children.
double cpu_seconds() {
  double total = 0.0;
  for (const int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage usage{};
    getrusage(who, &usage);
    total += double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
             1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }
  return total;
}

}  // namespace

std::string outcome_records_name(std::uint64_t seed) {
  char text[40];
  std::snprintf(text, sizeof(text), "scene-%06llu.json", static_cast<unsigned long long>(seed));
  return text;
}

std::string outcome_data_name(std::uint64_t seed) {
  return fs::path(outcome_records_name(seed)).replace_extension(".data").string();
}

int run_outcome_data(const OutcomeDataOptions& o) {
  check_options(o);
  const BenchShard shard = parse_shard(o.shard);
  fs::create_directories(o.out_dir);
  Settings settings;
  settings.tree_path = o.tree_path;
  settings.folder = fs::absolute(o.out_dir).string();
  std::ifstream tree_file(o.tree_path);
  settings.tree_yaml.assign(std::istreambuf_iterator<char>(tree_file), {});
  // The cores shared among the processes, as the benches share them; the user's --set last.
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const std::string threads = std::to_string(std::max(1, cores / o.jobs));
  settings.entries = {{"cell.render_threads", threads}, {"sampler.threads", threads}};
  for (auto& entry : parse_overrides(o.set)) settings.entries.push_back(std::move(entry));

  // The shard's seeds whose record file is missing: a killed run resumes there.
  std::vector<std::size_t> tasks;
  int done = 0;
  for (const std::size_t i : shard_tasks(std::size_t(o.scenes), shard)) {
    if (fs::exists(fs::path(settings.folder) / outcome_records_name(o.first_seed + i)))
      ++done;
    else
      tasks.push_back(i);
  }
  std::cout << "outcome data: " << tasks.size() << " scenes to run";
  if (done > 0) std::cout << " (" << done << " done before)";
  if (!shard.whole()) std::cout << "; " << shard.str();
  std::cout << ", " << o.jobs << " process(es), into " << o.out_dir << "\n";
  if (o.jobs > 1 && !tasks.empty())
    check_in_child([&](const Session& s) { load_scene_tree(s, settings, o.first_seed); });
  const double cpu_before = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Json> records = run_bench_tasks(
      tasks, o.jobs,
      [&](const Session& s, std::size_t i) { return run_scene(s, settings, i, o.first_seed + i); },
      progress_line);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_s = cpu_seconds() - cpu_before;
  Json total = no_trials();
  int errors = 0;
  for (const Json& r : records) {
    if (r.contains("error"))
      ++errors;
    else
      add_counts(r, total);
  }
  print_summary(std::cout, total, int(records.size()) - errors, wall_s, cpu_s);
  if (errors > 0)
    std::cout << errors << " scene(s) ended in an error (above); run again to retry them\n";
  return errors;
}

}  // namespace antipode::evaluation
