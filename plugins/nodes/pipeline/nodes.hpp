#pragma once
// The pipeline nodes: behaviour-tree leaves that move clouds, hands and grasps through the
// components of a tree (docs/trees.md, "Pipeline nodes"). One registration function per node.

#include "antipode/bt/node_registry.hpp"

namespace antipode::pipeline {

void register_load_cloud(bt::NodeRegistry& registry);
void register_capture_cloud(bt::NodeRegistry& registry);
void register_sample_hands(bt::NodeRegistry& registry);
void register_screen_hands(bt::NodeRegistry& registry);
void register_classify_hands(bt::NodeRegistry& registry);
void register_select_grasps(bt::NodeRegistry& registry);
void register_plan_reach(bt::NodeRegistry& registry);
void register_read_arm_state(bt::NodeRegistry& registry);
void register_execute_grasp(bt::NodeRegistry& registry);
void register_try_grasps(bt::NodeRegistry& registry);
void register_write_grasps(bt::NodeRegistry& registry);
void register_write_cloud(bt::NodeRegistry& registry);
void register_write_objects(bt::NodeRegistry& registry);
void register_write_arm_path(bt::NodeRegistry& registry);
void register_read_grasps(bt::NodeRegistry& registry);
void register_reset_scene(bt::NodeRegistry& registry);
void register_select_views(bt::NodeRegistry& registry);
void register_record_outcome(bt::NodeRegistry& registry);
void register_clear_box(bt::NodeRegistry& registry);
void register_avoid_failed_grasps(bt::NodeRegistry& registry);
void register_correct_depth_scale(bt::NodeRegistry& registry);

}  // namespace antipode::pipeline
