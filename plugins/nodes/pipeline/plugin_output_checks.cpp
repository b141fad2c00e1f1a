#include "plugin_output_checks.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "antipode/interfaces/grasp_selector.hpp"

namespace antipode::pipeline {
namespace {

std::string point_text(const Eigen::Vector3d& p) {
  std::ostringstream text;
  text.precision(3);
  text << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return text.str();
}

}  // namespace

std::string pose_problem(const Hand& hand, const std::string& which) {
  if (!hand.X_FrameHand.matrix().allFinite()) return "gave " + which + " a pose that is not finite";
  const Eigen::Matrix3d r = hand.X_FrameHand.linear();
  if (!(r.transpose() * r).isIdentity(1e-4) || r.determinant() < 0.0)
    return "gave " + which + " a rotation that is not orthonormal and right-handed";
  return "";
}

std::string sampling_problem(const HandSet& set) {
  if (set.hands.empty()) return "";
  if (!set.cloud) return "returned hands without the cloud they index";
  const Cloud& cloud = *set.cloud;
  for (std::size_t i = 0; i < set.hands.size(); ++i) {
    const Hand& hand = set.hands[i];
    if (std::string problem = pose_problem(hand, "hand " + std::to_string(i)); !problem.empty())
      return problem;
    if (hand.frame != cloud.frame)
      return "put hand " + std::to_string(i) + " in frame '" + hand.frame + "', not its cloud's '" +
             cloud.frame + "'";
    if (!std::isfinite(hand.width_m) || hand.width_m < 0.0)
      return "gave hand " + std::to_string(i) + " a width that is not a length";
    for (const std::int32_t point : hand.closing_points) {
      if (point < 0 || static_cast<std::size_t>(point) >= cloud.size())
        return "gave hand " + std::to_string(i) + " closing point " + std::to_string(point) +
               " of a cloud of " + std::to_string(cloud.size());
    }
  }
  return "";
}

std::string selection_problem(const HandSet& given, const HandSet& selection) {
  if (selection.cloud != given.cloud) return "returned its selection with another cloud";
  Eigen::AlignedBox3d candidates;
  for (const Hand& hand : given.hands) {
    if (selectable(hand) && hand.X_FrameHand.translation().allFinite())
      candidates.extend(hand.X_FrameHand.translation());
  }
  const Eigen::Vector3d slack = Eigen::Vector3d::Constant(0.001);
  for (std::size_t i = 0; i < selection.hands.size(); ++i) {
    const Hand& grasp = selection.hands[i];
    if (grasp.rejection != Rejection::kNone) break;
    if (std::string problem = pose_problem(grasp, "grasp " + std::to_string(i)); !problem.empty())
      return problem;
    if (given.cloud && grasp.frame != given.cloud->frame)
      return "put grasp " + std::to_string(i) + " in frame '" + grasp.frame +
             "', not the hands' '" + given.cloud->frame + "'";
    const Eigen::Vector3d at = grasp.X_FrameHand.translation();
    if (candidates.isEmpty() ||
        !Eigen::AlignedBox3d(candidates.min() - slack, candidates.max() + slack).contains(at))
      return "chose grasp " + std::to_string(i) + " at " + point_text(at) +
             ", away from every hand it was given to choose from";
  }
  return "";
}

std::string screening_problem(const HandSet& given, const HandSet& screened) {
  if (screened.cloud != given.cloud) return "returned its screen with another cloud";
  if (screened.hands.size() != given.hands.size())
    return "returned " + std::to_string(screened.hands.size()) + " hands for " +
           std::to_string(given.hands.size());
  for (std::size_t i = 0; i < given.hands.size(); ++i) {
    const Hand& before = given.hands[i];
    const Hand& after = screened.hands[i];
    if (!after.X_FrameHand.matrix().isApprox(before.X_FrameHand.matrix()) ||
        after.score != before.score || after.label != before.label)
      return "changed hand " + std::to_string(i) + " (a screen only sets rejections)";
    if (before.rejection != Rejection::kNone &&
        (after.rejection != before.rejection || after.rejection_text != before.rejection_text))
      return "changed the rejection of hand " + std::to_string(i) + " from '" +
             rejection_reason(before) + "'";
  }
  return "";
}

std::string plan_problem(const Eigen::Isometry3d& X_BaseHand, const Trajectory& trajectory) {
  if (!X_BaseHand.matrix().allFinite()) return "planned a grasp pose that is not finite";
  if (trajectory.positions_rad.empty()) return "returned a solved plan without waypoints";
  if (trajectory.times_s.size() != trajectory.positions_rad.size())
    return "returned " + std::to_string(trajectory.times_s.size()) + " times for " +
           std::to_string(trajectory.positions_rad.size()) + " waypoints";
  for (std::size_t w = 0; w < trajectory.positions_rad.size(); ++w) {
    const std::string which = "waypoint " + std::to_string(w);
    if (trajectory.positions_rad[w].size() != trajectory.joint_names.size())
      return "returned " + which + " with " + std::to_string(trajectory.positions_rad[w].size()) +
             " positions for " + std::to_string(trajectory.joint_names.size()) + " joints";
    for (const double q : trajectory.positions_rad[w]) {
      if (!std::isfinite(q)) return "returned " + which + " with a position that is not finite";
    }
    if (!std::isfinite(trajectory.times_s[w]) ||
        (w > 0 && trajectory.times_s[w] < trajectory.times_s[w - 1]))
      return "returned " + which + " at a time before the waypoint before it";
  }
  return "";
}

}  // namespace antipode::pipeline
