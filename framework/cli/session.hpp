#pragma once
// What every CLI command that touches trees needs: the plugin host with everything found on
// the search path, and a node registry with the built-in and plugin node types.

#include <memory>
#include <string>
#include <vector>

#include "antipode/bt/node_registry.hpp"
#include "antipode/bt/tracers.hpp"
#include "antipode/bt/tree.hpp"
#include "antipode/plugin/plugin_host.hpp"

namespace antipode::cli {

struct Session {
  std::unique_ptr<PluginHost> host;
  bt::NodeRegistry registry;
};

/// Loads every plugin on the search path and registers built-in and plugin nodes.
Session open_session();

struct TreeRunSettings;

/// Loads `tree_path` with the session's registry and components, seeded with `settings.seed`.
/// `entries` ("key=value", as --set takes them) are what the command fills in from its own
/// arguments; the user's `settings.set` is applied after them, so it can change any of them.
/// Unknown-name errors get a note when plugins were refused (a refused plugin is the usual
/// cause).
bt::Tree load_tree_for(const Session& session, const std::string& tree_path,
                       const std::vector<std::string>& entries, const TreeRunSettings& settings);

/// The tracers a command attached to a tree; they must outlive its ticks.
struct Tracing {
  std::unique_ptr<bt::ConsoleTracer> console;
  std::unique_ptr<bt::JsonlTracer> file;
};

/// Attaches a console tracer (when `console`) and a JSON-lines trace file (when
/// `trace_path` is not empty) to `tree`.
Tracing attach_tracers(bt::Tree& tree, bool console, const std::string& trace_path);

/// " - note: N plugin libraries were refused; see 'antipode plugins'", or "" when none were.
std::string refused_plugins_note(const PluginHost& host);

}  // namespace antipode::cli
