#pragma once
// Which robot link pairs the self-collision check can skip. Links separated by few moving
// joints touch at those joints by construction: their primitive shapes (cylinders per link)
// overlap where the real links are shaped around each other, and the joint limits of the
// real robot keep them apart. MoveIt's setup assistant disables such pairs for the same
// reason.

#include <string>
#include <vector>

#include "antipode/robot/robot_model.hpp"

namespace antipode::collision {

/// The number of moving joints on the kinematic tree's path from `a` to `b` (0 when they
/// are rigidly attached through fixed joints).
int moving_joints_between(const RobotModel& robot, const std::string& a, const std::string& b);

/// `link` and every link below it that has collision shapes (e.g. a gripper below its
/// flange: the links a caller may leave unchecked against observed points). Throws
/// antipode::Error for an unknown link, suggesting the nearest name.
std::vector<std::string> shaped_links_below(const RobotModel& robot, const std::string& link);
/// The same for each of `links`, in order, without repeats.
std::vector<std::string> shaped_links_below(const RobotModel& robot,
                                            const std::vector<std::string>& links);

}  // namespace antipode::collision
