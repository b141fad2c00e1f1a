#pragma once
// What every command and bench that touches trees needs: the plugin host with the plugins found on
// the search path (all of them, or only those a tree names), and a node registry with the
// built-in and plugin node types.

#include <memory>
#include <string>
#include <vector>

#include "antipode/bt/loader.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/bt/tracers.hpp"
#include "antipode/bt/tree.hpp"
#include "antipode/plugin/plugin_host.hpp"

namespace antipode::evaluation {

struct Session {
  std::unique_ptr<PluginHost> host;
  bt::NodeRegistry registry;
  bool every_plugin = true;  ///< false when only the libraries a tree names were opened
};

/// Loads every plugin on the search path and registers built-in and plugin nodes.
Session open_session();

struct TreeRunSettings;

/// Opens only the plugin libraries that provide a name used in `tree_path`, `entries` or
/// `settings.set` (PluginHost::load_for: the plugin directories' indexes tell which), so a
/// tree starts without loading every plugin and its libraries. The same as open_session()
/// when ANTIPODE_PLUGIN_LOAD=all is set.
Session open_session_for(const std::string& tree_path, const std::vector<std::string>& entries,
                         const TreeRunSettings& settings);

/// The load options of a tree run in `session`: its registry and components, the seed of
/// `settings`, and `entries` followed by the user's `settings.set` as overrides.
bt::LoadOptions load_options(const Session& session, const std::vector<std::string>& entries,
                             const TreeRunSettings& settings);

/// Replaces `session` by open_session(), releasing the old one in its own order (its node
/// registry before the host whose libraries hold the registry's code).
void replace_with_full_session(Session& session);

/// Loads `tree_path` with the session's registry and components, seeded with `settings.seed`.
/// `entries` ("key=value", as --set takes them) are what the command fills in from its own
/// arguments; the user's `settings.set` is applied after them, so it can change any of them.
/// Unknown-name errors get a note when plugins were refused (a refused plugin is the usual
/// cause). When the session holds only some plugins and the tree does not validate with
/// them, `session` is replaced by open_session() first, so errors are those of a full
/// session; components are built once. Throws antipode::Error for a tree that cannot load.
bt::Tree load_tree_for(Session& session, const std::string& tree_path,
                       const std::vector<std::string>& entries, const TreeRunSettings& settings);

/// The tracers a command attached to a tree; they must outlive its ticks.
struct Tracing {
  std::unique_ptr<bt::ConsoleTracer> console;
  std::unique_ptr<bt::JsonlTracer> file;
  std::unique_ptr<bt::FailureWitness> witness;
};

/// Attaches a console tracer (when `console`), a JSON-lines trace file (when `trace_path` is
/// not empty) and a failure witness to `tree`.
Tracing attach_tracers(bt::Tree& tree, bool console, const std::string& trace_path);

/// The line a command ends a tree run with: `trees/detect.yaml: SUCCESS`, or on failure
/// `trees/detect.yaml: FAILURE (SampleHands at trees/detect.yaml:18:13: no hand hypothesis
/// found)` - the last leaf that failed with a reason, unless the console trace already
/// showed it.
std::string result_line(const std::string& tree_path, bt::Status status, const Tracing& tracing);

/// Rethrows `error` (a tree naming a type no loaded library provides), with " - note: N plugin
/// libraries were refused, and may provide it; see 'antipode plugins'" when the host refused
/// any: only then can a refused library be the cause.
[[noreturn]] void throw_with_refused_plugins_note(const UnknownTypeError& error,
                                                  const PluginHost& host);

}  // namespace antipode::evaluation
