#include "session.hpp"

namespace antipode::cli {

Session open_session() {
  Session session{std::make_unique<PluginHost>(), bt::builtin_node_registry()};
  session.host->load_search_path();
  session.host->register_nodes(session.registry);
  return session;
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
