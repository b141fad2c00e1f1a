
#include <iostream>
#include <memory>

#include "antipode/bt/loader.hpp"
#include "antipode/bt/tracers.hpp"
#include "antipode/core/error.hpp"
#include "antipode/evaluation/exit_codes.hpp"
#include "antipode/evaluation/session.hpp"
#include "commands.hpp"

namespace antipode::cli {

using evaluation::load_options;
using evaluation::replace_with_full_session;
using evaluation::throw_with_refused_plugins_note;

int run_command(const RunOptions& options) {
  Session session = open_session_for(options.tree_path, {}, options.settings);
  bt::Tree tree = load_tree_for(session, options.tree_path, {}, options.settings);
  const Tracing tracing = attach_tracers(tree, options.settings.verbose, options.trace_path);
  const bt::Status status = tree.tick_while_running();
  std::cout << result_line(options.tree_path, status, tracing) << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

int validate_command(const std::string& tree_path) {
  Session session = open_session_for(tree_path, {}, TreeRunSettings{});
  if (!session.every_plugin) {
    try {
      bt::validate_tree_file(tree_path, load_options(session, {}, TreeRunSettings{}));
      std::cout << tree_path << ": valid\n";
      return kExitSuccess;
    } catch (const Error&) {
      replace_with_full_session(session);
    }
  }
  try {
    bt::validate_tree_file(tree_path, load_options(session, {}, TreeRunSettings{}));
  } catch (const UnknownTypeError& error) {
    throw_with_refused_plugins_note(error, *session.host);
  }
  std::cout << tree_path << ": valid\n";
  return kExitSuccess;
}

}  // namespace antipode::cli
