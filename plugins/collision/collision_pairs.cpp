#include "collision_pairs.hpp"

#include <algorithm>
#include <vector>

#include "antipode/core/error.hpp"

namespace antipode::collision {

namespace {

// `link` and its ancestors up to the root, each with the number of moving joints between it
// and `link`.
std::vector<std::pair<std::string, int>> ancestors(const RobotModel& robot,
                                                   const std::string& link) {
  std::vector<std::pair<std::string, int>> path{{link, 0}};
  for (;;) {
    bool moving = false;
    const std::string parent = robot.parent_link(path.back().first, nullptr, &moving);
    if (parent.empty()) return path;
    path.emplace_back(parent, path.back().second + (moving ? 1 : 0));
  }
}

}  // namespace

int moving_joints_between(const RobotModel& robot, const std::string& a, const std::string& b) {
  const auto up_a = ancestors(robot, a);
  const auto up_b = ancestors(robot, b);
  for (const auto& [link_a, joints_a] : up_a)  // the lowest common ancestor comes first
    for (const auto& [link_b, joints_b] : up_b)
      if (link_a == link_b) return joints_a + joints_b;
  return -1;  // not reached: every link hangs from the root
}

std::vector<std::string> shaped_links_below(const RobotModel& robot, const std::string& link) {
  if (!robot.has_link(link))
    throw Error(robot.source() + ": no link '" + link + "'" +
                did_you_mean(link, robot.link_names()));
  std::vector<std::string> names;
  for (const std::string& name : robot.link_names()) {
    if (robot.collision_shapes(name).empty()) continue;
    for (std::string up = name; !up.empty(); up = robot.parent_link(up)) {
      if (up == link) {
        names.push_back(name);
        break;
      }
    }
  }
  return names;
}

std::vector<std::string> shaped_links_below(const RobotModel& robot,
                                            const std::vector<std::string>& links) {
  std::vector<std::string> names;
  for (const std::string& link : links)
    for (const std::string& name : shaped_links_below(robot, link))
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

}  // namespace antipode::collision
