// The plugin library's entry symbol: one factory, planner "ompl_planner".
#include "antipode/plugin/abi.hpp"
#include "ompl_planner.hpp"

namespace {

antipode::Component* create_ompl_planner(const antipode::Parameters& params) {
  return new antipode::planning::OmplPlanner(params);
}

void check_ompl_planner(const antipode::Parameters& params) {
  antipode::planning::OmplPlanner::check_parameters(params);
}

const antipode::PluginFactory kFactories[] = {
    {"planner", "ompl_planner",
     "plans an arm's motion to a grasp: collision-free IK, an OMPL path to the pre-grasp, the "
     "straight approach (FCL checks)",
     &create_ompl_planner, nullptr},
};

const antipode::PluginParameterCheck kChecks[] = {{"ompl_planner", &check_ompl_planner}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("ompl_planner", "1.0.0", kFactories, kChecks)
