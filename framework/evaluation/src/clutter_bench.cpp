#include "antipode/evaluation/clutter_bench.hpp"

#include <malloc.h>
#include <algorithm>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "antipode/bt/loader.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/shipped_data.hpp"
#include "antipode/evaluation/bench_objects.hpp"
#include "antipode/evaluation/bench_processes.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/evaluation/bench_shard.hpp"
#include "antipode/evaluation/bench_task.hpp"
#include "antipode/evaluation/clutter_protocols.hpp"
#include "antipode/evaluation/run_bootstrap.hpp"
#include "antipode/evaluation/stage_timer.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/clearing_run.hpp"
#include "antipode/io/gripper_file.hpp"
#include "antipode/robot/robot_file.hpp"

namespace fs = std::filesystem;

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

struct RunSettings {
  std::string tree_path;
  std::string tree_yaml;
  std::string pictures_dir;    ///< failed attempts drawn here as seed-S-cycle-NN.png ("" = none)
  std::string selections_dir;  ///< each cycle's selection as seed-S-cycle-NN.json ("" = none)
  int threads = 2;
  std::vector<std::pair<std::string, std::string>> entries;  ///< the same for every run
  /// Objects left whose narrowest horizontal extent lies in [min, max] count as holdable.
  std::pair<double, double> graspable_m{kMinGraspableWidthM, kMaxGraspableWidthM};
};

// `o` with the protocol's tree and object count where the options leave them open.
ClutterBenchOptions with_protocol(ClutterBenchOptions o) {
  const ClutterProtocol& protocol = clutter_protocol(o.protocol);  // throws for a bad name
  if (o.tree_path.empty()) o.tree_path = resolve_shipped(protocol.tree);
  if (o.objects_per_run == 0) o.objects_per_run = protocol.objects_per_run;
  return o;
}

void check_options(const ClutterBenchOptions& o) {
  if (!o.report_path.empty()) check_output_path(o.report_path);  // before minutes of runs
  if (o.runs < 1 || o.runs > 100000) throw Error("--runs must be in 1..100000");
  if (o.replicates < 1 || o.replicates > 100) throw Error("--replicates must be in 1..100");
  if (std::int64_t(o.runs) * o.replicates > 100000)
    throw Error("--runs times --replicates must be at most 100000");
  if (o.objects_per_run < 1 || o.objects_per_run > 100)
    throw Error("--objects-per-run must be in 1..100");
  if (o.jobs < 1 || o.jobs > 64) throw Error("--jobs must be in 1..64");
  if (!fs::is_regular_file(o.tree_path)) throw Error("--tree: no tree file '" + o.tree_path + "'");
  require_cell_component(o.tree_path, clutter_protocol(o.protocol).tree);
  for (const auto& [option, dir] :
       {std::pair{"--pictures", &o.pictures_dir}, std::pair{"--selections", &o.selections_dir}})
    if (!dir->empty() && fs::exists(*dir) && !fs::is_directory(*dir))
      throw Error(std::string(option) + ": '" + *dir + "' is not a folder");
  if (o.objects != "procedural" && !fs::is_directory(o.objects))
    throw Error("--objects: '" + o.objects + "' is neither 'procedural' nor a folder of meshes");
  check_entries_are_read(o.tree_path, o.set);  // and throws for an entry without '='
  if (!o.gripper_path.empty()) read_gripper_file(o.gripper_path);  // throws for a bad file
}

// The --set entries every run shares, the user's last.
std::vector<std::pair<std::string, std::string>> shared_entries(const ClutterBenchOptions& o,
                                                                int threads) {
  const std::string t = std::to_string(threads);
  std::vector<std::pair<std::string, std::string>> entries;
  if (const std::string& scene = clutter_protocol(o.protocol).scene; !scene.empty())
    entries.emplace_back("cell.scene", scene);
  for (auto& entry : std::vector<std::pair<std::string, std::string>>{
           {"cell.object_count", std::to_string(o.objects_per_run)},
           {"cell.render_threads", t},
           {"sampler.threads", t},
           {"selector.threads", t},
           {"classifier.threads", t}})
    entries.push_back(std::move(entry));
  if (o.objects != "procedural") entries.emplace_back("cell.objects", fs::absolute(o.objects));
  if (!o.noise.empty()) entries.emplace_back("cell.noise", o.noise);
  if (!o.gripper_path.empty()) entries.emplace_back("sampler.hand", fs::absolute(o.gripper_path));
  for (auto& entry : parse_overrides(o.set)) entries.push_back(std::move(entry));
  return entries;
}

// For a folder option `option` (DIR, "" = not given): throws unless the tree reads the entry
// `key` the bench sets from it (the tree is what writes the files), then makes the folder.
void require_tree_entry(const RunSettings& settings, const std::string& option,
                        const std::string& dir, const std::string& key, const std::string& what) {
  if (dir.empty()) return;
  if (settings.tree_yaml.find("{" + key + "}") == std::string::npos)
    throw Error(option + ": the tree '" + settings.tree_path + "' " + what + " (it reads no {" +
                key + "} entry; trees/clear_box.yaml does)");
  std::error_code error;
  fs::create_directories(dir, error);
  if (error)
    throw Error(option + ": cannot make the folder '" + dir + "' (" + error.message() + ")");
}

// The tree of run `seed`, replicate `replicate` (ClutterBenchOptions::replicates).
bt::Tree load_run_tree(const Session& session, const RunSettings& settings, std::uint64_t seed,
                       int replicate) {
  bt::LoadOptions load;
  load.registry = &session.registry;
  load.components = session.host.get();
  load.seed = seed;
  load.overrides = {{"cell.seed", std::to_string(seed)}};
  if (replicate > 0) {  // before the user's entries, which may set other noise
    std::ostringstream noise;
    noise << kReplicateNoiseM;
    load.overrides.emplace_back("cell.execution_noise_m", noise.str());
    load.overrides.emplace_back("cell.execution_seed", std::to_string(replicate));
  }
  const std::string run_prefix = clutter_run_prefix(seed, replicate);
  if (!settings.pictures_dir.empty())
    load.overrides.emplace_back("picture_prefix",
                                (fs::path(settings.pictures_dir) / run_prefix).string());
  if (!settings.selections_dir.empty())
    load.overrides.emplace_back("selection_prefix",
                                (fs::path(settings.selections_dir) / run_prefix).string());
  for (const auto& entry : settings.entries) load.overrides.push_back(entry);
  return bt::load_tree_string(settings.tree_yaml, settings.tree_path, load);
}

// An attempt's failure class: the cell's record classified, or the planner's outcome.
std::string reason_of(const ClearingCycle& cycle) {
  return cycle.attempt ? failure_class(*cycle.attempt) : cycle.outcome;
}

Json cycle_json(const ClearingCycle& cycle) {
  Json out = {{"outcome", cycle.outcome}, {"reason", reason_of(cycle)}};
  out["detail"] = cycle.attempt ? cycle.attempt->reason : "";
  if (cycle.grasp) out["hand"] = hand_json(*cycle.grasp);
  if (cycle.attempt) out["record"] = record_json(*cycle.attempt);
  out["objects_before"] = cycle.objects_before;
  out["objects_after"] = cycle.objects_after;
  out["seconds"] = cycle.seconds;
  return out;
}

// What was left in the cell at the end of a run, from its ground truth (a simulated cell's):
// `left_objects` (name and narrowest horizontal extent of each) and `left_graspable` (how many
// of them have a width in `graspable_m`, so that the gripper could hold them from above as
// they lay). Nothing when the tree has no cell or the cell has no ground truth.
void record_what_was_left(const bt::Tree& tree, const std::pair<double, double>& graspable_m,
                          Json& out) {
  for (const std::string& name : tree.component_names()) {
    const auto cell = std::dynamic_pointer_cast<const Cell>(tree.component(name));
    if (!cell) continue;
    const std::vector<ObjectTruth> truth = cell->object_truth();
    if (truth.empty() && out["left"].get<int>() != 0) return;
    Json left = Json::array();
    int graspable = 0;
    for (const ObjectTruth& object : truth) {
      left.push_back(
          {{"name", object.name}, {"narrowest_horizontal_m", object.narrowest_horizontal_m}});
      graspable += object.narrowest_horizontal_m >= graspable_m.first &&
                   object.narrowest_horizontal_m <= graspable_m.second;
    }
    out["left_objects"] = left;
    out["left_graspable"] = graspable;
    out["graspable_width_m"] = {graspable_m.first, graspable_m.second};
    return;
  }
}

// This process's resident memory (MB, from /proc/self/status; 0 where there is none), after
// handing freed memory back to the system: a process that runs many episodes must not grow.
double resident_mb() {
  ::malloc_trim(0);  // what the process holds, not what the allocator keeps for reuse
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;
  return 0.0;
}

Json run_one(const Session& session, const RunSettings& settings, std::size_t index,
             std::uint64_t seed, int replicate) {
  Json out = {{"task", index}, {"seed", seed}, {"replicate", replicate}};
  const auto start = std::chrono::steady_clock::now();
  StageTimer timer;
  {
    bt::Tree tree = load_run_tree(session, settings, seed, replicate);
    tree.set_log_sink([](const bt::Node&, const std::string&) {});
    tree.add_observer(&timer);
    timer.start();
    try {
      tree.tick_while_running(std::chrono::milliseconds(0));
      if (!tree.blackboard().has("run")) throw Error("the tree wrote no {run} (a ClearBox node's)");
      const ClearingRun& run = tree.blackboard().get_ref<ClearingRun>("run");
      out["objects"] = run.objects_at_start;
      out["attempts"] = run.attempts();
      out["successes"] = run.successes();
      out["removed"] = run.successes();
      out["left"] = run.objects_left();
      out["lost"] = run.objects_lost();
      // Objects that did not come to rest in the workspace (bounced out of the box), when the
      // cell can tell (Cell::objects_placed).
      if (run.missed_at_filling() >= 0) out["missed_at_filling"] = run.missed_at_filling();
      out["stop"] = to_string(run.stop);
      out["summary"] = run.summary();
      record_what_was_left(tree, settings.graspable_m, out);
      Json cycles = Json::array();
      for (const ClearingCycle& cycle : run.cycles) cycles.push_back(cycle_json(cycle));
      out["cycles"] = cycles;
    } catch (const std::exception& error) {
      out["error"] = error.what();
    }
    out["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    tree.remove_observer(&timer);
  }
  // After the episode's tree, its blackboard (the last cycle's clouds and hands) and its
  // components are gone: what the process still holds is what the next episodes inherit.
  out["rss_mb"] = resident_mb();
  out["stage_s"] = timer.seconds();
  return out;
}

std::string progress_line(const Json& r, int runs) {
  std::ostringstream line;
  line << "[run " << r["task"].get<int>() + 1 << "/" << runs << "] seed " << r["seed"];
  if (r["replicate"].get<int>() > 0) line << " (replicate " << r["replicate"] << ")";
  line << ": ";
  if (r.contains("error")) {
    line << "error - " << r["error"].get<std::string>() << "\n";
    return line.str();
  }
  line << r["summary"].get<std::string>() << " (" << r["stop"].get<std::string>() << ", "
       << std::fixed << std::setprecision(1) << r["wall_s"].get<double>() << " s)\n";
  return line.str();
}

// The paper's failure groups (section 5.3) of a failure class.
std::string paper_class(const std::string& reason) {
  static const std::map<std::string, std::string> groups = {
      {"nothing between the planned fingers", "perception"},
      {"closed on nothing", "perception"},
      {"planned into the object", "perception"},
      {"stopped short of the pose", "perception"},
      {"slipped", "dropped"},
      {"arm collision", "collision"},
      {"collision at the stand-off pose", "collision"},
      {"no IK", "reach"},
      {"no motion plan", "reach"}};
  const auto group = groups.find(reason);
  return group == groups.end() ? "other" : group->second;
}

Json rate(int k, int n) {
  const auto [lo, hi] = wilson_interval(k, n);
  return {{"rate", n > 0 ? double(k) / n : 0.0}, {"ci95", {lo, hi}}};
}

}  // namespace

void print_clutter_summary(std::ostream& out, const Json& s, const std::string& protocol_name) {
  const ClutterProtocol& protocol = clutter_protocol(protocol_name);
  const auto pct = [](double v) {
    std::ostringstream t;
    t << std::fixed << std::setprecision(1) << 100 * v;
    return t.str();
  };
  const auto interval = [&](const Json& r) {
    std::string text = pct(r["rate"].get<double>()) + "% [" + pct(r["ci95"][0].get<double>()) +
                       ", " + pct(r["ci95"][1].get<double>()) + "]";
    if (r.contains("ci95_runs"))
      text += ", between runs [" + pct(r["ci95_runs"][0].get<double>()) + ", " +
              pct(r["ci95_runs"][1].get<double>()) + "]";
    return text;
  };
  const auto published = [&](bool success) {
    std::string text;
    for (const auto& p : protocol.published) {
      const double pct_value = success ? p.success_pct : p.removed_pct;
      if (pct_value < 0) continue;
      std::ostringstream t;
      t << (text.empty() ? "" : ", ") << p.who << " " << std::fixed << std::setprecision(1)
        << pct_value << "%";
      text += t.str();
    }
    return text;
  };
  out << protocol.success_name << " " << s["successes"] << " / " << s["attempts"] << " = "
      << interval(s["success_rate"]) << " (" << published(true) << ")\n";
  out << protocol.removed_name << " " << s["removed"] << " / " << s["objects"] << " = "
      << interval(s["removed_rate"]) << " (" << published(false) << ")\n";
  out << "objects out of the workspace (off the table or out of the box) other than by a pick: "
      << s["lost"] << " during the runs";
  if (s.contains("missed_at_filling")) out << ", " << s["missed_at_filling"] << " while filling";
  out << "\n";
  if (s.contains("by_replicate")) {
    out << "by replicate (success; removed; out of the workspace):";
    for (const Json& r : s["by_replicate"])
      out << "  " << r["replicate"] << ": " << pct(r["success_rate"].get<double>()) << "% ("
          << r["successes"] << "/" << r["attempts"] << "); " << r["removed"] << "/" << r["objects"]
          << "; " << r["lost"];
    out << "\n";
  }
  if (s.contains("left_graspable")) {
    const int graspable = s["removed"].get<int>() + s["left_graspable"].get<int>();
    const auto [min_m, max_m] = summary_graspable_width_m(s);
    out << "objects left " << s["left"] << ", of which "
        << s["left"].get<int>() - s["left_graspable"].get<int>()
        << " lay too wide or too thin for the gripper across every horizontal direction (narrowest "
        << "horizontal extent outside " << 100 * min_m << "-" << 100 * max_m
        << " cm); removed of the objects it could hold: " << s["removed"] << " / " << graspable
        << " = " << interval(s["removed_of_graspable_rate"]) << "\n";
  }
  out << "cycles " << s["cycles"] << ", of which found no grasp " << s["no_grasp"] << "\n";
  out << "failures by class:";
  for (const auto& [reason, count] : s["reasons"].items()) out << "  " << reason << " " << count;
  out << "\nfailures as the paper groups them (share of attempts):";
  for (const auto& [group, count] : s["paper_classes"].items())
    out << "  " << group << " " << count << " ("
        << pct(s["attempts"].get<int>() > 0 ? count.get<double>() / s["attempts"].get<int>() : 0)
        << "%)";
  out << "\nruns ended:";
  for (const auto& [stop, count] : s["stops"].items()) out << "  " << stop << " " << count;
  out << "\nsuccesses / attempts by object:";
  for (const auto& o : s["by_object"])
    out << "  " << o["name"].get<std::string>() << " " << o["successes"] << "/" << o["attempts"];
  out << "\nmedian seconds: cycle " << s["cycle_s_median"] << ", run " << s["run_s_median"] << "\n";
}

std::pair<double, double> graspable_width_m(double min_aperture_m, double max_aperture_m) {
  // Rounded to 0.1 mm first, so that an aperture of exactly 3 cm is not taken for 3.0000001.
  const auto cm = [](double m) { return std::round(m * 1000.0) / 10.0; };
  return {std::ceil(cm(min_aperture_m)) / 100.0, std::floor(cm(max_aperture_m)) / 100.0};
}

std::pair<double, double> summary_graspable_width_m(const Json& summary) {
  if (!summary.contains("graspable_width_m")) return {kMinGraspableWidthM, kMaxGraspableWidthM};
  const Json& range = summary["graspable_width_m"];
  return {range[0].get<double>(), range[1].get<double>()};
}

std::string clutter_run_prefix(std::uint64_t seed, int replicate) {
  std::string prefix = "seed-" + std::to_string(seed) + "-";
  if (replicate > 0) prefix += "replicate-" + std::to_string(replicate) + "-";
  return prefix;
}

Json between_runs_intervals(const Json& runs) {
  // One count per seed, its replicates summed: they share the seed's scene.
  std::map<std::uint64_t, RunCount> attempts_of, objects_of;
  for (const Json& run : runs) {
    if (run.contains("error")) continue;  // counted apart, as in the summary
    const auto seed = run.at("seed").get<std::uint64_t>();
    RunCount& a = attempts_of[seed];
    a.successes += run.at("successes").get<int>();
    a.trials += run.at("attempts").get<int>();
    // As in the summary, a run whose cell cannot count its objects (-1) adds nothing to removal.
    if (run.at("objects").get<int>() >= 0) {
      RunCount& o = objects_of[seed];
      o.successes += run.at("removed").get<int>();
      o.trials += run.at("objects").get<int>();
    }
  }
  std::vector<RunCount> attempts, objects;
  for (const auto& [seed, count] : attempts_of) attempts.push_back(count);
  for (const auto& [seed, count] : objects_of) objects.push_back(count);
  Json out = {{"runs", attempts.size()}};
  const auto as_json = [](std::pair<double, double> bounds) {
    return Json{bounds.first, bounds.second};
  };
  if (attempts.size() >= 2) out["success"] = as_json(run_bootstrap_interval(attempts));
  if (objects.size() >= 2) out["removed"] = as_json(run_bootstrap_interval(objects));
  return out;
}

namespace {

// by_object's names for attempts without an object.
constexpr const char* kNotExecuted = "(not executed)";
constexpr const char* kNothingBetweenTheFingers = "(nothing between the fingers)";

// Whether a cycle chose no grasp to try (no attempt).
bool found_no_grasp(const Json& cycle) {
  return cycle.at("outcome") == kNoGraspFound || cycle.at("outcome") == kNothingPredictedToHold;
}

// The object an attempt was made on, by the cell's account: the first named between the
// planned fingers when the grasp was detected.
std::string attempted_object(const Json& cycle) {
  if (!cycle.contains("record")) return kNotExecuted;
  const Json& record = cycle.at("record");
  if (!record.contains("between_fingers_at_detection") ||
      record.at("between_fingers_at_detection").empty())
    return kNothingBetweenTheFingers;
  return record.at("between_fingers_at_detection").at(0);
}

Json attempts_by_object(const Json& runs) {
  std::map<std::string, Json> objects;
  for (const Json& run : runs) {
    if (run.contains("error")) continue;
    for (const Json& cycle : run.at("cycles")) {
      if (found_no_grasp(cycle)) continue;
      const std::string name = attempted_object(cycle);
      Json& o = objects
                    .try_emplace(name, Json{{"name", name},
                                            {"attempts", 0},
                                            {"successes", 0},
                                            {"reasons", Json::object()}})
                    .first->second;
      o["attempts"] = o["attempts"].get<int>() + 1;
      const std::string reason = cycle.at("reason");
      if (reason == "success")
        o["successes"] = o["successes"].get<int>() + 1;
      else
        o["reasons"][reason] = o["reasons"].value(reason, 0) + 1;
    }
  }
  std::vector<Json> sorted;
  sorted.reserve(objects.size());
  for (auto& [name, o] : objects) sorted.push_back(std::move(o));
  std::stable_sort(sorted.begin(), sorted.end(), [](const Json& a, const Json& b) {
    return a.at("attempts").get<int>() > b.at("attempts").get<int>();
  });
  return Json(sorted);
}

// Each replicate's tallies, in replicate order; nothing when the records are of one replicate
// (reports written before replicates have none: replicate 0).
Json replicate_tallies(const Json& runs) {
  struct Tally {
    int runs = 0, attempts = 0, successes = 0, objects = 0, removed = 0, lost = 0;
  };
  std::map<int, Tally> by_replicate;
  for (const Json& run : runs) {
    if (run.contains("error")) continue;
    Tally& t = by_replicate[run.value("replicate", 0)];
    ++t.runs;
    t.attempts += run.at("attempts").get<int>();
    t.successes += run.at("successes").get<int>();
    if (run.at("objects").get<int>() >= 0) {  // as in the summary
      t.objects += run.at("objects").get<int>();
      t.removed += run.at("removed").get<int>();
    }
    t.lost += std::max(0, run.at("lost").get<int>());
  }
  if (by_replicate.size() < 2) return nullptr;
  Json out = Json::array();
  for (const auto& [replicate, t] : by_replicate)
    out.push_back({{"replicate", replicate},
                   {"runs", t.runs},
                   {"attempts", t.attempts},
                   {"successes", t.successes},
                   {"objects", t.objects},
                   {"removed", t.removed},
                   {"lost", t.lost},
                   {"success_rate", t.attempts > 0 ? double(t.successes) / t.attempts : 0.0},
                   {"removed_rate", t.objects > 0 ? double(t.removed) / t.objects : 0.0}});
  return out;
}

}  // namespace

Json summarise_clutter(const Json& runs) {
  int attempts = 0, successes = 0, objects = 0, removed = 0, lost = 0, cycles = 0, no_grasp = 0,
      errors = 0, missed_at_filling = 0;
  int left = 0, left_graspable = 0;
  Json graspable_width = {kMinGraspableWidthM, kMaxGraspableWidthM};
  bool truth = true;            // every run says what was left
  bool filling_counted = true;  // ... and how many objects missed the box while filling
  Json reasons = Json::object(), groups = Json::object(), stops = Json::object();
  std::vector<double> cycle_s, run_s;
  for (const Json& run : runs) {
    if (run.contains("error")) {
      ++errors;
      continue;
    }
    attempts += run.at("attempts").get<int>();
    successes += run.at("successes").get<int>();
    if (run.at("objects").get<int>() >= 0) {  // -1: a cell that cannot count its objects
      objects += run.at("objects").get<int>();
      removed += run.at("removed").get<int>();
    }
    lost += std::max(0, run.at("lost").get<int>());
    filling_counted = filling_counted && run.contains("missed_at_filling");  // not in older reports
    missed_at_filling += run.value("missed_at_filling", 0);
    truth = truth && run.contains("left_graspable");
    if (truth) {
      left += int(run.at("left_objects").size());
      left_graspable += run.at("left_graspable").get<int>();
      if (run.contains("graspable_width_m")) graspable_width = run.at("graspable_width_m");
    }
    const std::string stop = run.at("stop");
    stops[stop] = stops.value(stop, 0) + 1;
    run_s.push_back(run.at("wall_s").get<double>());
    for (const Json& cycle : run.at("cycles")) {
      ++cycles;
      cycle_s.push_back(cycle.at("seconds").get<double>());
      const std::string reason = cycle.at("reason");
      const bool found_none = found_no_grasp(cycle);
      if (found_none) ++no_grasp;
      if (found_none || reason == "success") continue;
      reasons[reason] = reasons.value(reason, 0) + 1;
      const std::string group = paper_class(reason);
      groups[group] = groups.value(group, 0) + 1;
    }
  }
  Json summary = {{"runs", runs.size()},
                  {"errors", errors},
                  {"attempts", attempts},
                  {"successes", successes},
                  {"objects", objects},
                  {"removed", removed},
                  {"lost", lost},
                  {"success_rate", rate(successes, attempts)},
                  {"removed_rate", rate(removed, objects)},
                  {"cycles", cycles},
                  {"no_grasp", no_grasp},
                  {"reasons", reasons},
                  {"paper_classes", groups},
                  {"stops", stops},
                  {"cycle_s_median", percentile(cycle_s, 0.5)},
                  {"run_s_median", percentile(run_s, 0.5)},
                  {"by_object", attempts_by_object(runs)}};
  const Json between_runs = between_runs_intervals(runs);
  if (between_runs.contains("success"))
    summary["success_rate"]["ci95_runs"] = between_runs.at("success");
  if (between_runs.contains("removed"))
    summary["removed_rate"]["ci95_runs"] = between_runs.at("removed");
  if (filling_counted) summary["missed_at_filling"] = missed_at_filling;
  if (Json replicates = replicate_tallies(runs); !replicates.is_null())
    summary["by_replicate"] = std::move(replicates);
  // The objects the gripper could hold as they lay: those removed and those left that fit.
  if (truth && errors < int(runs.size())) {
    summary["left"] = left;
    summary["left_graspable"] = left_graspable;
    summary["removed_of_graspable_rate"] = rate(removed, removed + left_graspable);
    summary["graspable_width_m"] = graspable_width;
  }
  return summary;
}

Json run_clutter_bench(const ClutterBenchOptions& options) {
  const ClutterBenchOptions o = with_protocol(options);
  check_options(o);
  const BenchShard shard = parse_shard(o.shard);
  require_shard_report(shard, o.report_path);
  // Task t is replicate t / runs of run t % runs: the first replicate of every run comes first.
  const std::size_t total = std::size_t(o.runs) * std::size_t(o.replicates);
  const std::vector<std::size_t> tasks = shard_tasks(total, shard);
  RunSettings settings;
  settings.tree_path = o.tree_path;
  settings.pictures_dir = o.pictures_dir;
  settings.selections_dir = o.selections_dir;
  std::ifstream tree_file(o.tree_path);
  settings.tree_yaml.assign(std::istreambuf_iterator<char>(tree_file), {});
  // The pictures and selections are the tree's: it writes them from the `picture_prefix` and
  // `selection_prefix` entries the bench sets.
  require_tree_entry(settings, "--pictures", o.pictures_dir, "picture_prefix", "draws no pictures");
  require_tree_entry(settings, "--selections", o.selections_dir, "selection_prefix",
                     "writes no selections");
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  settings.threads = std::max(1, cores / o.jobs);
  settings.entries = shared_entries(o, settings.threads);
  std::optional<GripperFile> gripper;
  const std::string robot_path = tree_robot_path(o.tree_path, o.set);
  std::optional<RobotFile> robot;
  if (!robot_path.empty()) robot = read_robot_file(robot_path);
  if (!o.gripper_path.empty()) {
    gripper = read_gripper_file(o.gripper_path);
    settings.graspable_m =
        graspable_width_m(gripper->geometry.min_aperture_m, gripper->geometry.max_aperture_m);
  } else if (robot) {
    settings.graspable_m =
        graspable_width_m(robot->gripper.min_aperture_m, robot->gripper.max_aperture_m);
  }

  std::cout << "clutter bench (" << o.protocol << "): " << o.runs << " runs of "
            << o.objects_per_run << " objects (" << o.objects << ")";
  if (o.replicates > 1) std::cout << ", " << o.replicates << " replicates each";
  std::cout << ", " << o.jobs << " process(es)";
  if (!shard.whole()) std::cout << "; " << shard.str() << ": " << tasks.size() << " runs";
  std::cout << "\n";
  const auto start = std::chrono::steady_clock::now();
  // With several processes, a tree that cannot load is one error line, not one per process.
  if (o.jobs > 1)
    check_in_child([&](const Session& session) {
      load_run_tree(session, settings, o.seed, o.replicates > 1 ? 1 : 0);
    });
  const std::size_t per_replicate = std::size_t(o.runs);
  std::vector<Json> records = run_bench_tasks(
      tasks, o.jobs,
      [&](const Session& session, std::size_t i) {
        return run_one(session, settings, i, o.seed + i % per_replicate, int(i / per_replicate));
      },
      [&](const Json& record) { return progress_line(record, int(total)); });
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  Json runs = Json::array();
  for (auto& record : records) runs.push_back(std::move(record));
  const Json summary = summarise_clutter(runs);
  std::cout << "\n";
  print_clutter_summary(std::cout, summary, o.protocol);
  std::cout << "wall time " << wall_s << " s\n";
  Json report = {{"bench", "clutter"},
                 {"protocol", o.protocol},
                 {"tree", o.tree_path},
                 {"objects", o.objects},
                 {"runs", o.runs},
                 {"replicates", o.replicates},
                 {"objects_per_run", o.objects_per_run},
                 {"seed", o.seed},
                 {"noise", o.noise.empty() ? "tree" : o.noise},
                 {"overrides", o.set}};
  add_how_it_ran(report, o.jobs, settings.threads, cores, wall_s);
  report["summary"] = summary;
  report["run_records"] = std::move(runs);
  if (gripper) report["gripper"] = {{"file", o.gripper_path}, {"name", gripper->name}};
  if (robot) {
    report["robot"] = {{"file", robot_path}, {"name", robot->name}};
    if (!robot->success_model_path.empty())
      report["robot"]["success_model"] = robot->success_model_path;
  }
  // Which of the robot file's models the classifiers use (trees/clear_box.yaml's `labels`).
  if (const std::string labels = tree_setting(o.tree_path, o.set, "labels"); !labels.empty())
    report["labels"] = labels;
  if (!shard.whole()) report["shard"] = shard_json(shard, total);
  return report;
}

}  // namespace antipode::evaluation
