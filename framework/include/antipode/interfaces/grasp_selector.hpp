#pragma once
/// @file
/// GraspSelector: picks and ranks grasps from classified hands (paper section 5.1).

#include <vector>

#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

class GraspSelector : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kGraspSelector; }

  /// Returns the grasps worth trying, best first. Hands with a rejection are never returned.
  /// An empty result means no grasp was found (not an error).
  virtual std::vector<Hand> select(const HandSet& hands) const = 0;
};

}  // namespace antipode
