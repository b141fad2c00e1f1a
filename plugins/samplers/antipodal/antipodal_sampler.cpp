#include "antipodal_sampler.hpp"

#include "sampler_settings.hpp"

namespace antipode::samplers {

AntipodalSampler::AntipodalSampler(const Parameters& params)
    : options_(read_sampler_settings(params)) {}

HandSet AntipodalSampler::sample(const Cloud& cloud, const RandomStream& random,
                                 const StopToken& stop) const {
  stop.throw_if_stop_requested("antipodal_sampler");
  HandSet hands = sample_hands(cloud, options_, random);
  stop.throw_if_stop_requested("antipodal_sampler");
  return hands;
}

}  // namespace antipode::samplers
