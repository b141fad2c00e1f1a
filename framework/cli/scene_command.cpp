#include <iostream>

#include "antipode/bt/loader.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "session.hpp"

namespace antipode::cli {

int scene_command(const SceneOptions& options) {
  RunOptions run;
  run.tree_path = options.tree_path;
  // The scene path goes in as a YAML string, so any file name is taken literally.
  run.set = {"cell.scene='" + options.scene_path + "'", "image_file=" + options.image_path,
             "grasps_file=" + options.grasps_path};
  run.set.insert(run.set.end(), options.set.begin(), options.set.end());
  run.seed = options.seed;
  Session session = open_session();
  bt::Tree tree = load_tree_for(session, run);
  const Tracing tracing = attach_tracers(tree, options.verbose, "");
  const bt::Status status = tree.tick_while_running();
  std::cout << options.tree_path << ": " << bt::to_string(status) << "\n";
  if (status == bt::Status::kSuccess) std::cout << "picture: " << options.image_path << "\n";
  return status == bt::Status::kSuccess ? kExitSuccess : kExitTreeFailed;
}

}  // namespace antipode::cli
