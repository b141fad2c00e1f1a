#pragma once
// What the pipeline nodes check of a plugin's output before passing it on. A third-party
// sampler, selector or planner that returns something broken (a pose with NaNs, a hand in
// another frame, a grasp made of nothing it was given, a trajectory whose waypoints do not
// match its joints) fails its node with one of these reasons instead of sending the broken
// value down the tree, where it would surface far from its cause or move the robot.
// Each *_problem function returns "" when nothing is wrong.

#include <optional>
#include <string>

#include "antipode/core/error.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/stop_token.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode::pipeline {

/// Runs `call` (a plugin's method): nullopt when it returns, the message when it throws
/// antipode::Error. An InternalError and a cancellation pass through (the node fails as
/// cancelled; an internal error stops the run).
template <typename Call>
std::optional<std::string> plugin_error(Call&& call) {
  try {
    call();
  } catch (const InternalError&) {
    throw;
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& error) {
    return std::string(error.what());
  }
  return std::nullopt;
}

/// The pose of `hand` (named `which` in the reason, e.g. "hand 3"): finite, its rotation
/// orthonormal and right-handed (within 1e-6).
std::string pose_problem(const Hand& hand, const std::string& which);

/// A sampler's result: a cloud when there are hands, every hand in that cloud's frame with a
/// valid pose, a finite width and closing points inside the cloud.
std::string sampling_problem(const HandSet& hands);

/// A selector's result for `given`: the same cloud, and every grasp (the leading hands
/// without a rejection) in its frame with a valid pose, placed within the bounding box of the
/// candidates it was given (hands without a rejection labelled positive or unknown; 1 mm
/// slack): a grasp is one of them or a mean of some.
std::string selection_problem(const HandSet& given, const HandSet& selection);

/// A selector's screen of `given`: the same cloud and hands in the same order, each with its
/// pose, score and label, and its rejection unless that was kNone.
std::string screening_problem(const HandSet& given, const HandSet& screened);

/// A planner's solved result: a finite final pose, and a trajectory with at least one
/// waypoint, one position per joint in each, finite values and non-decreasing times.
std::string plan_problem(const Eigen::Isometry3d& X_BaseHand, const Trajectory& trajectory);

}  // namespace antipode::pipeline
