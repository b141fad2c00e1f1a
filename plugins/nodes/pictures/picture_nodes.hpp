#pragma once
// The picture nodes: one registration function per node (docs/trees.md).

#include "antipode/bt/node_registry.hpp"

namespace antipode::pictures {

void register_draw_grasps(bt::NodeRegistry& registry);
void register_draw_attempt(bt::NodeRegistry& registry);
void register_draw_arm_path(bt::NodeRegistry& registry);
void register_draw_cloud(bt::NodeRegistry& registry);

}  // namespace antipode::pictures
