#pragma once
// The parameters of cluster_selector (docs/selection.md).

#include <cstddef>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "antipode/core/parameters.hpp"
#include "arm_reach.hpp"
#include "bin_walls.hpp"

namespace antipode::selectors {

struct SelectionOptions {
  /// Where the cell starts its approach, back along the approach from the grasp pose: the
  /// way from there must be free of observed points and clear of the support.
  double standoff_m = 0.10;
  /// How far above the support every corner of the hand must stay, at the grasp and on its
  /// way in.
  double clearance_m = 0.005;
  /// The support's height in the hands' frame (a plane z = support_z_m, normal +z) for hand
  /// sets whose sampler found no support plane; unset: no support check then.
  std::optional<double> support_z_m;
  /// The bin the objects lie in (a clutter box), when the cell has one: hands that reach
  /// into its walls are dropped (kInCollision), see bin_walls.hpp.
  std::optional<Bin> bin;
  /// Hands whose palm-face centres are this close and whose approach and closing directions
  /// are within `cluster_angle_deg` of each other (closing up to its sign) form a cluster.
  double cluster_distance_m = 0.02;
  double cluster_angle_deg = 20.0;
  /// Clusters with fewer hands are dropped (the paper: "a specified minimum number").
  std::size_t min_cluster_size = 3;
  /// First, the tilt of the closing direction from the support (closing_tilt.hpp): the
  /// penalty is zero up to this angle and grows quadratically (rad^2) beyond.
  double tilt_free_deg = 15.0;
  /// Tilt penalties closer than this (rad^2) tie, and the next criterion decides.
  double tilt_tolerance_rad2 = 1e-4;
  /// The way in must pass through space a sensor saw (hand_clearance.hpp): a probe more
  /// than `occlusion_margin_m` behind an observed surface in every view blocks it, with
  /// each point standing for a disc of `point_radius_m` (the sampler's defaults). With
  /// `unseen_is_free`, space no sensor saw counts as free.
  double occlusion_margin_m = 0.01;
  double point_radius_m = 0.0025;
  bool unseen_is_free = false;
  /// Criterion 2: the penalty of a grasp is zero while the object's width stays this far
  /// from both aperture limits, and grows quadratically closer to them.
  double aperture_margin_m = 0.005;
  /// The narrow side of the aperture is judged on the width the fingers will meet: the
  /// closing-region points' extent between this quantile and its complement (held_width.hpp);
  /// the wide side on the full extent.
  double width_trim = 0.05;
  /// The narrow side is judged after the squeeze (held_width.hpp): the closing direction
  /// turned about the approach or the hand axis downhill to the nearest local minimum of
  /// the width, at most this far (degrees; 0: the width along the hand's own closing
  /// direction). 20 degrees, the near-antipodal check's own tolerance: a part whose faces
  /// lie within it of the fingers' may turn that far. Further turns mostly follow the back
  /// of a one-view cloud that was never seen (half a cylinder narrows as it turns).
  double squeeze_turn_deg = 20.0;
  /// The closing-region points must span at least this share of the fingers' height along
  /// the hand axis (finger_cover.hpp), else kFingersOverAnEdge: fingers that only clip an
  /// object's rim or edge push it out.
  double min_finger_cover = 0.9;
  /// Each finger's contact patch must start at least this far (m) back from the fingertips
  /// (contact_depth.hpp), else kWidestBeyondTheTips: an object still widening at the tips is
  /// pushed out past them. 0: no check.
  double fingertip_margin_m = 0.01;
  /// When that check leaves no grasp, select again without it: an attempt that may push the
  /// object out beats giving up on it.
  bool fingertip_last_resort = true;
  /// With a segmented scene (the hand set's objects): at most this many grasps per object
  /// (0: no limit), as a clear-the-box policy wants a choice on every object.
  std::size_t grasps_per_object = 0;
  /// The object of interest: grasps on others are dropped (kOtherObject). By id (-1: any) or
  /// as the object whose centroid lies nearest a point (cloud frame).
  std::int32_t object = -1;
  std::optional<Eigen::Vector3d> near_m;
  /// Then balance: the penalty is zero while gravity's lever arm about the closing axis
  /// (from the centroid of the object points within `object_radius_m`) is at most this,
  /// and grows quadratically beyond (grasp_balance.hpp).
  double balance_free_m = 0.02;
  /// Grasps whose lever arm exceeds this are dropped (kUnbalanced), the object would turn
  /// out of the fingers, unless no other grasp remains: then they are the grasps.
  double max_torque_arm_m = 0.03;
  double object_radius_m = 0.15;
  /// Penalties closer than this (m^2) tie, and the next criterion decides; the last is the
  /// cluster's score.
  double penalty_tolerance_m2 = 1e-6;
  /// When the hands' scores are probabilities of success (HandSet::scores, as
  /// `hog_svm_classifier` gives them with a grasp-success model), the clusters' mean member
  /// score is the first criterion, scores closer than this tying so that tilt, aperture and
  /// balance decide; 0 keeps the score last. Scores that are only an order always come last.
  double score_first_tolerance = 0.05;
  /// How many grasps to return.
  std::size_t max_grasps = 10;
  /// Workers for the checks of each hand (steps 1-3, and the screen); 0: one per core. The
  /// result is the same for any number.
  int threads = 0;
  /// The arm (arm_reach.hpp): with a robot file, a grasp is kept only when the arm reaches
  /// it and its stand-off free of collisions (kNoIk, kNoIkAtPreGrasp, kInCollision otherwise).
  ArmReachOptions arm;
};

/// Reads the component's parameters; throws antipode::Error located at the bad key.
SelectionOptions read_selection_options(const Parameters& params);

}  // namespace antipode::selectors
