#pragma once
// The antipodal_sampler's YAML parameters (documented in docs/sampling.md).

#include "antipode/core/parameters.hpp"
#include "antipode/geometry/sample_hands.hpp"

namespace antipode::samplers {

/// Reads and validates every parameter; unknown keys and invalid values are antipode::Error
/// located in the YAML file.
HandSamplingOptions read_sampler_settings(const Parameters& params);

}  // namespace antipode::samplers
