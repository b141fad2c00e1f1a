// `antipode train` and `antipode eval-classifier`: the training and evaluation trees run with
// their file entries filled from the command line, with a progress bar on a terminal.
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "antipode/bt/loader.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/binary_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/shipped_data.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/evaluation/exit_codes.hpp"
#include "antipode/evaluation/progress_bar.hpp"
#include "antipode/evaluation/session.hpp"
#include "commands.hpp"

namespace antipode::cli {

using evaluation::attach_progress_bar;
using evaluation::machine_json;
using evaluation::progress_wanted;
using evaluation::ProgressBar;

int run_tree_command(const std::string& tree_path, const std::vector<std::string>& entries,
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

namespace {

// A shipped model (one of the shipped models/ folder's files) is replaced only when asked:
// the default --out would otherwise overwrite models/hog_svm.model with a model for whatever
// hand the tree samples.
void check_not_shipped(const std::string& path, bool overwrite) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (overwrite || !fs::exists(path, error) || shipped_data_dir().empty()) return;
  const fs::path models = fs::weakly_canonical(fs::path(shipped_data_dir()) / "models", error);
  if (fs::weakly_canonical(path, error).parent_path() != models) return;
  throw Error(path +
              " is a shipped model: write the new one elsewhere (--out my.model, then "
              "the classifier's model: my.model), or give --overwrite to replace it");
}

}  // namespace

int train_command(const TrainOptions& options) {
  // Before the half hour of training, not after it.
  check_not_shipped(options.model_path, options.overwrite);
  for (const std::string* path : {&options.model_path, &options.dataset_path})
    if (!path->empty()) check_output_path(*path);
  return run_tree_command(
      options.tree_path,
      {"model_file=" + options.model_path, "dataset_file=" + options.dataset_path},
      options.settings);
}

namespace {

// Adds to the tree's report what `antipode report` needs to place it: the kind, the
// command's settings and the machine.
void stamp_eval_report(const EvalOptions& o) {
  std::ifstream in(o.report_path);
  if (!in) return;  // the tree wrote no report (its EvaluateClassifier has no report_file)
  nlohmann::ordered_json report = nlohmann::ordered_json::parse(in, nullptr, false);
  if (report.is_discarded()) throw Error(o.report_path + ": the tree wrote no JSON report");
  report["bench"] = "classifier";
  report["tree"] = o.tree_path;
  report["overrides"] = o.settings.set;
  report["machine"] = machine_json();
  write_file_atomically(o.report_path, [&](const std::string& temporary) {
    std::ofstream out(temporary);
    out << report.dump(2) << '\n';
    if (!out.flush()) throw Error("cannot write " + temporary);
  });
}

}  // namespace

int eval_classifier_command(const EvalOptions& options) {
  if (!options.report_path.empty()) check_output_path(options.report_path);
  // The tree reads the model only after computing every example: a damaged one is refused now.
  check_binary_file(options.model_path, "classifier model");
  const int code = run_tree_command(
      options.tree_path, {"model_file=" + options.model_path, "report_file=" + options.report_path},
      options.settings);
  if (code == kExitSuccess && !options.report_path.empty()) stamp_eval_report(options);
  return code;
}

}  // namespace antipode::cli
