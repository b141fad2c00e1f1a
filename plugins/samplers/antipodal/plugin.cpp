// The plugin library's entry symbol: one factory, sampler "antipodal_sampler".
#include "antipodal_sampler.hpp"
#include "antipode/plugin/abi.hpp"

namespace {

antipode::Component* create_antipodal_sampler(const antipode::Parameters& params) {
  return new antipode::samplers::AntipodalSampler(params);
}

const antipode::PluginFactory kFactories[] = {
    {"sampler", "antipodal_sampler",
     "hand hypotheses by antipodal sampling (ten Pas & Platt, Algorithms 2-3)",
     &create_antipodal_sampler, nullptr},
};

}  // namespace

ANTIPODE_PLUGIN("antipodal_sampler", "1.0.0", kFactories)
