#pragma once
// The states a straight joint-space motion is checked at, in the order they are checked.
//
// A motion is cut every `resolution_rad` (as OMPL's DiscreteMotionValidator cuts it). Whether
// it is free does not depend on the order its states are checked in, but the time does: a
// motion that meets an obstacle meets it over a stretch of consecutive states, and the
// planner's motions mostly do (RRTConnect tries long extensions into clutter). Checked from
// the start, every state before the stretch is checked first. Checked as a rake, the motion's
// states are cut into `lanes` teeth of consecutive states (as equal as whole states allow);
// the first batch holds each tooth's last state, the next batch the states before those, and
// so on. The first batch - the spheres' SIMD batch of 16 - is spread evenly along the motion,
// ends at its last state (the new state of an extension, which OMPL's own validator checks
// first), and lands in any stretch at least as long as a tooth. VAMP (Thomason et al., ICRA
// 2024) checks its motions in this spirit.
//
// Units: radians (metres for prismatic joints). Threads: pure functions, except that
// segment_states() reuses a per-thread buffer for the order.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace antipode::planning {

/// The order in which to check `steps` states: a permutation of 0 .. steps - 1. With
/// teeth = min(lanes, steps), tooth t holds the states from t * steps / teeth up to (not
/// including) (t + 1) * steps / teeth (integer division); the order takes the last state of
/// every tooth, then the one before it in every tooth that has one, and so on. `lanes` 0
/// keeps the states in order (as does `lanes` 1); steps 0 gives an empty order.
std::vector<std::size_t> rake_order(std::size_t steps, std::size_t lanes);

/// The motion from `a` to `b` (same size, finite) cut every `resolution_rad` (> 0, finite):
/// the states a + (b - a) * (i / steps) for i = 1 .. steps (from i = 0 with `include_start`),
/// steps = max(1, ceil(|b - a| / resolution_rad)), in rake_order() over `lanes` (0: in order).
/// Writes into `states` (resized; its vectors are reused).
void segment_states(const Eigen::Ref<const Eigen::VectorXd>& a,
                    const Eigen::Ref<const Eigen::VectorXd>& b, double resolution_rad,
                    bool include_start, std::size_t lanes, std::vector<Eigen::VectorXd>& states);

}  // namespace antipode::planning
