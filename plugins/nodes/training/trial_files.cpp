// NewTrialLog, SaveTrials and MergeTrials: where a trial log starts, how one scene's trials are
// kept (a record file and a data file), and how the scenes' files join into one training set.
#include <filesystem>
#include <fstream>
#include <map>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "nodes.hpp"
#include "trial_log.hpp"

namespace antipode::training {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat = "antipode-trials 1";

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

/// Writes one scene's trial log: its examples to `data_file` (antipode's training-set format),
/// then its records to `records_file` (JSON naming the data file), each all-or-nothing. The
/// record file, written last, marks the scene done: a run killed in between redoes it.
class SaveTrials final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"SaveTrials",
            bt::NodeCategory::kAction,
            {bt::input_port<TrialLogPtr>("log", "the trial log"),
             bt::input_port<std::string>("records_file", "the records (JSON); empty = nowhere"),
             bt::input_port<std::string>("data_file", "the descriptors, beside the records"),
             bt::input_port<std::uint64_t>("source", "the scene's seed")},
            0,
            0,
            "Writes one scene's trials (records and descriptors), all-or-nothing.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string records_file = get_input<std::string>("records_file");
    if (records_file.empty()) return bt::Status::kSuccess;
    const fs::path data_file = get_input<std::string>("data_file");
    if (data_file.parent_path() != fs::path(records_file).parent_path())
      fail("data_file", "data_file must lie in the folder of records_file");
    const TrialLog& trials = *get_input<TrialLogPtr>("log");
    save_training_set(trials.examples, data_file.string());
    const nlohmann::ordered_json file = {{"format", kFormat},
                                         {"source", get_input<std::uint64_t>("source")},
                                         {"data", data_file.filename().string()},
                                         {"trials", trials.records}};
    write_file_atomically(records_file, [&](const std::string& temporary) {
      std::ofstream out(temporary);
      out << file.dump(1) << "\n";
      if (!out) throw Error("cannot write " + temporary);
    });
    log(std::to_string(trials.records.size()) + " trials written to " + records_file);
    return bt::Status::kSuccess;
  }
};

// The trial record files of `folder` (every *.json there must be one) by source, ascending.
std::map<std::uint64_t, nlohmann::json> record_files(const std::string& folder) {
  std::map<std::uint64_t, nlohmann::json> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    nlohmann::json file = nlohmann::json::parse(in, nullptr, false);
    if (file.is_discarded() || !file.is_object() || file.value("format", "") != kFormat ||
        !file.contains("trials") || !file["trials"].is_array() || !file.contains("source") ||
        !file["source"].is_number_unsigned() || !file.contains("data") || !file["data"].is_string())
      throw Error("trials: '" + entry.path().string() + "' is not a trial record file (" + kFormat +
                  ")");
    const auto source = file["source"].get<std::uint64_t>();
    if (files.count(source) != 0)
      throw Error("trials: two record files of '" + folder + "' are of scene " +
                  std::to_string(source));
    files[source] = std::move(file);
  }
  if (error) throw Error("trials: cannot read the folder '" + folder + "': " + error.message());
  return files;
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
    auto set = std::make_shared<TrainingSet>();
    std::size_t scenes = 0;
    for (const auto& [source, file] : record_files(folder)) {
      append_scene(file, folder, source, labels, *set);
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
        load_training_set((fs::path(folder) / file["data"].get<std::string>()).string());
    const nlohmann::json& records = file["trials"];
    const std::int32_t first_group = out.next_group();
    if (scene.empty()) return;
    if (out.empty()) {
      out.descriptor = scene.descriptor;
      out.geometry = scene.geometry;
    } else if (!SvmDescriptorSpec::of(out.descriptor, out.geometry)
                    .matches(SvmDescriptorSpec::of(scene.descriptor, scene.geometry))) {
      throw Error("trials: scene " + std::to_string(source) +
                  " was described with another descriptor or gripper than the scenes before it; "
                  "merge one gripper's trials at a time");
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

void register_new_trial_log(bt::NodeRegistry& registry) { registry.register_node<NewTrialLog>(); }
void register_save_trials(bt::NodeRegistry& registry) { registry.register_node<SaveTrials>(); }
void register_merge_trials(bt::NodeRegistry& registry) { registry.register_node<MergeTrials>(); }

}  // namespace antipode::training
