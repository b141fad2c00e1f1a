#pragma once
/// @file
/// What flows from the sampler through the classifier to the selector.

#include <memory>
#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"

namespace antipode {

/// Hands together with the (preprocessed) cloud their `closing_points` index into and the
/// gripper geometry they were found for (a classifier that images the closing region, such
/// as the HOG + SVM one, needs its extent).
struct HandSet {
  std::shared_ptr<const Cloud> cloud;
  std::vector<Hand> hands;
  HandGeometry geometry;
};

/// How hand sets travel between behaviour-tree nodes: shared and immutable; a stage that
/// changes hands (a classifier) writes a new set.
using HandSetPtr = std::shared_ptr<const HandSet>;

}  // namespace antipode
