#pragma once
// The antipodal_sampler component: hand hypotheses by the paper's Algorithms 2 and 3.

#include "antipode/core/parameters.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/interfaces/sampler.hpp"

namespace antipode::samplers {

/// Preprocesses the cloud (workspace, voxels) and searches it for collision-free hands with
/// part of the cloud between their fingers (see sample_hands.hpp and docs/sampling.md).
/// Stateless after construction, so concurrent calls are safe.
class AntipodalSampler final : public Sampler {
 public:
  /// Throws antipode::Error (located in the YAML file) for unknown or invalid parameters.
  explicit AntipodalSampler(const Parameters& params);

  HandSet sample(const Cloud& cloud, const RandomStream& random,
                 const StopToken& stop) const override;

  /// The `hand` parameter's gripper (Baxter's by default).
  std::optional<HandGeometry> hand() const override { return options_.search.hand; }

  const HandSamplingOptions& options() const { return options_; }

 private:
  HandSamplingOptions options_;
};

}  // namespace antipode::samplers
