// The robot_nodes plugin: the nodes that check a robot's files.
#include "antipode/bt/node_registry.hpp"
#include "antipode/plugin/abi.hpp"

namespace antipode::robot_nodes {
void register_check_robot(bt::NodeRegistry& registry);
}  // namespace antipode::robot_nodes

namespace {

const antipode::PluginFactory kFactories[] = {
    {"node", "CheckRobot", "checks a robot file: kinematics, collisions, reach, gripper", nullptr,
     &antipode::robot_nodes::register_check_robot},
};

}  // namespace

ANTIPODE_PLUGIN("robot_nodes", "0.1.0", kFactories)
