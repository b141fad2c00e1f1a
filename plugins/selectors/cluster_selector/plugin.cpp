// The plugin library's entry symbol: one factory, selector "cluster_selector".
#include "antipode/plugin/abi.hpp"
#include "cluster_selector.hpp"

namespace {

antipode::Component* create_cluster_selector(const antipode::Parameters& params) {
  return new antipode::selectors::ClusterSelector(params);
}

const antipode::PluginFactory kFactories[] = {
    {"selector", "cluster_selector",
     "clusters hands, one mean grasp per cluster, ranked by aperture margin then score "
     "(paper 5.1)",
     &create_cluster_selector, nullptr},
};

}  // namespace

ANTIPODE_PLUGIN("cluster_selector", "1.0.0", kFactories)
