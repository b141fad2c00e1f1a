// NewTrialLog, SaveTrials and MergeTrials: where a trial log starts, how one scene's trials are
// kept (a record file and a data file), and how the scenes' files join into one training set.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "nodes.hpp"
#include "trial_log.hpp"

namespace antipode::training {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat = "antipode-trials 1";

std::string padded(std::uint64_t source) {
  char text[32];
  std::snprintf(text, sizeof(text), "%06llu", static_cast<unsigned long long>(source));
  return text;
}

/// Starts an empty trial log.
class NewTrialLog final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"NewTrialLog",
            bt::NodeCategory::kAction,
            {bt::output_port<TrialLogPtr>("log", "an empty trial log")},
            0,
            0,
            "Starts an empty trial log for CollectTrials to fill.",
            {}};
  }

 protected:
  bt::Status tick() override {
    set_output("log", std::make_shared<TrialLog>());
    return bt::Status::kSuccess;
  }
};

/// Writes a trial log as FOLDER/scene-SOURCE.data (its examples, antipode's training-set
/// format) and then FOLDER/scene-SOURCE.json (its records): the record file, written last and
/// all-or-nothing, marks the scene done, so a run killed in between redoes the scene.
class SaveTrials final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"SaveTrials",
            bt::NodeCategory::kAction,
            {bt::input_port<TrialLogPtr>("log", "the trial log"),
             bt::input_port<std::string>("folder", "where to write it; empty = nowhere"),
             bt::input_port<std::uint64_t>("source", "the scene's seed, which names the files")},
            0,
            0,
            "Writes one scene's trials (records and descriptors), all-or-nothing.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string folder = get_input<std::string>("folder");
    if (folder.empty()) return bt::Status::kSuccess;
    const TrialLog& trials = *get_input<TrialLogPtr>("log");
    const std::uint64_t source = get_input<std::uint64_t>("source");
    const fs::path dir(folder);
    save_training_set(trials.examples, (dir / trial_data_name(source)).string());
    const nlohmann::ordered_json file = {
        {"format", kFormat}, {"source", source}, {"trials", trials.records}};
    write_file_atomically((dir / trial_records_name(source)).string(), [&](const std::string& t) {
      std::ofstream out(t);
      out << file.dump(1) << "\n";
      if (!out) throw Error("cannot write " + t);
    });
    log(std::to_string(trials.records.size()) + " trials written to " + folder);
    return bt::Status::kSuccess;
  }
};

// The scene record files of `folder` by source, in ascending order.
std::map<std::uint64_t, fs::path> record_files(const std::string& folder) {
  std::map<std::uint64_t, fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    unsigned long long source = 0;
    char tail[8] = {};
    if (std::sscanf(name.c_str(), "scene-%llu.%7s", &source, tail) == 2 &&
        std::string(tail) == "json" && name == trial_records_name(source))
      files[source] = entry.path();
  }
  if (error) throw Error("trials: cannot read the folder '" + folder + "': " + error.message());
  return files;
}

nlohmann::json read_records(const fs::path& path) {
  std::ifstream in(path);
  nlohmann::json file = nlohmann::json::parse(in, nullptr, false);
  if (file.is_discarded() || !file.is_object() || file.value("format", "") != kFormat ||
      !file.contains("trials") || !file["trials"].is_array())
    throw Error("trials: '" + path.string() + "' is not a trial record file (" + kFormat + ")");
  return file;
}

// +1 / -1 for `record` under `labels`, 0 for no label (an indeterminate antipodal check).
int label_of(const nlohmann::json& record, const std::string& labels) {
  if (labels == "outcome") return record.at("held").get<bool>() ? 1 : -1;
  const std::string antipodal = record.at("antipodal").get<std::string>();
  return antipodal == "positive" ? 1 : antipodal == "negative" ? -1 : 0;
}

/// Joins the scenes' trial files of a folder (SaveTrials) into one training set, scenes in
/// ascending seed order, every trial's examples in one group of their own: the same set
/// whatever processes or shards made the files. `labels` chooses the label source: `outcome`
/// (the grasp held) or `antipodal` (the near-antipodal check; indeterminate trials give no
/// example), so that both models train on the same hands.
class MergeTrials final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"MergeTrials",
            bt::NodeCategory::kAction,
            {bt::input_port<std::string>("folder", "a folder of trial files (SaveTrials)"),
             bt::input_port<std::string>("labels", std::string("outcome"), "outcome or antipodal"),
             bt::input_port<std::vector<int>>("sources", std::vector<int>{0, -1},
                                              "keep scenes whose seed is in [first, last] "
                                              "(-1: no bound)"),
             bt::output_port<TrainingSetPtr>("dataset", "the examples")},
            0,
            0,
            "Joins the trial files of a folder into one training set.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string folder = get_input<std::string>("folder");
    const std::string labels = get_input<std::string>("labels");
    if (labels != "outcome" && labels != "antipodal")
      fail("labels", "labels must be outcome or antipodal, got '" + labels + "'");
    const auto bounds = get_input<std::vector<int>>("sources");
    if (bounds.size() != 2) fail("sources", "sources must be [first, last]");
    auto set = std::make_shared<TrainingSet>();
    std::size_t scenes = 0;
    for (const auto& [source, path] : record_files(folder)) {
      if ((bounds[0] >= 0 && source < std::uint64_t(bounds[0])) ||
          (bounds[1] >= 0 && source > std::uint64_t(bounds[1])))
        continue;
      append_scene(read_records(path), folder, source, labels, *set);
      ++scenes;
    }
    if (set->empty()) fail("folder", "trials: no example in the trial files of '" + folder + "'");
    log(std::to_string(set->size()) + " examples (" + std::to_string(set->positives()) +
        " positive) from " + std::to_string(scenes) + " scenes, labels: " + labels);
    set_output("dataset", TrainingSetPtr(std::move(set)));
    return bt::Status::kSuccess;
  }

 private:
  static void append_scene(const nlohmann::json& file, const std::string& folder,
                           std::uint64_t source, const std::string& labels, TrainingSet& out) {
    const TrainingSet scene =
        load_training_set((fs::path(folder) / trial_data_name(source)).string());
    const nlohmann::json& records = file["trials"];
    const std::int32_t first_group = out.next_group();
    if (out.empty() && !scene.empty()) {
      out.descriptor = scene.descriptor;
      out.geometry = scene.geometry;
    }
    for (std::size_t e = 0; e < scene.size(); ++e) {
      const auto group = std::size_t(scene.groups[e]);
      if (group >= records.size())
        throw Error("trials: scene " + std::to_string(source) + " has an example of trial " +
                    std::to_string(group) + " but " + std::to_string(records.size()) + " records");
      const int label = label_of(records[group], labels);
      if (label == 0) continue;
      const std::vector<float> row(scene.row(e), scene.row(e) + scene.dimension);
      out.add(row, label > 0, first_group + scene.groups[e], scene.sources[e]);
    }
  }
};

}  // namespace

std::string trial_records_name(std::uint64_t source) { return "scene-" + padded(source) + ".json"; }
std::string trial_data_name(std::uint64_t source) { return "scene-" + padded(source) + ".data"; }

void register_new_trial_log(bt::NodeRegistry& registry) { registry.register_node<NewTrialLog>(); }
void register_save_trials(bt::NodeRegistry& registry) { registry.register_node<SaveTrials>(); }
void register_merge_trials(bt::NodeRegistry& registry) { registry.register_node<MergeTrials>(); }

}  // namespace antipode::training
