#pragma once
// Clouds of synthetic shapes seen by sensors at given positions, and hands placed by hand.

#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"

namespace antipode::testing {

/// A shape centred at the given point, as a sensor at the origin sees it.
using Shape = std::function<Cloud(const Eigen::Vector3d& centre_m)>;

/// `shape` centred at `centre_m`, seen by a sensor at each of `sensors_m` (view v at
/// sensors_m[v]); a point seen by several views appears once per view, with its view's bit.
Cloud seen_from(const Shape& shape, const Eigen::Vector3d& centre_m,
                const std::vector<Eigen::Vector3d>& sensors_m);

/// A hand with the given approach and closing directions and palm-face centre, with the
/// closing points of the default hand geometry (HandGeometry{}) in `cloud`.
Hand hand_at(const Cloud& cloud, const Eigen::Vector3d& approach, const Eigen::Vector3d& closing,
             const Eigen::Vector3d& palm_m);

}  // namespace antipode::testing
