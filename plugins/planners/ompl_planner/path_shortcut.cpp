#include "path_shortcut.hpp"

#include "arm_planner.hpp"

namespace antipode::planning {

std::vector<Eigen::VectorXd> shortcut_path(const collision::ArmCollisionWorld& world,
                                           const std::vector<Eigen::VectorXd>& path,
                                           double resolution_rad, bool rake) {
  if (path.size() <= 2) return path;
  std::vector<Eigen::VectorXd> kept{path.front()};
  std::size_t from = 0;
  while (from + 1 < path.size()) {
    std::size_t to = path.size() - 1;  // the farthest reachable; the next one always is
    while (to > from + 1 && !segment_is_free(world, path[from], path[to], resolution_rad, rake))
      --to;
    kept.push_back(path[to]);
    from = to;
  }
  return kept;
}

}  // namespace antipode::planning
