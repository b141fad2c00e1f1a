#pragma once
// The `antipode` subcommands. Each returns the process exit code (see exit_codes.hpp) and
// throws antipode::Error for bad input, which main() prints as one line.

#include <string>
#include <vector>

#include "antipode/evaluation/exit_codes.hpp"
#include "antipode/evaluation/session.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"

namespace antipode::cli {

// The commands run trees in the evaluation library's sessions, and exit with its codes.
using evaluation::attach_tracers;
using evaluation::kExitInternalError;
using evaluation::kExitInvalidInput;
using evaluation::kExitSuccess;
using evaluation::kExitTreeFailed;
using evaluation::load_tree_for;
using evaluation::open_session;
using evaluation::open_session_for;
using evaluation::result_line;
using evaluation::Session;
using evaluation::Tracing;
using evaluation::TreeRunSettings;

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
  /// Also write to --out the hands a stage dropped, each with its reason (the tree's entry
  /// include_rejected).
  bool rejected = false;
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

/// `antipode robot check ROBOT` (trees/robot_check.yaml): a robot file's checks.
struct RobotCheckOptions {
  std::string robot_path;
  std::string tree_path = "trees/robot_check.yaml";
  std::string scene_path = "scenes/clear_box_procedural.yaml";  ///< entry scene_file
  int configurations = 1000;                                    ///< entry configurations
  std::string report_path;                                      ///< entry report_file
  TreeRunSettings settings;
};

/// Runs `tree_path` with `entries` ("key=value", the command's arguments) set on its main
/// blackboard; a progress bar on a terminal unless every node's status is printed.
int run_tree_command(const std::string& tree_path, const std::vector<std::string>& entries,
                     const TreeRunSettings& settings);

int run_command(const RunOptions& options);
int robot_check_command(const RobotCheckOptions& options);
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
struct ViewOptions;
/// `antipode view`: writes the page (view_page.hpp) and opens it with --open.
int view_command(const ViewOptions& options);
/// Lists every node type, or (when `type` is not empty) the ports of one.
int nodes_command(const std::string& type);

}  // namespace antipode::cli
