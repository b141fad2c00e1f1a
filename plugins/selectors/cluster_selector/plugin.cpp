// The plugin library's entry symbol: one factory, selector "cluster_selector".
#include "antipode/plugin/abi.hpp"
#include "cluster_selector.hpp"

namespace {

antipode::Component* create_cluster_selector(const antipode::Parameters& params) {
  return new antipode::selectors::ClusterSelector(params);
}

// Builds the selector: its only heavy part, the arm's collision model, is the check of
// `robot` (about 20 ms for Baxter).
void check_cluster_selector(const antipode::Parameters& params) {
  const antipode::selectors::ClusterSelector checked(params);
}

const antipode::PluginFactory kFactories[] = {
    {"selector", "cluster_selector",
     "clusters hands, one mean grasp per cluster, ranked by aperture margin then score "
     "(paper 5.1)",
     &create_cluster_selector, nullptr},
};

const antipode::PluginParameterCheck kChecks[] = {{"cluster_selector", &check_cluster_selector}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("cluster_selector", "1.0.0", kFactories, kChecks)
