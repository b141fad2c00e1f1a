// `antipode bench clutter` as a user runs it: seeded clear-the-box runs of
// trees/clear_box.yaml with a floor on what they remove, the same results for any number of
// processes, and one-line errors for bad options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <vector>

#include "support/bench_command.hpp"

namespace {

using antipode::testing::CommandResult;
using antipode::testing::without_seconds;

class ClutterBenchTest : public antipode::testing::BenchCommandTest {
 protected:
  ClutterBenchTest() : BenchCommandTest("clutter") {}

  // The markdown `antipode report` writes for the bench report `r` (one crafted by a test).
  std::string report_markdown(const nlohmann::json& r) const {
    std::ofstream(file("crafted.json")) << r.dump();
    const CommandResult made =
        antipode("report " + file("crafted.json") + " --out " + file("crafted.md"));
    EXPECT_EQ(made.exit_code, 0) << made.out;
    std::ifstream in(file("crafted.md"));
    return std::string((std::istreambuf_iterator<char>(in)), {});
  }
};

// Two runs of four objects: every run removes at least one object, and the report has the
// summary keys docs/cli.md promises.
TEST_F(ClutterBenchTest, EveryRunRemovesObjects) {
  const auto r = report("--runs 2 --objects-per-run 4 --jobs 2", "two.json");
  ASSERT_TRUE(r.contains("summary")) << r.dump();
  const auto& s = r["summary"];
  for (const char* key : {"attempts", "successes", "objects", "removed"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["errors"], 0);
  ASSERT_EQ(r["run_records"].size(), 2u);
  int left_graspable = 0;
  for (const auto& run : r["run_records"]) {
    EXPECT_GE(run["removed"].get<int>(), 1) << run.dump(1);
    EXPECT_LE(run["cycles"].size(), 2u * run["objects"].get<std::size_t>());
    // The simulated cell names what was left and how wide each object lay.
    ASSERT_EQ(run["left_objects"].size(), run["left"].get<std::size_t>()) << run.dump(1);
    int fits = 0;
    for (const auto& object : run["left_objects"]) {
      EXPECT_FALSE(object["name"].get<std::string>().empty());
      const double width = object["narrowest_horizontal_m"];
      EXPECT_GT(width, 0.005) << object.dump();
      EXPECT_LT(width, 0.3) << object.dump();
      fits += width >= 0.03 && width <= 0.07;
    }
    EXPECT_EQ(run["left_graspable"], fits);
    left_graspable += fits;
    for (const auto& cycle : run["cycles"]) {
      EXPECT_TRUE(cycle.contains("reason")) << cycle.dump();
      // The cell counts what is left: a success takes the held object out, nothing comes back.
      const int before = cycle["objects_before"], after = cycle["objects_after"];
      if (cycle["outcome"] == "success") {
        EXPECT_TRUE(cycle.contains("record")) << cycle.dump();
        EXPECT_LE(after, before - 1) << cycle.dump();
      } else {
        EXPECT_LE(after, before) << cycle.dump();
      }
    }
  }
  EXPECT_LE(s["successes"].get<int>(), s["attempts"].get<int>());
  // Every attempt is counted once by the object its grasp was planned around: the first the
  // cell found between the planned fingers, most tried first.
  int by_object_attempts = 0, by_object_successes = 0, previous = 1 << 30;
  for (const auto& o : s["by_object"]) {
    const int attempts = o["attempts"], successes = o["successes"];
    int failures = 0;
    for (const auto& [reason, count] : o["reasons"].items()) failures += count.get<int>();
    EXPECT_EQ(successes + failures, attempts) << o.dump();
    EXPECT_LE(attempts, previous) << s["by_object"].dump();
    previous = attempts;
    by_object_attempts += attempts;
    by_object_successes += successes;
  }
  EXPECT_EQ(by_object_attempts, s["attempts"].get<int>()) << s["by_object"].dump();
  EXPECT_EQ(by_object_successes, s["successes"].get<int>());
  // Each object's counts are those of the cycles whose record names it first.
  std::map<std::string, std::pair<int, int>> expected;  // attempts, successes
  for (const auto& run : r["run_records"])
    for (const auto& cycle : run["cycles"]) {
      if (!cycle.contains("record") || cycle["record"]["between_fingers_at_detection"].empty())
        continue;
      auto& [attempts, successes] =
          expected[cycle["record"]["between_fingers_at_detection"][0].get<std::string>()];
      ++attempts;
      successes += cycle["outcome"] == "success";
    }
  ASSERT_FALSE(expected.empty());
  for (const auto& [name, counts] : expected) {
    bool found = false;
    for (const auto& o : s["by_object"]) {
      if (o["name"] != name) continue;
      found = true;
      EXPECT_EQ(o["attempts"].get<int>(), counts.first) << name;
      EXPECT_EQ(o["successes"].get<int>(), counts.second) << name;
    }
    EXPECT_TRUE(found) << name << " is not in " << s["by_object"].dump();
  }
  EXPECT_EQ(s["left_graspable"], left_graspable);
  EXPECT_EQ(s["left"].get<int>(),
            s["objects"].get<int>() - s["removed"].get<int>() - s["lost"].get<int>());
  const int removed = s["removed"];
  EXPECT_DOUBLE_EQ(s["removed_of_graspable_rate"]["rate"].get<double>(),
                   double(removed) / (removed + left_graspable));
  // Intervals that resample whole runs hold the pooled rate: each draw's rate lies between
  // the runs' own rates, and so do both bounds.
  double lowest = 1.0, highest = 0.0;
  for (const auto& run : r["run_records"]) {
    const double rate = run["removed"].get<double>() / run["objects"].get<double>();
    lowest = std::min(lowest, rate), highest = std::max(highest, rate);
  }
  const auto& runs_ci = s["removed_rate"]["ci95_runs"];
  ASSERT_EQ(runs_ci.size(), 2u) << s.dump(1);
  EXPECT_DOUBLE_EQ(runs_ci[0].get<double>(), lowest);  // both draws of the lower run
  EXPECT_DOUBLE_EQ(runs_ci[1].get<double>(), highest);
  EXPECT_TRUE(s["success_rate"].contains("ci95_runs")) << s.dump(1);
}

TEST_F(ClutterBenchTest, TheSameResultsForAnyNumberOfProcesses) {
  const std::string args = "--runs 2 --objects-per-run 3 --seed 7";
  const auto one = report(args + " --jobs 1", "one.json");
  const auto two = report(args + " --jobs 2", "two.json");
  ASSERT_EQ(one["run_records"].size(), 2u);
  ASSERT_EQ(two["run_records"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& a = one["run_records"][i]["cycles"];
    const auto& b = two["run_records"][i]["cycles"];
    ASSERT_EQ(a.size(), b.size()) << "run " << i;
    for (std::size_t c = 0; c < a.size(); ++c) {
      EXPECT_EQ(a[c]["outcome"], b[c]["outcome"]) << "run " << i << " cycle " << c;
      EXPECT_EQ(a[c].value("hand", nlohmann::json()), b[c].value("hand", nlohmann::json()));
    }
  }
  EXPECT_EQ(one["summary"]["successes"], two["summary"]["successes"]);
}

// Three runs in two shards, merged in either order, give the report of the whole bench (but
// for the seconds it took).
TEST_F(ClutterBenchTest, ShardsMergedGiveTheWholeBenchsReport) {
  const std::string args = "--runs 3 --objects-per-run 2 --seed 7";
  const auto whole = report(args, "whole.json");
  const auto second = report(args + " --shard 2/2", "2.json");
  ASSERT_EQ(second["run_records"].size(), 1u);  // runs 1, 3 and 2
  EXPECT_EQ(second["shard"]["index"], 2);
  report(args + " --shard 1/2", "1.json");
  const CommandResult merge = antipode("bench merge " + file("2.json") + " " + file("1.json") +
                                       " --report " + file("merged.json"));
  ASSERT_EQ(merge.exit_code, 0) << merge.out;
  std::ifstream in(file("merged.json"));
  const auto merged = nlohmann::json::parse(in);
  EXPECT_EQ(without_seconds(merged["summary"]), without_seconds(whole["summary"]));
  EXPECT_EQ(without_seconds(merged["run_records"]), without_seconds(whole["run_records"]));
  EXPECT_EQ(merged["shards"], 2);
  EXPECT_FALSE(merged.contains("shard"));
  // The console shows the same tallies as the whole bench's.
  EXPECT_NE(merge.out.find("grasp success " + whole["summary"]["successes"].dump() + " / " +
                           whole["summary"]["attempts"].dump()),
            std::string::npos)
      << merge.out;
}

// antipode report turns a bench report into a markdown section with the figures of its
// summary and a PNG chart of the runs.
TEST_F(ClutterBenchTest, ReportWritesMarkdownAndAChart) {
  const auto r = report("--runs 2 --objects-per-run 2 --seed 3", "clutter-small.json");
  const CommandResult made =
      antipode("report " + file("clutter-small.json") + " --out " + file("results.md"));
  ASSERT_EQ(made.exit_code, 0) << made.out;
  std::ifstream in(file("results.md"));
  const std::string markdown((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(markdown.find("## Dense clutter: procedural shapes"), std::string::npos) << markdown;
  const auto& s = r["summary"];
  const std::string counts = "(" + s["successes"].dump() + "/" + s["attempts"].dump() + ")";
  EXPECT_NE(markdown.find(counts), std::string::npos) << counts << "\n" << markdown;
  EXPECT_NE(markdown.find("--runs 2 --objects-per-run 2 --seed 3"), std::string::npos);
  EXPECT_NE(markdown.find("![per run](images/clutter-small-runs.png)"), std::string::npos);
  EXPECT_NE(markdown.find("Removed of the objects it could hold: "), std::string::npos);
  EXPECT_NE(markdown.find("| left (narrowest horizontal extent) |"), std::string::npos);
  EXPECT_NE(markdown.find("| object | attempts | succeeded | failures |"), std::string::npos);
  for (const auto& o : s["by_object"])
    EXPECT_NE(markdown.find("| " + o["name"].get<std::string>() + " | " + o["attempts"].dump() +
                            " | " + o["successes"].dump() + " | "),
              std::string::npos)
        << o.dump() << "\n"
        << markdown;
  std::ifstream png(file("images/clutter-small-runs.png"), std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");

  const auto report_error = [&](const std::string& arguments, const std::string& words) {
    const CommandResult e = antipode("report " + arguments);
    EXPECT_EQ(e.exit_code, 2) << arguments << ": " << e.out;
    EXPECT_NE(e.out.find("antipode: error: "), std::string::npos) << e.out;
    EXPECT_NE(e.out.find(words), std::string::npos) << arguments << ": " << e.out;
  };
  report_error(file("none.json") + " --out " + file("x.md"), "cannot read a bench report");
  report_error("CMakeLists.txt --out " + file("x.md"), "not JSON (");
  report_error("robots/baxter/baxter.urdf --out " + file("x.md"), "not JSON (");
  // A report nested a million levels deep is refused while it is read.
  std::ofstream(file("deep.json"))
      << "{\"bench\": \"clutter\", \"runs\": " << std::string(1000000, '[')
      << std::string(1000000, ']') << "}";
  report_error(file("deep.json") + " --out " + file("x.md"), "nested deeper than 100 levels");
  report_error(
      file("clutter-small.json") + " --out " + file("x.md") + " --notes " + file("none.md"),
      "cannot read the notes");
  // A report with an entry missing (a hand-edited or truncated file) names the entry.
  auto broken = r;
  broken["run_records"][0].erase("attempts");
  std::ofstream(file("broken.json")) << broken.dump();
  report_error(file("broken.json") + " --out " + file("x.md"), "key 'attempts' not found");
  EXPECT_FALSE(std::filesystem::exists(file("x.md")));
  // Nothing is left behind: no chart of the good report before the broken one, no folder.
  report_error(file("clutter-small.json") + " " + file("broken.json") + " --out " + file("x.md") +
                   " --plots " + file("bad/charts"),
               "key 'attempts' not found");
  EXPECT_FALSE(std::filesystem::exists(file("bad/charts")));
  // A --plots folder that cannot be made is one clear error.
  report_error(file("clutter-small.json") + " --out " + file("y.md") + " --plots " +
                   file("clutter-small.json") + "/charts",
               "--plots: cannot write the charts to");
  EXPECT_FALSE(std::filesystem::exists(file("y.md")));
}

// A run whose classifier is swapped by `--set` is reported apart, named as the paper names
// its variants, with the option in its command.
TEST_F(ClutterBenchTest, ReportNamesTheClassifierARunSwappedIn) {
  const std::string nc = "--set classifier.plugin=passthrough_classifier";
  report("--runs 1 --objects-per-run 2 --seed 3 " + nc, "clutter-nc.json");
  const auto svm = report("--runs 1 --objects-per-run 2 --seed 3", "clutter-svm.json");
  const CommandResult made = antipode("report " + file("clutter-svm.json") + " " +
                                      file("clutter-nc.json") + " --out " + file("nc.md"));
  ASSERT_EQ(made.exit_code, 0) << made.out;
  std::ifstream in(file("nc.md"));
  const std::string markdown((std::istreambuf_iterator<char>(in)), {});
  // Baxter's robot file names a grasp-success model, which the tree's default `labels`
  // (outcome_or_antipodal) chooses: the report records both and says so.
  EXPECT_EQ(svm.value("labels", ""), "outcome_or_antipodal") << svm.dump();
  EXPECT_EQ(std::filesystem::path(svm["robot"].value("success_model", "")).filename(),
            "hog_svm_outcome.model");
  const std::string outcome_title =
      "## Dense clutter: procedural shapes, ranked by success probability "
      "(`hog_svm_outcome.model`)\n";
  EXPECT_NE(markdown.find(outcome_title), std::string::npos) << markdown;
  // The paper's antipodal-labelled model, chosen by `labels` or by a robot file without a
  // grasp-success model, gets the plain title.
  auto antipodal = svm;
  antipodal["overrides"] = {"labels=antipodal"};
  antipodal["labels"] = "antipodal";  // as the bench records the override
  EXPECT_NE(report_markdown(antipodal).find("## Dense clutter: procedural shapes\n"),
            std::string::npos);
  // A report from before `labels` was recorded: its last override decides.
  antipodal.erase("labels");
  EXPECT_NE(report_markdown(antipodal).find("## Dense clutter: procedural shapes\n"),
            std::string::npos);
  antipodal["overrides"] = {"labels=antipodal", "labels=outcome"};
  EXPECT_NE(report_markdown(antipodal).find(outcome_title), std::string::npos);
  auto no_success_model = svm;
  no_success_model["robot"].erase("success_model");
  EXPECT_NE(report_markdown(no_success_model).find("## Dense clutter: procedural shapes\n"),
            std::string::npos);
  EXPECT_NE(markdown.find("## Dense clutter: procedural shapes, no classifier (NC)\n"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("--seed 3 " + nc + " --jobs 1 --report clutter-nc.json"),
            std::string::npos)
      << markdown;
}

// The report's between-runs intervals resample whole runs: two runs, one that succeeded in
// every attempt and one in none, give draws of both (rate 1), neither (0) and one of each
// (0.5), so the interval spans [0, 100]; two equal runs give their common rate.
TEST_F(ClutterBenchTest, ReportResamplesWholeRunsForItsBetweenRunsIntervals) {
  auto r = report("--runs 2 --objects-per-run 2 --seed 3", "runs.json");
  ASSERT_EQ(r["run_records"].size(), 2u) << r.dump();
  const auto between_runs = [&](int first_successes, int second_successes) {
    r["run_records"][0]["attempts"] = 10;
    r["run_records"][0]["successes"] = first_successes;
    r["run_records"][1]["attempts"] = 10;
    r["run_records"][1]["successes"] = second_successes;
    const std::string markdown = report_markdown(r);
    const std::size_t at = markdown.find("Between runs (the 2 runs resampled whole");
    EXPECT_NE(at, std::string::npos) << markdown;
    const std::size_t end = markdown.find(" for grasp success", at);
    return at == std::string::npos || end == std::string::npos
               ? std::string()
               : markdown.substr(markdown.rfind('[', end), end - markdown.rfind('[', end));
  };
  EXPECT_EQ(between_runs(10, 0), "[0.0, 100.0]");
  EXPECT_EQ(between_runs(5, 5), "[50.0, 50.0]");
  EXPECT_EQ(between_runs(7, 9), "[70.0, 90.0]");
  // A run that ended in an error is left out, as the summary leaves it out.
  r["run_records"].push_back({{"seed", 5}, {"error", "the cell failed"}, {"wall_s", 1.0}});
  EXPECT_EQ(between_runs(7, 9), "[70.0, 90.0]");

  // One run: no between-runs line.
  report("--runs 1 --objects-per-run 2 --seed 3", "one_run.json");
  ASSERT_EQ(antipode("report " + file("one_run.json") + " --out " + file("one.md")).exit_code, 0);
  std::ifstream in(file("one.md"));
  const std::string markdown((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(markdown.find("Between runs"), std::string::npos) << markdown;
}

// The report summarises the run records as the bench does: the median of an even number of
// runs is the mean of the middle two, and a run on a cell that cannot count its objects
// (objects -1) adds nothing to the removal figure.
TEST_F(ClutterBenchTest, ReportMediansAndRemovalFollowTheRunRecords) {
  auto r = report("--runs 2 --objects-per-run 2 --seed 3", "runs.json");
  ASSERT_EQ(r["run_records"].size(), 2u) << r.dump();
  r["run_records"][0]["wall_s"] = 10.0;
  r["run_records"][1]["wall_s"] = 21.0;
  r["run_records"][0]["objects"] = -1;
  const int removed = r["run_records"][1]["removed"], objects = r["run_records"][1]["objects"];
  const std::string markdown = report_markdown(r);
  EXPECT_NE(markdown.find("median run 15.5 s"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("(" + std::to_string(removed) + "/" + std::to_string(objects) + ") |"),
            std::string::npos)
      << markdown;
}

TEST_F(ClutterBenchTest, MergeRefusesShardsThatAreNotOneWholeBench) {
  const std::string args = "--runs 2 --objects-per-run 1";
  report(args + " --seed 7 --shard 1/2", "1.json");
  report(args + " --seed 8 --shard 2/2", "2_other.json");
  report(args + " --seed 7", "whole.json");
  const auto merge_error = [&](const std::string& files, const std::string& words) {
    const CommandResult r = antipode("bench merge " + files);
    EXPECT_EQ(r.exit_code, 2) << files << ": " << r.out;
    EXPECT_NE(r.out.find("antipode: error: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(words), std::string::npos) << files << ": " << r.out;
  };
  merge_error(file("1.json") + " " + file("2_other.json"), "entry \"seed\" differs");
  merge_error(file("1.json"), "shards 2 of 2 are missing");
  merge_error(file("1.json") + " " + file("1.json"), "shard 1 given twice");
  merge_error(file("whole.json"), "not a shard's report");
  merge_error(file("none.json"), "cannot read a bench report");
  std::ofstream(file("deep.json")) << std::string(1000000, '[') << std::string(1000000, ']');
  merge_error(file("deep.json"), "deep.json: nested deeper than 100 levels");
  // A shard whose record lacks an entry (a hand-edited or truncated file) is bad input.
  auto second = report(args + " --seed 7 --shard 2/2", "2.json");
  second["run_records"][0].erase("attempts");
  std::ofstream(file("2_broken.json")) << second.dump();
  merge_error(file("1.json") + " " + file("2_broken.json") + " --report " + file("m.json"),
              "a shard's record lacks an entry or has a malformed one");
  EXPECT_FALSE(std::filesystem::exists(file("m.json")));
  // Entries of the wrong type are named, never an internal error.
  const auto with = [&](const std::string& key, const nlohmann::json& value) {
    auto shard = second;
    shard["run_records"][0]["attempts"] = 1;
    shard[key] = value;
    std::ofstream(file("2_" + key + ".json")) << shard.dump();
    return file("1.json") + " " + file("2_" + key + ".json");
  };
  merge_error(with("wall_s", "12 s"), "\"wall_s\" is \"12 s\", not a number of seconds");
  merge_error(with("protocol", 3), "entry \"protocol\" differs");
  auto first = nlohmann::json::parse(std::ifstream(file("1.json")));
  first["protocol"] = 3;
  std::ofstream(file("1_protocol.json")) << first.dump();
  with("protocol", 3);  // writes 2_protocol.json
  merge_error(file("1_protocol.json") + " " + file("2_protocol.json"),
              "the report's \"protocol\" is 3, not one of");
  // A shard count no bench makes is refused before anything is sized by it.
  auto huge = first;
  huge["shard"]["count"] = 2147483647;
  std::ofstream(file("1_huge.json")) << huge.dump();
  merge_error(file("1_huge.json"),
              "\"shard\": \"count\" is 2147483647, not a whole number in 1..10000");
}

// VGN's protocol: rounds of five objects from one noisy view; a round ends when the scene is
// empty, after two consecutive failed attempts, or when a cycle finds no grasp.
TEST_F(ClutterBenchTest, VgnRoundsFollowTheirRules) {
  const auto r = report("--protocol vgn-packed --runs 2 --jobs 2", "vgn.json");
  EXPECT_EQ(r["protocol"], "vgn-packed");
  EXPECT_EQ(r["objects_per_run"], 5);
  EXPECT_EQ(r["tree"], "trees/vgn_round.yaml");
  ASSERT_EQ(r["run_records"].size(), 2u);
  int successes = 0;
  for (const auto& run : r["run_records"]) {
    ASSERT_FALSE(run.contains("error")) << run.dump();
    EXPECT_LE(run["objects"].get<int>(), 5);
    successes += run["successes"].get<int>();
    const auto& cycles = run["cycles"];
    int failed_in_a_row = 0;
    for (std::size_t c = 0; c < cycles.size(); ++c) {
      const bool last = c + 1 == cycles.size();
      if (cycles[c]["outcome"] == "no grasp found") {
        EXPECT_TRUE(last) << run.dump(1);
      }
      failed_in_a_row = cycles[c]["outcome"] == "success" ? 0 : failed_in_a_row + 1;
      if (!last) {
        EXPECT_LT(failed_in_a_row, 2) << run.dump(1);
      }
    }
  }
  EXPECT_GE(successes, 1) << r["summary"].dump(1);
}

// --gripper: the sampler searches for the file's gripper (the model trained for it would
// refuse Baxter's hands), the cell executes it, and the objects left count as holdable by
// its apertures, rounded inwards to whole centimetres (Baxter's 2.9-7.2 cm: 3-7 cm).
TEST_F(ClutterBenchTest, AGripperFileSetsTheHandAndWhatCountsAsHoldable) {
  const auto r = report(
      "--protocol vgn-pile --runs 2 --seed 2000 --jobs 2 --gripper "
      "robots/grippers/parallel_8cm.yaml --set "
      "classifier.model=models/hog_svm_8cm.model",
      "eight.json");
  EXPECT_EQ(r["gripper"]["name"], "8 cm gripper");
  EXPECT_EQ(r["summary"]["errors"], 0) << r["summary"].dump(1);
  EXPECT_GE(r["summary"]["successes"].get<int>(), 1) << r["summary"].dump(1);
  EXPECT_EQ(r["summary"]["graspable_width_m"], nlohmann::json::parse("[0.01, 0.08]"));
  const auto baxter = report("--runs 1 --objects-per-run 1", "baxter.json");
  EXPECT_EQ(baxter["summary"]["graspable_width_m"], nlohmann::json::parse("[0.03, 0.07]"));
  EXPECT_FALSE(baxter.contains("gripper"));
}

// --pictures draws every attempt the cell executed and that failed, named by seed and cycle,
// and nothing else.
TEST_F(ClutterBenchTest, PicturesShowEveryFailedAttempt) {
  const std::string folder = file("pictures");
  const auto r = report("--runs 1 --seed 2002 --pictures " + folder, "pictured.json");
  ASSERT_EQ(r["run_records"].size(), 1u);
  std::set<std::string> expected;
  const auto& cycles = r["run_records"][0]["cycles"];
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    if (!cycles[c].contains("record") || cycles[c]["outcome"] == "success") continue;
    char name[64];
    std::snprintf(name, sizeof name, "seed-2002-cycle-%02zu.png", c + 1);
    expected.insert(name);
  }
  std::set<std::string> drawn;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    drawn.insert(entry.path().filename().string());
  EXPECT_EQ(drawn, expected);
  EXPECT_FALSE(expected.empty()) << "seed 2002 no longer fails an attempt: pick another seed";
}

// --selections writes, for every cycle that chose a grasp, what the selection kept - in rank
// order, the executed grasp among them - and what it dropped, with the reasons; for every
// cycle the cloud it captured and where the objects lay; and for every cycle that executed a
// grasp the arm's planned path to it. The run is the same without.
TEST_F(ClutterBenchTest, SelectionsAreWrittenForEveryAttempt) {
  const std::string folder = file("selections");
  const std::string args = "--runs 1 --objects-per-run 3 --seed 2001";
  const auto r = report(args + " --selections " + folder, "selected.json");
  const auto plain = report(args, "plain.json");
  EXPECT_EQ(r["run_records"][0]["summary"], plain["run_records"][0]["summary"]);
  const auto& cycles = r["run_records"][0]["cycles"];
  std::set<std::string> expected;
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    char stem[64];
    std::snprintf(stem, sizeof stem, "seed-2001-cycle-%02zu", c + 1);
    expected.insert(std::string(stem) + ".pcd");
    expected.insert(std::string(stem) + "-objects.json");
    if (cycles[c].contains("record")) expected.insert(std::string(stem) + "-path.json");  // planned
    const std::string name = std::string(stem) + ".json";
    std::ifstream in(folder + "/" + name);
    if (cycles[c]["outcome"] == "no grasp found" ||
        cycles[c]["outcome"] == "no grasp predicted to hold") {
      // When the selector ran and kept nothing, its selection says why: every hand rejected.
      if (!in) continue;
      expected.insert(name);
      const auto hands = nlohmann::json::parse(in).at("hands");
      ASSERT_FALSE(hands.empty()) << name;
      EXPECT_TRUE(std::all_of(hands.begin(), hands.end(), [](const auto& hand) {
        return hand.contains("rejection");
      })) << name;
      continue;
    }
    expected.insert(name);
    ASSERT_TRUE(in) << name;
    const auto selection = nlohmann::json::parse(in);
    const auto& hands = selection.at("hands");
    ASSERT_FALSE(hands.empty()) << name;
    EXPECT_FALSE(hands.front().contains("rejection")) << name;  // the kept grasps first
    // The executed grasp is one of them (the first the arm reached).
    const bool executed_kept = std::any_of(hands.begin(), hands.end(), [&](const auto& hand) {
      return !hand.contains("rejection") && cycles[c].contains("hand") &&
             hand.at("position_m") == cycles[c]["hand"]["position_m"];
    });
    EXPECT_TRUE(executed_kept || !cycles[c].contains("hand")) << name;
    const bool some_dropped = std::any_of(
        hands.begin(), hands.end(), [](const auto& hand) { return hand.contains("rejection"); });
    EXPECT_TRUE(some_dropped) << name;
  }
  std::set<std::string> written;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    written.insert(entry.path().filename().string());
  EXPECT_EQ(written, expected);
  EXPECT_FALSE(expected.empty());
}

// A cycle whose selection keeps no grasp writes it too, so that --selections shows why the
// cycle found none: with clusters of at least 1,000 hands required, every cycle's selection
// rejects every hand, and the run ends after three such cycles.
TEST_F(ClutterBenchTest, ASelectionThatKeepsNoGraspIsWrittenWithEveryReason) {
  const std::string folder = file("none-kept");
  const auto r = report(
      "--runs 1 --objects-per-run 3 --seed 2001 --set selector.min_cluster_size=1000"
      " --selections " +
          folder,
      "none-kept.json");
  const auto& cycles = r["run_records"][0]["cycles"];
  ASSERT_EQ(cycles.size(), 3u) << r["run_records"][0]["summary"];
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    EXPECT_EQ(cycles[c]["outcome"], "no grasp found");
    char name[64];
    std::snprintf(name, sizeof name, "seed-2001-cycle-%02zu.json", c + 1);
    std::ifstream in(folder + "/" + name);
    ASSERT_TRUE(in) << name;
    const auto hands = nlohmann::json::parse(in).at("hands");
    ASSERT_FALSE(hands.empty()) << name;
    std::size_t too_small = 0;
    for (const auto& hand : hands) {
      ASSERT_TRUE(hand.contains("rejection")) << name;
      too_small += hand["rejection"] == "cluster too small";
    }
    EXPECT_GT(too_small, 0u) << name;
  }
}

// Soak, short form: one process runs twelve clear-the-box episodes back to back; every one
// ends with a recorded outcome, and the process holds no more memory after the last ones than
// after the first ones (the resident size after each episode's tree is gone, freed memory
// returned; it varies by some 6% from episode to episode, so the windows' largest values are
// compared).
TEST_F(ClutterBenchTest, ManyEpisodesInOneProcessNeitherFailNorGrow) {
  const auto r = report("--runs 12 --objects-per-run 3 --seed 3000 --jobs 1", "soak.json");
  ASSERT_EQ(r["run_records"].size(), 12u);
  std::vector<double> rss;
  for (const auto& run : r["run_records"]) {
    EXPECT_FALSE(run.contains("error")) << run.dump();
    EXPECT_NE(run.value("stop", ""), "") << run.dump();
    rss.push_back(run["rss_mb"].get<double>());
  }
  const double early = *std::max_element(rss.begin() + 1, rss.begin() + 5);
  const double late = *std::max_element(rss.end() - 4, rss.end());
  EXPECT_GT(early, 10.0);
  EXPECT_LT(late, 1.10 * early) << "resident MB per episode: " << r["run_records"].dump();
}

TEST_F(ClutterBenchTest, BadOptionsAreOneLineErrors) {
  expect_error("--protocol vgn", "unknown protocol 'vgn' (paper, vgn-pile, vgn-packed)");
  expect_error("--shard 3/2 --report x.json", "--shard: '3/2' is not i/n");
  expect_error("--shard 1/0 --report x.json", "is not i/n");
  expect_error("--shard 1/2", "needs --report");
  expect_error("--runs 0", "--runs must be in 1..100000");
  expect_error("--replicates 101", "--replicates must be in 1..100");
  expect_error("--objects-per-run 101", "--objects-per-run: Value 101 not in range 1 to 100");
  expect_error("--objects-per-run 0", "--objects-per-run: Value 0 not in range 1 to 100");
  expect_error("--noise -1", "--noise: Value -1 not in range");
  expect_error("--tree trees/detect.yaml", "has no component 'cell'");
  expect_error("--report /no/such/folder/r.json", "directory '/no/such/folder' does not exist");
  expect_error("--jobs 0", "--jobs must be in 1..64");
  expect_error("--objects /no/such/folder", "neither 'procedural' nor a folder");
  expect_error("--tree trees/none.yaml", "no tree file");
  expect_error("--set cell.object_count=0", "'object_count' must be in [1, 100]");
  expect_error("--gripper robots/grippers/none.yaml",
               "gripper file 'robots/grippers/none.yaml': no such file");
  // A tree that draws nothing is an error, not a folder left empty.
  expect_error("--protocol vgn-pile --pictures " + file("vgn-pictures"),
               "--pictures: the tree 'trees/vgn_round.yaml' draws no pictures");
  EXPECT_FALSE(std::filesystem::exists(file("vgn-pictures")));
  expect_error("--protocol vgn-pile --selections " + file("vgn-selections"),
               "--selections: the tree 'trees/vgn_round.yaml' writes no selections");
  EXPECT_FALSE(std::filesystem::exists(file("vgn-selections")));
  expect_error("--selections CMakeLists.txt", "--selections: 'CMakeLists.txt' is not a folder");
  expect_error("--pictures CMakeLists.txt/pictures",
               "--pictures: cannot make the folder 'CMakeLists.txt/pictures' (Not a directory)");
}

}  // namespace
