#pragma once
// The cluster_selector component: the paper's grasp selection (section 5.1) for a hand that
// is not yet on an arm - geometric filters, clusters of similar hands, one mean grasp per
// cluster, ranked by the tilt of the closing direction from the support, the distance from
// the gripper's aperture limits (criterion 2), the object's balance, then the classifier's
// score. The arm's criteria (joint limits, travel) extend this ranking when
// a robot is in the tree.

#include <memory>

#include "antipode/interfaces/grasp_selector.hpp"
#include "selection_options.hpp"

namespace antipode::selectors {

/// Criterion 2 of the paper: zero while the object is at least `margin_m` from both
/// aperture limits of `geometry` - `held_width_m` (held_width.hpp) from the narrow one,
/// `width_m` (the full extent) from the wide one - and (margin - distance)^2 closer to them.
double aperture_penalty(double held_width_m, double width_m, const HandGeometry& geometry,
                        double margin_m);

class ClusterSelector final : public GraspSelector {
 public:
  /// Parameters as in docs/selection.md; throws antipode::Error for unknown or invalid ones.
  explicit ClusterSelector(const Parameters& params);
  explicit ClusterSelector(const SelectionOptions& options);

  /// In order: hands already rejected or labelled otherwise than positive (or unknown) stay
  /// out; hands reaching below the support on their way in (kBelowSupport), whose width is
  /// outside the aperture (kApertureLimit), whose points fill too little of the fingers'
  /// height (kFingersOverAnEdge, finger_cover.hpp) or that would meet the object only at the
  /// fingertips (kWidestBeyondTheTips, contact_depth.hpp; when that leaves no grasp, the
  /// selection runs again without it) are dropped; the rest are clustered, best score
  /// first, and clusters smaller than the minimum dropped (kSmallCluster). Each cluster
  /// proposes its mean grasp, or its best hand where the mean's body or way in meets
  /// observed points; proposals are ranked by tilt, criterion 2 and balance (each deciding
  /// where the ones before tie within their tolerance), then score, those with a lever arm
  /// beyond `max_torque_arm_m` last (kUnbalanced unless no other grasp is kept), and the
  /// first `max_grasps` whose way in is free (and, with a robot, that the arm reaches) are
  /// the grasps. See GraspSelector::select for the layout of the result.
  HandSet select(const HandSet& hands, const SelectionContext& context) const override;

  /// select()'s checks of each hand on its own, but the fingertip one (which select() waives
  /// when nothing else is left): below the support, into the bin's walls, outside the
  /// aperture, fingers over an edge.
  HandSet screen(const HandSet& hands, const SelectionContext& context) const override;

 private:
  SelectionOptions options_;
  std::shared_ptr<const ArmReach> arm_;  // null for a free-floating hand
};

}  // namespace antipode::selectors
