#include <unistd.h>

#include <cstdlib>
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

bool stdout_wants_colour() {
  return isatty(STDOUT_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
}

bt::LoadOptions load_options(const Session& session, const RunOptions& options) {
  bt::LoadOptions load;
  load.registry = &session.registry;
  load.components = session.host.get();
  load.seed = options.seed;
  load.overrides = parse_overrides(options.set);
  return load;
}

}  // namespace

bt::Tree load_tree_for(const Session& session, const RunOptions& options) {
  try {
    return bt::load_tree_file(options.tree_path, load_options(session, options));
  } catch (const Error& error) {
    const std::string note = refused_plugins_note(*session.host);
    if (note.empty()) throw;
    throw Error(error.what() + note);
  }
}

int run_command(const RunOptions& options) {
  Session session = open_session();
  bt::Tree tree = load_tree_for(session, options);
  std::unique_ptr<bt::ConsoleTracer> console;
  std::unique_ptr<bt::JsonlTracer> trace_file;
  if (!options.quiet) {
    console = std::make_unique<bt::ConsoleTracer>(std::cout, stdout_wants_colour());
    tree.add_observer(console.get());
  }
  if (!options.trace_path.empty()) {
    trace_file = std::make_unique<bt::JsonlTracer>(options.trace_path);
    tree.add_observer(trace_file.get());
  }
  const bt::Status status = tree.tick_while_running();
  std::cout << options.tree_path << ": " << bt::to_string(status) << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

int validate_command(const std::string& tree_path) {
  Session session = open_session();
  RunOptions options;
  options.tree_path = tree_path;
  try {
    bt::validate_tree_file(tree_path, load_options(session, options));
  } catch (const Error& error) {
    const std::string note = refused_plugins_note(*session.host);
    if (note.empty()) throw;
    throw Error(error.what() + note);
  }
  std::cout << tree_path << ": valid\n";
  return kExitSuccess;
}

}  // namespace antipode::cli
