// `antipode train` and `antipode eval-classifier`: the training and evaluation trees run with
// their file entries filled from the command line, with a progress bar on a terminal.
#include <iostream>

#include "antipode/bt/loader.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "progress_bar.hpp"
#include "session.hpp"

namespace antipode::cli {
namespace {

struct TreeRun {
  std::string tree_path;
  std::vector<std::string> entries;  // "key=value" before the user's --set
  const std::vector<std::string>* set = nullptr;
  std::uint64_t seed = 0;
  bool verbose = false;
};

int run_tree(const TreeRun& what) {
  RunOptions run;
  run.tree_path = what.tree_path;
  run.set = what.entries;
  run.set.insert(run.set.end(), what.set->begin(), what.set->end());
  run.seed = what.seed;
  Session session = open_session();
  bt::Tree tree = load_tree_for(session, run);
  const Tracing tracing = attach_tracers(tree, what.verbose, "");
  ProgressBar bar(std::cerr, !what.verbose && progress_wanted());
  attach_progress_bar(tree, bar);
  const bt::Status status = tree.tick_while_running();
  bar.clear();
  std::cout << what.tree_path << ": " << bt::to_string(status) << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

}  // namespace

int train_command(const TrainOptions& options) {
  return run_tree({options.tree_path,
                   {"model_file=" + options.model_path, "dataset_file=" + options.dataset_path},
                   &options.set,
                   options.seed,
                   options.verbose});
}

int eval_classifier_command(const EvalOptions& options) {
  return run_tree({options.tree_path,
                   {"model_file=" + options.model_path, "report_file=" + options.report_path},
                   &options.set,
                   options.seed,
                   options.verbose});
}

}  // namespace antipode::cli
