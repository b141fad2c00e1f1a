// The pipeline_nodes plugin: the behaviour-tree nodes that connect components.
#include "antipode/plugin/abi.hpp"
#include "nodes.hpp"

namespace {
using namespace antipode::pipeline;

const antipode::PluginFactory kFactories[] = {
    {"node", "LoadCloud", "reads a PCD or PLY file", nullptr, &register_load_cloud},
    {"node", "CaptureCloud", "captures a cloud from a cell", nullptr, &register_capture_cloud},
    {"node", "SampleHands", "samples hand hypotheses", nullptr, &register_sample_hands},
    {"node", "ScreenHands", "drops hands before classification", nullptr, &register_screen_hands},
    {"node", "ClassifyHands", "scores and labels hands", nullptr, &register_classify_hands},
    {"node", "SelectGrasps", "ranks grasps", nullptr, &register_select_grasps},
    {"node", "PlanReach", "plans an arm motion to a grasp", nullptr, &register_plan_reach},
    {"node", "ReadArmState", "reads a cell's arm state", nullptr, &register_read_arm_state},
    {"node", "ExecuteGrasp", "executes a grasp in a cell", nullptr, &register_execute_grasp},
    {"node", "TryGrasps", "tries hands as trials from one saved world", nullptr,
     &register_try_grasps},
    {"node", "WriteGrasps", "writes hands to JSON", nullptr, &register_write_grasps},
    {"node", "WriteCloud", "writes a cloud to PCD", nullptr, &register_write_cloud},
    {"node", "WriteObjects", "writes where a cell's objects lie", nullptr, &register_write_objects},
    {"node", "WriteArmPath", "writes where an arm's links pass along a motion", nullptr,
     &register_write_arm_path},
    {"node", "ReadGrasps", "reads hands from JSON", nullptr, &register_read_grasps},
    {"node", "SelectViews", "keeps the points of some views", nullptr, &register_select_views},
    {"node", "ResetScene", "rebuilds a cell's scene from a seed", nullptr, &register_reset_scene},
    {"node", "RecordOutcome", "tallies grasp outcomes", nullptr, &register_record_outcome},
    {"node", "ClearBox", "picks until the box is empty", nullptr, &register_clear_box},
    {"node", "AvoidFailedGrasps", "drops hands where a grasp just failed", nullptr,
     &register_avoid_failed_grasps},
    {"node", "CorrectDepthScale", "corrects depth scale against the support", nullptr,
     &register_correct_depth_scale},
};

}  // namespace

ANTIPODE_PLUGIN("pipeline_nodes", "0.1.0", kFactories)
