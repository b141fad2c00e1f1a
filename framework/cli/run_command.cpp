
#include <iostream>
#include <memory>

#include "antipode/bt/loader.hpp"
#include "antipode/bt/tracers.hpp"
#include "antipode/core/error.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "session.hpp"

namespace antipode::cli {
namespace {

bt::LoadOptions load_options(const Session& session, const std::vector<std::string>& entries,
                             const TreeRunSettings& settings) {
  std::vector<std::string> overrides = entries;
  overrides.insert(overrides.end(), settings.set.begin(), settings.set.end());
  bt::LoadOptions load;
  load.registry = &session.registry;
  load.components = session.host.get();
  load.seed = settings.seed;
  load.overrides = parse_overrides(overrides);
  load.main_tree = settings.main_tree;
  return load;
}

}  // namespace

bt::Tree load_tree_for(Session& session, const std::string& tree_path,
                       const std::vector<std::string>& entries, const TreeRunSettings& settings) {
  check_entries_are_read(tree_path, settings.set);
  if (!session.every_plugin) {
    // Checked first (which builds no component): a tree the opened plugins cannot load is
    // loaded with all of them, so its errors are those of a full session. The parameters are
    // left to the load, which makes the components (a model is then read once).
    try {
      bt::LoadOptions names_only = load_options(session, entries, settings);
      names_only.check_component_parameters = false;
      bt::validate_tree_file(tree_path, names_only);
    } catch (const Error&) {
      replace_with_full_session(session);
    }
  }
  try {
    return bt::load_tree_file(tree_path, load_options(session, entries, settings));
  } catch (const UnknownTypeError& error) {
    throw_with_refused_plugins_note(error, *session.host);
  }
}

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
