#include <iostream>

#include "antipode/bt/loader.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/evaluation/exit_codes.hpp"
#include "antipode/evaluation/session.hpp"
#include "commands.hpp"

namespace antipode::cli {

int scene_command(const SceneOptions& options) {
  if (!options.image_path.empty()) check_output_path(options.image_path);
  // The scene path goes in as a YAML string, so any file name is taken literally.
  const std::vector<std::string> entries = {"cell.scene='" + options.scene_path + "'",
                                            "image_file=" + options.image_path,
                                            "grasps_file=" + options.grasps_path};
  Session session = open_session_for(options.tree_path, entries, options.settings);
  bt::Tree tree = load_tree_for(session, options.tree_path, entries, options.settings);
  const Tracing tracing = attach_tracers(tree, options.settings.verbose, "");
  const bt::Status status = tree.tick_while_running();
  std::cout << result_line(options.tree_path, status, tracing) << "\n";
  if (status == bt::Status::kSuccess) std::cout << "picture: " << options.image_path << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

}  // namespace antipode::cli
