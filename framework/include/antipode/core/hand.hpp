#pragma once
/// @file
/// A hand hypothesis: a pose of the gripper with its fingers fully open, plus what each
/// pipeline stage learned about it.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace antipode {

/// The classification label of a hand (paper section 4).
enum class HandLabel : std::uint8_t { kUnknown, kPositive, kNegative, kIndeterminate };

/// Why a stage dropped a hand. kNone means the hand is still a candidate.
enum class Rejection : std::uint8_t {
  kNone,
  kInCollision,
  kEmptyClosingRegion,
  kTooWide,
  kNotAntipodal,
  kLowScore,
  kNoIk,    ///< no collision-free inverse kinematics solution at the grasp
  kNoPlan,  ///< no motion to the grasp was found
  kOutOfWorkspace,
  kBelowSupport,         ///< the body or its approach from the stand-off reaches below the support
  kApertureLimit,        ///< the object is as wide as the opening or narrower than the closed hand
  kClustered,            ///< merged into a cluster's grasp (see Hand::merged_into)
  kSmallCluster,         ///< in a cluster with fewer hands than the selector's minimum
  kNotSelected,          ///< acceptable, but ranked below the grasps the selector returns
  kUnbalanced,           ///< too far from the object's centre of mass: it would turn out
  kNoIkAtPreGrasp,       ///< IK at the grasp, but none collision-free at the pre-grasp
  kOtherObject,          ///< on another object than the one the selection was asked for
  kFingersOverAnEdge,    ///< the object fills too little of the fingers' height: they clip an edge
  kWidestBeyondTheTips,  ///< the object widens beyond the fingertips: squeezed out past them
  /// A plugin's own reason, in its words (Hand::rejection_text; set with reject_for()): a
  /// third-party stage need not squeeze its criterion into one of the codes above.
  kPluginReason,
};

const char* to_string(HandLabel label);
const char* to_string(Rejection reason);

/// One hand hypothesis. The pose is X_FrameHand: hand frame expressed in `frame` (the
/// cloud's frame). Rotation columns are the approach (x), closing (y) and axis (z)
/// directions; the origin is the centre of the palm face (see hand_geometry.hpp).
struct Hand {
  Eigen::Isometry3d X_FrameHand = Eigen::Isometry3d::Identity();
  std::string frame = "base";
  double width_m = 0.0;  ///< extent of the object between the fingers along closing
  double score = 0.0;    ///< higher is better; meaning set by the last stage that scored it
  HandLabel label = HandLabel::kUnknown;
  Rejection rejection = Rejection::kNone;
  /// With kPluginReason, the plugin's reason ("too tilted"); empty otherwise.
  std::string rejection_text;
  std::int32_t sample_index = -1;            ///< which surface sample produced this hand
  std::vector<std::int32_t> closing_points;  ///< indices into the cloud, inside the closing region
  /// Selection only: for a hand rejected as kClustered, the index (in the selection's hand
  /// list) of the grasp it was merged into; -1 otherwise.
  std::int32_t merged_into = -1;
  /// The id of the object the hand closes on (the hand set's `objects`: the segment holding
  /// most of its closing points); -1 when the sampler did not segment the scene or the hand
  /// holds no object's points.
  std::int32_t object = -1;

  Eigen::Vector3d approach() const { return X_FrameHand.linear().col(0); }
  Eigen::Vector3d closing() const { return X_FrameHand.linear().col(1); }
  Eigen::Vector3d axis() const { return X_FrameHand.linear().col(2); }
  Eigen::Vector3d position_m() const { return X_FrameHand.translation(); }
};

/// Rejects `hand` for a reason of the caller's own: kPluginReason with `reason` as its text
/// ("too tilted": a short phrase, as the codes' names are). Control characters become
/// spaces, and a reason spelt as a code's name ("low score", "none") gets " (a plugin's)"
/// added, so that it is never counted as that code.
void reject_for(Hand& hand, std::string reason);

/// Why `hand` was rejected, as printed and written: its rejection_text for kPluginReason
/// ("a plugin's reason" when that is empty), else to_string(hand.rejection).
std::string rejection_reason(const Hand& hand);

/// "12 clustered into another grasp, 3 in collision": how many of `hands` each rejection
/// dropped, most frequent first (ties by name); hands without one are counted as "none"
/// when `count_kept`, else left out. "no hands" when nothing is counted.
std::string rejection_counts(const std::vector<Hand>& hands, bool count_kept = true);

}  // namespace antipode
