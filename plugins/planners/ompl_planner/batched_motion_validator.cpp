#include "batched_motion_validator.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace antipode::planning {

namespace ob = ompl::base;

BatchedMotionValidator::BatchedMotionValidator(const ob::SpaceInformationPtr& si,
                                               const collision::ArmCollisionWorld& world,
                                               double resolution_rad, std::atomic<long>& checks)
    : ob::MotionValidator(si), world_(world), resolution_rad_(resolution_rad), checks_(checks) {}

std::size_t BatchedMotionValidator::first_contact(const ob::State* s1, const ob::State* s2,
                                                  std::size_t& steps) const {
  const auto* a = s1->as<ob::RealVectorStateSpace::StateType>();
  const auto* b = s2->as<ob::RealVectorStateSpace::StateType>();
  const auto dof = Eigen::Index(si_->getStateDimension());
  const Eigen::Map<const Eigen::VectorXd> qa(a->values, dof), qb(b->values, dof);
  steps = std::size_t(std::max(1.0, std::ceil((qb - qa).norm() / resolution_rad_)));
  thread_local std::vector<Eigen::VectorXd> states;
  states.resize(steps);
  for (std::size_t i = 0; i < steps; ++i)
    states[i] = qa + (qb - qa) * (double(i + 1) / double(steps));
  checks_ += long(steps);
  return world_.first_contact(states);
}

bool BatchedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  std::size_t steps = 0;
  const bool free = first_contact(s1, s2, steps) == steps;
  if (free)
    ++valid_;
  else
    ++invalid_;
  return free;
}

bool BatchedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                         std::pair<ob::State*, double>& last_valid) const {
  std::size_t steps = 0;
  const std::size_t contact = first_contact(s1, s2, steps);
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
