#pragma once
/// @file
/// Sampler: cloud in, hand hypotheses out (paper section 3).

#include <optional>

#include "antipode/core/hand_geometry.hpp"
#include "antipode/core/random.hpp"
#include "antipode/core/stop_token.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

class Sampler : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kSampler; }

  /// Returns hand hypotheses that satisfy the sampler's necessary geometric conditions.
  ///
  /// Contract: `cloud` is in any frame; the returned HandSet's cloud is the cloud the hands
  /// refer to (the sampler may preprocess it) and every hand's `frame` equals its frame.
  /// The result depends only on `cloud`, the sampler's parameters and `random`'s seed - not
  /// on the number of threads. Throws antipode::Error for unusable input (no finite point,
  /// nothing in the workspace) and Cancelled when `stop` asks to stop. May be called
  /// concurrently from several trees.
  virtual HandSet sample(const Cloud& cloud, const RandomStream& random,
                         const StopToken& stop) const = 0;

  /// The gripper this sampler finds hands for (the `geometry` of every HandSet it returns),
  /// or nothing when it cannot say before sampling. A tree checks its classifiers against it
  /// when it loads (Classifier::hand_problem). Const and thread-safe.
  virtual std::optional<HandGeometry> hand() const { return std::nullopt; }
};

}  // namespace antipode
