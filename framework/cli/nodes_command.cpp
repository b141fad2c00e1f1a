// `antipode nodes [TYPE]`: the node types trees can use (built in and from plugins), and the
// ports of one of them - what docs/trees.md describes, as this installation has it.
#include <iostream>

#include "antipode/bt/node_registry.hpp"
#include "antipode/evaluation/exit_codes.hpp"
#include "antipode/evaluation/session.hpp"
#include "commands.hpp"

namespace antipode::cli {

namespace {

std::string children_of(const bt::NodeManifest& manifest) {
  if (manifest.category != bt::NodeCategory::kControl) return "";
  if (manifest.max_children < 0) {
    return ", " + std::to_string(manifest.min_children) + " or more children";
  }
  return ", " + std::to_string(manifest.min_children) + " to " +
         std::to_string(manifest.max_children) + " children";
}

void print_port(const bt::PortInfo& port) {
  std::cout << "  " << port.name << " (" << bt::to_string(port.direction) << ", " << port.type_name;
  if (port.required) {
    std::cout << ", required";
  } else if (port.default_text) {
    std::cout << ", default " << (port.default_text->empty() ? "\"\"" : *port.default_text);
  }
  std::cout << ")";
  if (!port.description.empty()) std::cout << ": " << port.description;
  std::cout << "\n";
}

}  // namespace

int nodes_command(const std::string& type) {
  const Session session = open_session();
  if (type.empty()) {
    for (const std::string& name : session.registry.types()) {
      const bt::NodeManifest& manifest = session.registry.get(name);
      std::cout << name << " (" << bt::to_string(manifest.category) << ")"
                << (manifest.summary.empty() ? "" : ": " + manifest.summary) << "\n";
    }
    return kExitSuccess;
  }
  const bt::NodeManifest& manifest = session.registry.get(type);  // did-you-mean on a typo
  std::cout << manifest.type << " (" << bt::to_string(manifest.category) << children_of(manifest)
            << ")\n";
  if (!manifest.summary.empty()) std::cout << manifest.summary << "\n";
  std::cout << (manifest.ports.empty() ? "no ports\n" : "ports:\n");
  for (const bt::PortInfo& port : manifest.ports) print_port(port);
  return kExitSuccess;
}

}  // namespace antipode::cli
