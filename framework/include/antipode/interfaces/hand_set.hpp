#pragma once
/// @file
/// What flows from the sampler through the classifier to the selector.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"
#include "antipode/geometry/scene_layout.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode {

/// What the hands' scores (Hand::score) say.
enum class ScoreMeaning : std::uint8_t {
  kOrder,  ///< higher is better, and nothing more (a decision value, a sampler's score)
  /// The score of each hand the classifier scored (those without an earlier rejection) is a
  /// calibrated probability, in [0, 1], that the grasp holds (a classifier trained on
  /// outcomes): a selector may weigh score differences against other criteria.
  kProbability,
};

/// Hands together with the (preprocessed) cloud their `closing_points` index into, the
/// gripper geometry they were found for (a classifier that images the closing region, such
/// as the HOG + SVM one, needs its extent; the cell executes that gripper) and the support
/// plane the sampler found in the cloud, if any (in the cloud's frame).
struct HandSet {
  std::shared_ptr<const Cloud> cloud;
  std::vector<Hand> hands;
  HandGeometry geometry;
  std::optional<SupportPlane> support;
  /// The objects the sampler found standing on the support (scene_layout.hpp), which the
  /// hands' `object` ids name; empty when it did not segment the scene.
  std::vector<SceneObject> objects{};
  /// What the hands' scores say; the stage that scores them sets it (a classifier), and a
  /// stage that passes them on keeps it.
  ScoreMeaning scores = ScoreMeaning::kOrder;
};

/// How hand sets travel between behaviour-tree nodes: shared and immutable; a stage that
/// changes hands (a classifier) writes a new set.
using HandSetPtr = std::shared_ptr<const HandSet>;

}  // namespace antipode
