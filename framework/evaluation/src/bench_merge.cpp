#include "antipode/evaluation/bench_merge.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/evaluation/clutter_bench.hpp"
#include "antipode/evaluation/clutter_protocols.hpp"
#include "antipode/evaluation/json_file.hpp"

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

// What each kind of bench calls its records.
std::string records_key(const std::string& bench) {
  if (bench == "isolation") return "attempts";
  if (bench == "clutter") return "run_records";
  return "";
}

// Entries that differ between shards of one bench: the shard's own records and figures and
// how its machine ran it.
bool per_shard(const std::string& key, const std::string& records) {
  static const std::set<std::string> keys = {"shard", "summary",         "wall_s", "jobs",
                                             "cores", "threads_per_job", "machine"};
  return key == records || keys.count(key) > 0;
}

// The most shards and tasks a report may claim (`--shard` takes at most 10000 shards;
// `--runs`, and `--poses` times the objects, stay far below the tasks).
constexpr std::int64_t kMaxShards = 10000;
constexpr std::int64_t kMaxTasks = 10000000;

// Throws antipode::Error unless `report` (read from `path`) is one shard's report.
void check_shard(const Json& report, const std::string& path) {
  if (!report.is_object() || !report.contains("bench") || !report["bench"].is_string() ||
      records_key(report["bench"].get<std::string>()).empty())
    throw Error(path + ": not the report of an isolation or clutter bench");
  const Json& shard = report.contains("shard") ? report["shard"] : Json();
  if (!shard.is_object() || !shard.contains("index") || !shard.contains("count") ||
      !shard.contains("tasks"))
    throw Error(path + ": not a shard's report (no \"shard\" entry: run the bench with --shard)");
  // Bounded as the bench's options are, before anything is sized by them.
  const auto whole = [&](const char* key, std::int64_t lo, std::int64_t hi) {
    const Json& v = shard[key];
    if (!v.is_number_integer() || v.get<std::int64_t>() < lo || v.get<std::int64_t>() > hi)
      throw Error(path + ": \"shard\": \"" + key + "\" is " + v.dump() +
                  ", not a whole number in " + std::to_string(lo) + ".." + std::to_string(hi));
  };
  whole("count", 1, kMaxShards);
  whole("index", 1, shard["count"].get<std::int64_t>());
  whole("tasks", 0, kMaxTasks);
  if (!report.contains(records_key(report["bench"])) ||
      !report[records_key(report["bench"])].is_array())
    throw Error(path + ": the report has no records");
}

// "PATH: entry "KEY" WHAT".
Error entry_error(const std::string& path, const std::string& key, const std::string& what) {
  return Error(path + ": entry \"" + key + "\" " + what);
}

// Throws unless `report` (from `path`) was run with the settings of `first` (from `first_path`).
void check_same_bench(const Json& first, const std::string& first_path, const Json& report,
                      const std::string& path) {
  const std::string records = records_key(first["bench"]);
  const std::string differs = "differs from " + first_path + "'s: the shards are not of one bench";
  for (const auto& [key, value] : first.items()) {
    if (per_shard(key, records)) continue;
    if (!report.contains(key) || report[key] != value) throw entry_error(path, key, differs);
  }
  const std::string missing = "is not in " + first_path;
  for (const auto& [key, value] : report.items())
    if (!per_shard(key, records) && !first.contains(key)) throw entry_error(path, key, missing);
  if (report["shard"]["count"] != first["shard"]["count"] ||
      report["shard"]["tasks"] != first["shard"]["tasks"])
    throw Error(path + ": its shard count or task count differs from " + first_path + "'s");
}

// The records of every shard in task order; throws unless each shard 1..n came exactly once
// and the records are the bench's tasks 0..tasks-1, each once.
Json joined_records(const std::vector<Json>& shards, const std::vector<std::string>& paths) {
  const std::string key = records_key(shards.front()["bench"]);
  const int count = shards.front()["shard"]["count"].get<int>();
  const auto tasks = shards.front()["shard"]["tasks"].get<std::size_t>();
  std::set<int> seen;
  for (std::size_t i = 0; i < shards.size(); ++i)
    if (!seen.insert(shards[i]["shard"]["index"].get<int>()).second)
      throw Error(paths[i] + ": shard " + shards[i]["shard"]["index"].dump() + " given twice");
  if (int(seen.size()) != count) {
    std::string missing;  // the first ten
    int listed = 0;
    for (int i = 1; i <= count && listed <= 10; ++i)
      if (!seen.count(i))
        missing += (listed++ == 10 ? ", ..." : (missing.empty() ? "" : ", ") + std::to_string(i));
    throw Error("shards " + missing + " of " + std::to_string(count) + " are missing");
  }
  std::vector<Json> records;
  for (const Json& shard : shards)
    for (const Json& record : shard[key]) records.push_back(record);
  std::sort(records.begin(), records.end(), [](const Json& a, const Json& b) {
    return a.at("task").get<std::size_t>() < b.at("task").get<std::size_t>();
  });
  for (std::size_t i = 0; i < records.size(); ++i)
    if (records[i]["task"].get<std::size_t>() != i)
      throw Error("the shards' records are not tasks 0.." + std::to_string(tasks - 1) +
                  " each once (task " + std::to_string(i) + ")");
  if (records.size() != tasks)
    throw Error("the shards hold " + std::to_string(records.size()) + " records of " +
                std::to_string(tasks) + " tasks");
  return Json(records);
}

}  // namespace

Json merge_shard_reports(const std::vector<Json>& shards, const std::vector<std::string>& paths) {
  if (shards.empty()) throw Error("bench merge: give the shards' reports");
  if (paths.size() != shards.size())
    throw Error("bench merge: " + std::to_string(shards.size()) + " shards but " +
                std::to_string(paths.size()) + " file names");
  for (std::size_t i = 0; i < shards.size(); ++i) check_shard(shards[i], paths[i]);
  for (std::size_t i = 1; i < shards.size(); ++i)
    check_same_bench(shards.front(), paths.front(), shards[i], paths[i]);
  const std::string bench = shards.front()["bench"];
  // The records and their summary; a record without an entry the summary reads (a hand-edited
  // or truncated file) is bad input, named as such.
  Json records, summary;
  std::vector<std::string> variants;  // an isolation bench's
  try {
    records = joined_records(shards, paths);
    if (bench != "clutter") variants = shards.front().at("variants");
    if (bench != "clutter" && variants.empty())
      throw Error(paths.front() + ": \"variants\" is empty: the report names no variant");
    summary = bench == "clutter" ? summarise_clutter(records) : summarise(records, variants);
  } catch (const Json::exception& e) {
    throw Error("bench merge: a shard's record lacks an entry or has a malformed one (" +
                std::string(e.what()) + ")");
  }

  Json merged;
  double wall_s = 0.0;
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const auto entry = shards[i].find("wall_s");
    if (entry != shards[i].end() && !entry->is_number())
      throw Error(paths[i] + ": \"wall_s\" is " + entry->dump() + ", not a number of seconds");
    if (entry != shards[i].end()) wall_s += entry->get<double>();
  }
  for (const auto& [key, value] : shards.front().items())
    if (key != "shard") merged[key] = value;
  merged["wall_s"] = wall_s;
  merged["shards"] = shards.size();
  merged[records_key(bench)] = records;
  merged["summary"] = summary;
  return merged;
}

std::string merged_tables(const Json& merged, const std::string& first_name) {
  const std::string bench = merged.at("bench");
  const Json& records = merged.at(records_key(bench));
  const Json& summary = merged.at("summary");
  // What is printed reads the merged report: a malformed entry is the shards' fault.
  std::ostringstream printed;
  try {
    std::vector<std::string> variants;  // an isolation bench's
    if (bench != "clutter") variants = merged.at("variants").get<std::vector<std::string>>();
    if (bench == "clutter")
      print_clutter_summary(printed, summary, report_protocol(merged).name);
    else
      print_report(printed, records, summary, variants);
  } catch (const Error& e) {
    throw Error("bench merge: " + first_name + ": " + e.what());
  } catch (const Json::exception& e) {
    throw Error("bench merge: a shard has a malformed entry (" + std::string(e.what()) + ")");
  }
  std::ostringstream text;
  text << bench << " bench: " << merged.at("shards").get<std::size_t>() << " shards, "
       << records.size() << " records\n\n"
       << printed.str() << "wall time " << merged.at("wall_s").get<double>()
       << " s (the shards' sum)\n";
  return text.str();
}

Json run_bench_merge(const BenchMergeOptions& o) {
  if (o.reports.empty()) throw Error("bench merge: give the shards' reports");
  if (!o.report_path.empty()) check_output_path(o.report_path);
  std::vector<Json> shards;
  for (const std::string& path : o.reports)
    shards.push_back(read_json_file(path, "a bench report"));
  Json merged = merge_shard_reports(shards, o.reports);
  std::cout << merged_tables(merged, o.reports.front());
  return merged;
}

}  // namespace antipode::evaluation
