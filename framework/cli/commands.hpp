#pragma once
// The `antipode` subcommands. Each returns the process exit code (see exit_codes.hpp) and
// throws antipode::Error for bad input, which main() prints as one line.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace antipode::cli {

/// What every command that runs a tree takes from --set, --seed and -v (or run's -q); main.cpp
/// declares these options once, for all of them.
struct TreeRunSettings {
  std::vector<std::string> set;  ///< "key=value" overrides, applied after the command's own
  std::uint64_t seed = 0;        ///< seed of every random stream
  bool verbose = false;          ///< per-node console trace
  std::string main_tree;         ///< the tree to run instead of the file's `main` ("": main)
};

struct RunOptions {
  std::string tree_path;
  TreeRunSettings settings;  ///< `run` traces every node with -v, as the other commands
  std::string trace_path;    ///< JSON-lines trace file; "" for none
};

struct DetectOptions {
  std::string cloud_path;
  std::string tree_path = "trees/detect.yaml";
  std::string out_path;    ///< grasps JSON; "" for none
  std::string image_path;  ///< PNG picture; "" for none
  TreeRunSettings settings;
  std::string hands_entry = "grasps";  ///< the entry whose hands are summarised
  /// Also print the scene found (support, objects), the hands per stage and per object, and
  /// how many of the grasps lie on objects: the selected ones with --top or --per-object, else
  /// the 12 best.
  bool explain = false;
  std::string camera_pose;  ///< "x y z qw qx qy qz" or an extrinsics file; "" = none
  std::string frame;        ///< the output frame's name ("": base with a camera pose, else sensor)
  int top = 0;              ///< select at most this many grasps (0: no selection unless per_object)
  int per_object = 0;       ///< select at most this many grasps per object (0: no limit)
  std::vector<double> workspace;  ///< xmin ymin zmin xmax ymax zmax, in the output frame
};

/// `antipode train` (trees/train.yaml) and `antipode eval-classifier`
/// (trees/eval_classifier.yaml): trees run with file-name entries filled from the arguments.
struct TrainOptions {
  std::string tree_path = "trees/train.yaml";
  std::string model_path = "models/hog_svm.model";  ///< entry model_file
  std::string dataset_path;  ///< entry dataset_file: keep the examples ("" = don't)
  TreeRunSettings settings;
  bool overwrite = false;  ///< replace a shipped model (models/) at model_path
};

struct EvalOptions {
  std::string tree_path = "trees/eval_classifier.yaml";
  std::string model_path = "models/hog_svm.model";  ///< entry model_file
  std::string report_path;                          ///< entry report_file ("" = none)
  TreeRunSettings settings;
};

struct SceneOptions {
  std::string scene_path;
  std::string tree_path = "trees/scene.yaml";
  std::string image_path = "scene.png";
  std::string grasps_path;  ///< grasps JSON to draw; "" for none
  TreeRunSettings settings;
};

int run_command(const RunOptions& options);
int scene_command(const SceneOptions& options);
int detect_command(const DetectOptions& options);
int train_command(const TrainOptions& options);
int eval_classifier_command(const EvalOptions& options);
int validate_command(const std::string& tree_path);
int plugins_command();
/// `antipode plugins --check LIB`: loads `library` alone and prints its name, version, the
/// plugin ABI it was built for and what it provides (exit 0), or exactly why it cannot be
/// loaded - a missing symbol demangled, an ABI mismatch (one error line, exit 2).
int check_plugin_command(const std::string& library);
/// `antipode plugins --write-index DIR`: writes DIR's plugin index (plugin_index.hpp).
int write_index_command(const std::string& directory);
/// Lists every node type, or (when `type` is not empty) the ports of one.
int nodes_command(const std::string& type);

/// Splits "key=value" overrides; throws Error for an entry without '='.
std::vector<std::pair<std::string, std::string>> parse_overrides(
    const std::vector<std::string>& entries);

/// Throws Error for a user's `--set key=value` (a blackboard entry: no dot in `key`) that the
/// tree file at `tree_path` never reads as `{key}` - usually a component parameter given
/// without its component (`--set samples=10` for `--set sampler.samples=10`), which would
/// otherwise change nothing. The message suggests the components whose parameters in the file
/// have that name.
void check_entries_are_read(const std::string& tree_path, const std::vector<std::string>& set);

}  // namespace antipode::cli
