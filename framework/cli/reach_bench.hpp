#pragma once
// `antipode bench reach`: inverse kinematics of a robot arm measured with TRAC-IK's
// protocol (docs/cli.md, docs/results.md).

#include <cstdint>
#include <string>
#include <vector>

namespace antipode::cli {

struct ReachBenchOptions {
  std::string robot_path = "robots/baxter/baxter.urdf";
  std::string base_link = "base";
  std::string tip_link = "right_hand";
  int ik_poses = 10000;    ///< random reachable poses
  std::uint64_t seed = 1;  ///< the poses' random stream
  std::vector<std::string> solvers{"dls", "kdl"};
  double timeout_ms = 5.0;  ///< per pose
  double tolerance = 1e-5;  ///< m and rad per component
  std::string report_path;  ///< JSON report ("" = none)
};

/// Draws `ik_poses` joint vectors uniformly within the limits, takes their forward
/// kinematics as targets and solves each from the mid-range seed with every solver; prints
/// success rates and times and writes the report. Returns the exit code; throws
/// antipode::Error for bad options.
int bench_reach_command(const ReachBenchOptions& options);

}  // namespace antipode::cli
