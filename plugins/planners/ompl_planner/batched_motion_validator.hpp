#pragma once
// OMPL's motion validator for an arm in an ArmCollisionWorld: the straight joint-space segment
// between two states is cut every `resolution_rad` (as OMPL's DiscreteMotionValidator cuts it),
// and its states are checked as one batch (ArmCollisionWorld::first_contact: the spheres test
// 16 of them at a time) instead of one OMPL validity call each, in rake order when only
// whether the segment is free matters (segment_states.hpp).
//
// Units: radians (metres for prismatic joints). Threads: as the world's check(); the counter
// of checked states is atomic, and each thread keeps its own buffer of a motion's states.

#include <atomic>
#include <cstddef>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>

#include "arm_collision_world.hpp"

namespace antipode::planning {

class BatchedMotionValidator : public ompl::base::MotionValidator {
 public:
  /// `checks` counts the states checked (a segment's up to its first contact in checking order)
  /// (shared with the planner's own count); `rake` false checks every segment in order (the
  /// baseline).
  BatchedMotionValidator(const ompl::base::SpaceInformationPtr& si,
                         const collision::ArmCollisionWorld& world, double resolution_rad,
                         bool rake, std::atomic<long>& checks);

  /// True when every state after s1 up to s2 is free (s1 is taken to be valid, as OMPL does).
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  /// The same; when not free, the last free state before the first contact and its fraction
  /// of the way.
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

 private:
  // The index, in checking order, of the first of the segment's `steps` states after s1 in
  // contact (steps when none is); states in rake order over `lanes` (0: in order).
  std::size_t first_contact(const ompl::base::State* s1, const ompl::base::State* s2,
                            std::size_t lanes, std::size_t& steps) const;

  const collision::ArmCollisionWorld& world_;
  double resolution_rad_;
  bool rake_;
  std::atomic<long>& checks_;
};

}  // namespace antipode::planning
