#pragma once
// One attempt of the isolation benchmark: the pick tree's `attempt` tree run once on one
// object in one pose for one variant, and its record as JSON.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antipode/core/hand.hpp"
#include "antipode/evaluation/bench_objects.hpp"
#include "antipode/evaluation/session.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"

namespace antipode::evaluation {

/// A variant of the paper's isolation experiment: a classifier and the views captured.
struct BenchVariant {
  std::string name;                ///< "nc_1v", "nc_2v", "a_2v", "svm_1v", "svm_2v"
  std::string classifier_plugin;   ///< replaces the tree's classifier; "" keeps it (SVM)
  bool classifier_threads = true;  ///< the classifier takes a `threads` parameter
  std::vector<std::string> views;
};

/// The paper's five variants, in its order.
const std::vector<BenchVariant>& isolation_variants();

/// What every task of a run shares.
struct TaskSettings {
  std::string tree_path;               ///< the pick tree file (its `attempt` tree is run)
  std::string tree_yaml;               ///< its text, read once
  int threads = 2;                     ///< threads of the sampler, classifier and renderer
  std::string noise;                   ///< the cell's `noise` ("" = the tree's)
  std::string pictures_dir;            ///< where failed attempts are drawn ("" = nowhere)
  std::string selections_dir;          ///< where each attempt's selection, cloud and objects go
  std::vector<std::string> overrides;  ///< the user's --set entries, applied last
};

struct BenchTask {
  int index = 0;    ///< position in the run's task list
  int attempt = 0;  ///< attempt number (object and pose); variants of an attempt share it
  BenchObject object;
  int pose = 0;
  int poses = 1;
  const BenchVariant* variant = nullptr;
  std::uint64_t seed = 0;  ///< the cell's seed: sensor noise and settling
  bool held_out = false;
  bool graspable = true;  ///< the gripper can hold the object in this pose at all
};

/// A hand as JSON: position_m, quaternion_xyzw, approach, score, width_m.
nlohmann::ordered_json hand_json(const Hand& hand);

/// A cell's attempt record as JSON (its fields but outcome and reason; NaN as null).
nlohmann::ordered_json record_json(const GraspAttempt& record);

/// The failure class of an executed attempt, from the cell's record (docs/cli.md lists
/// them): "success", "collision at the stand-off pose", "arm collision", "planned into the
/// object", "stopped short of the pose", "nothing between the planned fingers", "closed on
/// nothing", "knocked out", "slipped" or "not executed".
std::string failure_class(const GraspAttempt& record);

/// Throws antipode::Error unless the tree file at `tree_path` (which exists) has a component
/// named `cell`: every bench runs its tree in the simulated cell, as `example_tree` does.
void require_cell_component(const std::string& tree_path, const std::string& example_tree);

/// The pick tree's `attempt` tree, loaded for `task` (its components created, nothing run).
/// Throws antipode::Error when it cannot be loaded (e.g. a parameter the variant's
/// classifier does not take).
bt::Tree load_task_tree(const Session& session, const TaskSettings& settings,
                        const BenchTask& task);

/// Runs `task` and returns its record: the task's identity, "outcome" ("no grasp found",
/// "error" or the cell's outcome), "reason" (a failure class, see failure_class()),
/// "detail" (one line), the executed "hand", the cell's "record", "stage_s" and "wall_s".
/// A tree that cannot be loaded throws antipode::Error (the run stops); an error while the
/// tree runs is recorded as outcome "error".
nlohmann::ordered_json run_task(const Session& session, const TaskSettings& settings,
                                const BenchTask& task);

}  // namespace antipode::evaluation
