#include "antipode/evaluation/isolation_bench.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/evaluation/bench_processes.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/evaluation/bench_shard.hpp"
#include "antipode/evaluation/bench_task.hpp"
#include "antipode/evaluation/clutter_bench.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"
#include "antipode/robot/robot_file.hpp"

namespace fs = std::filesystem;

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

std::vector<const BenchVariant*> chosen_variants(const std::vector<std::string>& names) {
  std::vector<std::string> known;
  for (const auto& v : isolation_variants()) known.push_back(v.name);
  std::vector<const BenchVariant*> chosen;
  for (const auto& v : isolation_variants())
    if (names.empty() || std::find(names.begin(), names.end(), v.name) != names.end())
      chosen.push_back(&v);
  for (const auto& name : names)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw Error("--variants: unknown variant '" + name + "'" + did_you_mean(name, known) +
                  " (variants: nc_1v, nc_2v, a_2v, svm_1v, svm_2v)");
  return chosen;
}

void check_options(const IsolationBenchOptions& o) {
  if (!o.report_path.empty()) check_output_path(o.report_path);  // before minutes of attempts
  if (o.poses < 1 || o.poses > 360) throw Error("--poses must be in 1..360");
  if (o.attempts < 0) throw Error("--attempts must be 0 (every object in every pose) or more");
  if (o.first < 0) throw Error("--first must be 0 or more");
  if (o.jobs < 1 || o.jobs > 64) throw Error("--jobs must be in 1..64");
  if (!fs::is_regular_file(o.tree_path)) throw Error("--tree: no tree file '" + o.tree_path + "'");
  require_cell_component(o.tree_path, "trees/pick_isolated.yaml");
  for (const auto& [option, dir] :
       {std::pair{"--pictures", &o.pictures_dir}, std::pair{"--selections", &o.selections_dir}})
    if (!dir->empty() && fs::exists(*dir) && !fs::is_directory(*dir))
      throw Error(std::string(option) + ": '" + *dir + "' is not a folder");
  check_entries_are_read(o.tree_path, o.set);  // and throws for an entry without '='
}

std::vector<BenchTask> plan(const IsolationBenchOptions& o, const std::vector<BenchObject>& objects,
                            const std::vector<const BenchVariant*>& variants) {
  std::vector<std::string> names;
  names.reserve(objects.size());
  for (const auto& object : objects) names.push_back(object.name);
  for (const auto& name : o.held_out)
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw Error("--held-out: no object '" + name + "'" + did_you_mean(name, names));
  const int n = int(objects.size());
  const int attempts = o.attempts > 0 ? o.attempts : n * o.poses;
  // Holdable widths: the apertures of the tree's robot's gripper, else Baxter's 3-7 cm.
  std::pair<double, double> graspable{kMinGraspableWidthM, kMaxGraspableWidthM};
  if (const std::string robot = tree_robot_path(o.tree_path, o.set); !robot.empty()) {
    const HandGeometry& hand = read_robot_file(robot).gripper;
    graspable = graspable_width_m(hand.min_aperture_m, hand.max_aperture_m);
  }
  std::vector<BenchTask> tasks;
  for (int i = o.first; i < o.first + attempts; ++i)
    for (const BenchVariant* variant : variants) {
      BenchTask t;
      t.index = int(tasks.size());
      t.attempt = i;
      t.object = objects[std::size_t(i % n)];
      t.pose = (i / n) % o.poses;
      t.poses = o.poses;
      t.variant = variant;
      t.seed = o.seed + std::uint64_t(i);
      t.held_out =
          std::find(o.held_out.begin(), o.held_out.end(), t.object.name) != o.held_out.end();
      t.graspable = t.object.graspable_in_pose(t.pose, o.poses, graspable.first, graspable.second);
      tasks.push_back(std::move(t));
    }
  return tasks;
}

std::string progress_line(const Json& r, std::size_t total) {
  std::ostringstream line;
  line << "[" << r["task"].get<int>() + 1 << "/" << total << "] " << r["variant"].get<std::string>()
       << " " << r["object"].get<std::string>() << " pose " << r["pose"].get<int>() << ": "
       << r["outcome"].get<std::string>();
  if (r["outcome"] != "success" && !r["detail"].get<std::string>().empty())
    line << " - " << r["detail"].get<std::string>();
  line << "\n";
  return line.str();
}

// Loads the tree of each variant's first task in a child process: a parameter the
// variant's plugin does not take is one error line before anything runs, not one per worker.
void check_every_variant_loads(const TaskSettings& settings, const std::vector<BenchTask>& tasks) {
  check_in_child([&](const Session& session) {
    std::vector<const BenchVariant*> seen;
    for (const BenchTask& task : tasks) {
      if (std::find(seen.begin(), seen.end(), task.variant) != seen.end()) continue;
      seen.push_back(task.variant);
      load_task_tree(session, settings, task);
    }
  });
}

}  // namespace

Json run_isolation_bench(const IsolationBenchOptions& o) {
  check_options(o);
  const BenchShard shard = parse_shard(o.shard);
  require_shard_report(shard, o.report_path);
  const std::vector<const BenchVariant*> variants = chosen_variants(o.variants);
  const std::vector<BenchObject> objects = bench_objects(o.objects, o.procedural_file);
  const std::vector<BenchTask> tasks = plan(o, objects, variants);
  if (!o.pictures_dir.empty()) fs::create_directories(o.pictures_dir);

  TaskSettings settings;
  settings.tree_path = o.tree_path;
  std::ifstream tree_file(o.tree_path);
  settings.tree_yaml.assign(std::istreambuf_iterator<char>(tree_file), {});
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  settings.threads = std::max(1, cores / o.jobs);
  settings.noise = o.noise;
  settings.pictures_dir = o.pictures_dir;
  settings.selections_dir = o.selections_dir;
  if (!o.selections_dir.empty() && settings.tree_yaml.find("{selection_file}") == std::string::npos)
    throw Error("--selections: the tree '" + o.tree_path +
                "' writes no selections (it reads no {selection_file} entry; "
                "trees/pick_isolated.yaml does)");
  if (!o.selections_dir.empty()) fs::create_directories(o.selections_dir);
  settings.overrides = o.set;

  std::vector<std::string> variant_names;
  variant_names.reserve(variants.size());
  for (const BenchVariant* v : variants) variant_names.push_back(v->name);
  std::cout << "isolation bench: " << objects.size() << " objects, " << o.poses << " poses, "
            << tasks.size() / variants.size() << " attempts for each of " << variant_names.size()
            << " variants, " << o.jobs << " process(es)";
  const std::vector<std::size_t> shard_indices = shard_tasks(tasks.size(), shard);
  if (!shard.whole()) std::cout << "; " << shard.str() << ": " << shard_indices.size() << " tasks";
  std::cout << "\n";
  const auto start = std::chrono::steady_clock::now();
  if (o.jobs > 1) check_every_variant_loads(settings, tasks);
  std::vector<Json> records = run_bench_tasks(
      shard_indices, o.jobs,
      [&](const Session& session, std::size_t i) { return run_task(session, settings, tasks[i]); },
      [&](const Json& record) { return progress_line(record, tasks.size()); });
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  Json attempts = Json::array();
  for (auto& record : records) attempts.push_back(std::move(record));
  const Json summary = summarise(attempts, variant_names);
  std::cout << "\n";
  print_report(std::cout, attempts, summary, variant_names);
  std::cout << "\nwall time " << wall_s << " s\n";
  Json names = Json::array();
  for (const auto& object : objects) names.push_back(object.name);
  Json report = {{"bench", "isolation"},
                 {"tree", o.tree_path},
                 {"objects", o.objects},
                 {"object_names", names},
                 {"held_out", o.held_out},
                 {"poses", o.poses},
                 {"attempts_per_variant", tasks.size() / variants.size()},
                 {"first", o.first},
                 {"seed", o.seed},
                 {"noise", o.noise.empty() ? "tree" : o.noise},
                 {"overrides", o.set},
                 {"variants", variant_names}};
  add_how_it_ran(report, o.jobs, settings.threads, cores, wall_s);
  report["summary"] = summary;
  report["attempts"] = std::move(attempts);
  if (const std::string robot = tree_robot_path(o.tree_path, o.set); !robot.empty())
    report["robot"] = {{"file", robot}, {"name", read_robot_file(robot).name}};
  if (!shard.whole()) report["shard"] = shard_json(shard, tasks.size());
  return report;
}

bool has_errors(const Json& isolation_report) {
  const Json& attempts = isolation_report.at("attempts");
  return std::any_of(attempts.begin(), attempts.end(),
                     [](const Json& a) { return a.at("outcome") == "error"; });
}

}  // namespace antipode::evaluation
