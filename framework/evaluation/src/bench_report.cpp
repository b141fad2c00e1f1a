#include "antipode/evaluation/bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <thread>

#include <sys/utsname.h>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;
using Filter = std::function<bool(const Json&)>;

double median(std::vector<double> values) { return percentile(std::move(values), 0.5); }

bool succeeded(const Json& a) { return a.at("outcome") == "success"; }

// Attempts, successes, rate, interval and per-object mean of the attempts `keep` accepts.
Json tally(const std::vector<const Json*>& attempts, const Filter& keep) {
  int n = 0, k = 0;
  std::map<std::string, std::pair<int, int>> by_object;  // successes, attempts
  for (const Json* a : attempts) {
    if (!keep(*a)) continue;
    ++n;
    k += succeeded(*a) ? 1 : 0;
    auto& object = by_object[a->at("object").get<std::string>()];
    object.first += succeeded(*a) ? 1 : 0;
    ++object.second;
  }
  double mean = 0.0;
  for (const auto& [name, counts] : by_object) mean += double(counts.first) / counts.second;
  const auto [lo, hi] = wilson_interval(k, n);
  return {{"attempts", n},
          {"successes", k},
          {"success_rate", n ? double(k) / n : 0.0},
          {"ci95", {lo, hi}},
          {"per_object_mean", by_object.empty() ? 0.0 : mean / double(by_object.size())}};
}

Json fidelity(const std::vector<const Json*>& attempts) {
  int executed = 0, as_detected = 0, held = 0;
  for (const Json* a : attempts) {
    if (!a->contains("record") || !a->at("graspable").get<bool>()) continue;
    ++executed;
    const Json& r = a->at("record");
    if (r.at("reached_pose").get<bool>() || !r.at("stopped_by").empty()) ++as_detected;
    held += succeeded(*a) ? 1 : 0;
  }
  const auto [lo, hi] = wilson_interval(held, executed);
  return {{"executed", executed},
          {"as_detected", as_detected},
          {"as_detected_rate", executed ? double(as_detected) / executed : 0.0},
          {"held", held},
          {"held_rate", executed ? double(held) / executed : 0.0},
          {"held_ci95", {lo, hi}}};
}

Json stage_medians(const std::vector<const Json*>& attempts) {
  std::map<std::string, std::vector<double>> seconds;
  for (const Json* a : attempts) {
    for (const auto& [stage, s] : a->at("stage_s").items())
      seconds[stage].push_back(s.get<double>());
    seconds["whole attempt"].push_back(a->at("wall_s").get<double>());
  }
  Json out = Json::object();
  for (auto& [stage, values] : seconds) out[stage] = median(values);
  return out;
}

Json variant_summary(const std::vector<const Json*>& attempts) {
  Json s = tally(attempts, [](const Json&) { return true; });
  int no_grasp = 0;
  Json outcomes = Json::object(), reasons = Json::object();
  for (const Json* a : attempts) {
    no_grasp += a->at("outcome") == "no grasp found" ? 1 : 0;
    const std::string outcome = a->at("outcome"), reason = a->at("reason");
    outcomes[outcome] = outcomes.value(outcome, 0) + 1;
    reasons[reason] = reasons.value(reason, 0) + 1;
  }
  s["no_grasp"] = no_grasp;
  // The arm's failures (trees with an arm): no IK, no motion plan, an arm link in contact.
  const auto count = [&](const std::string& key, const std::string& value) {
    int n = 0;
    for (const Json* a : attempts) n += (*a)[key] == value ? 1 : 0;
    return n;
  };
  s["arm"] = {{"no_ik", count("outcome", "no IK")},
              {"no_motion_plan", count("outcome", "no motion plan")},
              {"arm_collision", count("reason", "arm collision")}};
  s["found_grasp"] =
      tally(attempts, [](const Json& a) { return a.at("outcome") != "no grasp found"; });
  s["outcomes"] = outcomes;
  s["reasons"] = reasons;
  const auto graspable = [](const Json& a) { return a.at("graspable").get<bool>(); };
  const auto held_out = [](const Json& a) { return a.at("held_out").get<bool>(); };
  s["groups"] = {
      {"graspable", tally(attempts, graspable)},
      {"not_graspable", tally(attempts, [&](const Json& a) { return !graspable(a); })},
      {"tuning", tally(attempts, [&](const Json& a) { return graspable(a) && !held_out(a); })},
      {"held_out", tally(attempts, [&](const Json& a) { return graspable(a) && held_out(a); })}};
  s["fidelity"] = fidelity(attempts);
  s["stage_s_median"] = stage_medians(attempts);
  return s;
}

std::string rate_text(const Json& t) {
  char text[64];
  if (t["attempts"].get<int>() == 0) return "-";
  std::snprintf(text, sizeof text, "%.1f%% [%.1f, %.1f]", 100.0 * t["success_rate"].get<double>(),
                100.0 * t["ci95"][0].get<double>(), 100.0 * t["ci95"][1].get<double>());
  return text;
}

void row(std::ostream& out, const std::string& label, const std::vector<std::string>& cells,
         int label_width, int cell_width) {
  char text[256];
  std::snprintf(text, sizeof text, "%-*s", label_width, label.c_str());
  out << text;
  for (const auto& cell : cells) {
    std::snprintf(text, sizeof text, " %*s", cell_width, cell.c_str());
    out << text;
  }
  out << "\n";
}

}  // namespace

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double rank = std::clamp(p, 0.0, 1.0) * double(v.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, v.size() - 1);
  return v[below] + (rank - double(below)) * (v[above] - v[below]);
}

std::pair<double, double> wilson_interval(int successes, int trials) {
  if (trials <= 0) return {0.0, 1.0};
  const double z = 1.959963984540054, n = trials, p = double(successes) / n;
  const double centre = (p + z * z / (2 * n)) / (1 + z * z / n);
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

Json summarise(const Json& attempts, const std::vector<std::string>& variants) {
  Json summary = Json::object();
  for (const auto& variant : variants) {
    std::vector<const Json*> mine;
    for (const Json& a : attempts)
      if (a.at("variant") == variant) mine.push_back(&a);
    summary[variant] = variant_summary(mine);
  }
  return summary;
}

void print_report(std::ostream& out, const Json& attempts, const Json& summary,
                  const std::vector<std::string>& variants) {
  std::vector<std::string> objects;
  std::map<std::string, std::map<std::string, std::pair<int, int>>> cells;  // object, variant
  std::map<std::string, std::pair<int, int>> poses;  // graspable, all (of the first variant)
  std::map<std::string, bool> held_out;
  for (const Json& a : attempts) {
    const std::string object = a.at("object");
    if (std::find(objects.begin(), objects.end(), object) == objects.end())
      objects.push_back(object);
    auto& cell = cells[object][a.at("variant").get<std::string>()];
    cell.first += succeeded(a) ? 1 : 0;
    ++cell.second;
    if (a.at("variant") == variants.front()) {
      poses[object].first += a.at("graspable").get<bool>() ? 1 : 0;
      ++poses[object].second;
    }
    held_out[object] = a.at("held_out").get<bool>();
  }
  std::map<std::string, std::string> marks;
  for (const auto& [object, counts] : poses) {
    if (counts.first == 0)
      marks[object] = " (not graspable)";
    else if (counts.first < counts.second)
      marks[object] = " (graspable in " + std::to_string(counts.first) + "/" +
                      std::to_string(counts.second) + ")";
    if (held_out[object]) marks[object] += " (held out)";
  }
  const int label_width = 46, cell_width = 20;
  row(out, "object", variants, label_width, cell_width);
  for (const auto& object : objects) {
    std::vector<std::string> texts;
    for (const auto& variant : variants) {
      const auto [k, n] = cells[object][variant];
      char text[64];
      std::snprintf(text, sizeof text, "%d/%d %3.0f%%", k, n, n ? 100.0 * k / n : 0.0);
      texts.push_back(n ? text : "-");
    }
    row(out, object + marks[object], texts, label_width, cell_width);
  }
  const auto group_rows = [&](const std::string& label, const std::string& group) {
    std::vector<std::string> pooled, mean;
    for (const auto& variant : variants) {
      const Json& t = group.empty() ? summary[variant] : summary[variant]["groups"][group];
      pooled.push_back(rate_text(t));
      char text[32];
      std::snprintf(text, sizeof text, "%.1f%%", 100.0 * t["per_object_mean"].get<double>());
      mean.push_back(t["attempts"].get<int>() ? text : "-");
    }
    row(out, label + ", per-object mean", mean, label_width, cell_width);
    row(out, label + ", all attempts", pooled, label_width, cell_width);
  };
  out << "\n";
  group_rows("every object", "");
  for (const auto& [label, group] :
       {std::pair{"graspable objects", "graspable"}, std::pair{"not graspable", "not_graspable"},
        std::pair{"graspable, tuning objects", "tuning"},
        std::pair{"graspable, held-out objects", "held_out"}}) {
    bool any = false, all = true;
    for (const auto& variant : variants) {
      const int n = summary[variant]["groups"][group]["attempts"];
      any = any || n > 0;
      all = all && n == summary[variant]["attempts"].get<int>();
    }
    if (any && !all) group_rows(label, group);
  }
  std::vector<std::string> found, fidelity;
  for (const auto& variant : variants) {
    found.push_back(rate_text(summary[variant]["found_grasp"]));
    const Json& f = summary[variant]["fidelity"];
    char text[64];
    std::snprintf(text, sizeof text, "%d/%d held, %d planned", f["held"].get<int>(),
                  f["executed"].get<int>(), f["as_detected"].get<int>());
    fidelity.push_back(text);
  }
  row(out, "where a grasp was found", found, label_width, cell_width);
  row(out, "executed on graspable objects", fidelity, label_width, cell_width);

  out << "\nfailures (attempts)\n";
  std::vector<std::string> reasons;
  for (const auto& variant : variants)
    for (const auto& [reason, count] : summary[variant]["reasons"].items())
      if (reason != "success" && std::find(reasons.begin(), reasons.end(), reason) == reasons.end())
        reasons.push_back(reason);
  for (const auto& reason : reasons) {
    std::vector<std::string> counts;
    counts.reserve(variants.size());
    for (const auto& variant : variants)
      counts.push_back(std::to_string(summary[variant]["reasons"].value(reason, 0)));
    row(out, reason, counts, label_width, cell_width);
  }
  out << "\nseconds per stage (median)\n";
  std::vector<std::string> stages;
  for (const auto& variant : variants)
    for (const auto& [stage, s] : summary[variant]["stage_s_median"].items())
      if (std::find(stages.begin(), stages.end(), stage) == stages.end()) stages.push_back(stage);
  for (const auto& stage : stages) {
    std::vector<std::string> seconds;
    for (const auto& variant : variants) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3f",
                    summary[variant]["stage_s_median"].value(stage, 0.0));
      seconds.push_back(text);
    }
    row(out, stage, seconds, label_width, cell_width);
  }
}

nlohmann::ordered_json machine_json() {
  std::string cpu = "unknown";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  struct utsname name {};
  std::string system = "unknown";
  if (uname(&name) == 0)
    system = std::string(name.sysname) + " " + name.release + " " + name.machine;
  return {{"cpu", cpu},
          {"cores", std::max(1u, std::thread::hardware_concurrency())},
          {"system", system}};
}

void add_how_it_ran(Json& report, int jobs, int threads_per_job, int cores, double wall_s) {
  report["jobs"] = jobs;
  report["threads_per_job"] = threads_per_job;
  report["cores"] = cores;
  report["machine"] = machine_json();
  report["wall_s"] = wall_s;
}

void write_report(std::ostream& out, const std::string& path,
                  const nlohmann::ordered_json& report) {
  if (path.empty()) return;
  write_file_atomically(path, [&](const std::string& temporary) {
    std::ofstream file(temporary);
    file << report.dump(1) << "\n";
    if (!file) throw Error("cannot write the report");
  });
  out << "report: " << path << "\n";
}

}  // namespace antipode::evaluation
