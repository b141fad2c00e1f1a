// `antipode robot check ROBOT`: trees/robot_check.yaml with the robot file as its `robot`
// setting (docs/robot.md, "Bringing your own robot").
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "commands.hpp"

namespace antipode::cli {

int robot_check_command(const RobotCheckOptions& o) {
  if (o.configurations < 1) throw Error("robot check: --configurations must be at least 1");
  if (!o.report_path.empty()) check_output_path(o.report_path);
  return run_tree_command(
      o.tree_path,
      {"robot=" + o.robot_path, "scene_file=" + o.scene_path,
       "configurations=" + std::to_string(o.configurations), "report_file=" + o.report_path},
      o.settings);
}

}  // namespace antipode::cli
