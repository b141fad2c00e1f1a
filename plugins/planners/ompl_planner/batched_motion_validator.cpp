#include "batched_motion_validator.hpp"

#include <algorithm>
#include <vector>

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include "segment_states.hpp"
#include "sphere_kernels.hpp"

namespace antipode::planning {

namespace ob = ompl::base;

BatchedMotionValidator::BatchedMotionValidator(const ob::SpaceInformationPtr& si,
                                               const collision::ArmCollisionWorld& world,
                                               double resolution_rad, bool rake,
                                               std::atomic<long>& checks)
    : ob::MotionValidator(si),
      world_(world),
      resolution_rad_(resolution_rad),
      rake_(rake),
      checks_(checks) {}

std::size_t BatchedMotionValidator::first_contact(const ob::State* s1, const ob::State* s2,
                                                  std::size_t lanes, std::size_t& steps) const {
  const auto* a = s1->as<ob::RealVectorStateSpace::StateType>();
  const auto* b = s2->as<ob::RealVectorStateSpace::StateType>();
  const auto dof = Eigen::Index(si_->getStateDimension());
  const Eigen::Map<const Eigen::VectorXd> qa(a->values, dof), qb(b->values, dof);
  thread_local std::vector<Eigen::VectorXd> states;  // reused, motion after motion
  segment_states(qa, qb, resolution_rad_, false, lanes, states);
  steps = states.size();
  const std::size_t contact = world_.first_contact(states);
  checks_ += long(std::min(contact + 1, steps));  // up to the first contact, in checking order
  return contact;
}

bool BatchedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  std::size_t steps = 0;
  // Whether the segment is free does not depend on the order: check it as a rake.
  const bool free = first_contact(s1, s2, rake_ ? collision::kBatchLanes : 0, steps) == steps;
  if (free)
    ++valid_;
  else
    ++invalid_;
  return free;
}

bool BatchedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                         std::pair<ob::State*, double>& last_valid) const {
  std::size_t steps = 0;
  const std::size_t contact = first_contact(s1, s2, 0, steps);  // in order: the first contact
  if (contact == steps) {
    ++valid_;
    return true;
  }
  ++invalid_;
  last_valid.second = double(contact) / double(steps);  // the state before the contact
  if (last_valid.first != nullptr)
    si_->getStateSpace()->interpolate(s1, s2, last_valid.second, last_valid.first);
  return false;
}

}  // namespace antipode::planning
