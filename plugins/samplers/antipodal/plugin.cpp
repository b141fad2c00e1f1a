// The plugin library's entry symbol: one factory, sampler "antipodal_sampler".
#include "antipodal_sampler.hpp"
#include "antipode/plugin/abi.hpp"
#include "sampler_settings.hpp"

namespace {

antipode::Component* create_antipodal_sampler(const antipode::Parameters& params) {
  return new antipode::samplers::AntipodalSampler(params);
}

void check_antipodal_sampler(const antipode::Parameters& params) {
  (void)antipode::samplers::read_sampler_settings(params);
}

const antipode::PluginFactory kFactories[] = {
    {"sampler", "antipodal_sampler",
     "hand hypotheses by antipodal sampling (ten Pas & Platt, Algorithms 2-3)",
     &create_antipodal_sampler, nullptr},
};

const antipode::PluginParameterCheck kChecks[] = {{"antipodal_sampler", &check_antipodal_sampler}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("antipodal_sampler", "1.0.0", kFactories, kChecks)
