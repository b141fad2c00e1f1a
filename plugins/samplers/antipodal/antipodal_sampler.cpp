#include "antipodal_sampler.hpp"

#include "sampler_settings.hpp"

namespace antipode::samplers {

AntipodalSampler::AntipodalSampler(const Parameters& params)
    : options_(read_sampler_settings(params)) {}

HandSet AntipodalSampler::sample(const Cloud& cloud, const RandomStream& random) const {
  return sample_hands(cloud, options_, random);
}

}  // namespace antipode::samplers
