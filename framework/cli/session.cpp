#include "session.hpp"

#include <unistd.h>

#include <cstdlib>
#include <iostream>

namespace antipode::cli {

Session open_session() {
  Session session{std::make_unique<PluginHost>(), bt::builtin_node_registry()};
  session.host->load_search_path();
  session.host->register_nodes(session.registry);
  return session;
}

Tracing attach_tracers(bt::Tree& tree, bool console, const std::string& trace_path) {
  Tracing tracing;
  if (console) {
    const bool colour = isatty(STDOUT_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
    tracing.console = std::make_unique<bt::ConsoleTracer>(std::cout, colour);
    tree.add_observer(tracing.console.get());
  }
  if (!trace_path.empty()) {
    tracing.file = std::make_unique<bt::JsonlTracer>(trace_path);
    tree.add_observer(tracing.file.get());
  }
  return tracing;
}

std::string refused_plugins_note(const PluginHost& host) {
  int refused = 0;
  for (const auto& record : host.records()) {
    if (record.state == PluginRecord::State::kRefused) ++refused;
  }
  if (refused == 0) return {};
  return " - note: " + std::to_string(refused) + " plugin " +
         (refused == 1 ? "library was" : "libraries were") + " refused; see 'antipode plugins'";
}

}  // namespace antipode::cli
