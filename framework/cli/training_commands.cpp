// `antipode train` and `antipode eval-classifier`: the training and evaluation trees run with
// their file entries filled from the command line, with a progress bar on a terminal.
#include <iostream>

#include "antipode/bt/loader.hpp"
#include "antipode/core/atomic_file.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "progress_bar.hpp"
#include "session.hpp"

namespace antipode::cli {
namespace {

// Runs `tree_path` with `entries` filled from the command's arguments; a progress bar on a
// terminal unless every node's status is printed.
int run_tree(const std::string& tree_path, const std::vector<std::string>& entries,
             const TreeRunSettings& settings) {
  Session session = open_session_for(tree_path, entries, settings);
  bt::Tree tree = load_tree_for(session, tree_path, entries, settings);
  const Tracing tracing = attach_tracers(tree, settings.verbose, "");
  ProgressBar bar(std::cerr, !settings.verbose && progress_wanted());
  attach_progress_bar(tree, bar);
  const bt::Status status = tree.tick_while_running();
  bar.clear();
  std::cout << result_line(tree_path, status, tracing) << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

}  // namespace

int train_command(const TrainOptions& options) {
  // Before the half hour of training, not after it.
  for (const std::string* path : {&options.model_path, &options.dataset_path})
    if (!path->empty()) check_output_path(*path);
  return run_tree(options.tree_path,
                  {"model_file=" + options.model_path, "dataset_file=" + options.dataset_path},
                  options.settings);
}

int eval_classifier_command(const EvalOptions& options) {
  if (!options.report_path.empty()) check_output_path(options.report_path);
  return run_tree(options.tree_path,
                  {"model_file=" + options.model_path, "report_file=" + options.report_path},
                  options.settings);
}

}  // namespace antipode::cli
