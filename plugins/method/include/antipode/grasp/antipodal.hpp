#pragma once
/// @file
/// The near-antipodal check of ten Pas & Platt (Definition 3) and the labels it gives a hand
/// hypothesis (paper section 4, "Labeling Grasp Hypotheses"); see docs/classification.md.
///
/// Sign convention. Normals are outward (they point out of the object, towards the sensor
/// that saw the surface). The finger at +y closes along -closing, so it presses on surfaces
/// whose outward normal n points along +closing (n . closing >= cos theta): those points
/// *face the +y finger*. Likewise points with n . closing <= -cos theta face the -y finger,
/// which closes along +closing. Definition 3 asks for k points of each kind in the closing
/// region.
///
/// Contact patches. Definition 3 counts aligned points anywhere between the fingers, but a
/// closing finger first meets the points nearest to it: across a box's edge, the aligned
/// points of a rounded lip may lie between the fingers while the fingers meet the two faces
/// at 45 degrees, and the object squirts out. With `contact_depth_m` > 0, only the points
/// within that distance of each finger's first contact (the closing-region points farthest
/// along +closing for the +y finger, along -closing for the -y finger; with `contact_trim`,
/// a quantile from each end) are counted for it.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/hand.hpp"
#include "antipode/grasp/normals.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

struct AntipodalParameters {
  /// k: how many closing-region points each finger needs with a normal within theta of
  /// the closing direction (the paper: 6).
  int min_points = 6;
  /// theta in degrees, in (0, 90] (the paper: 20).
  double max_angle_deg = 20.0;
  /// Count, for each finger, only the points within this distance (m) of its first contact
  /// along the closing direction; 0 counts the whole closing region (the paper's
  /// Definition 3). See "Contact patches" above.
  double contact_depth_m = 0.005;
  /// Where each finger's first contact lies, as a quantile of the closing-region points along
  /// the closing direction, in [0, 0.45]: 0 is the point farthest towards the finger, 0.05 the
  /// point beyond which 5% of them lie (floor(0.05 (n - 1)) of the n points: none of 20 or
  /// fewer). A noisy cloud's farthest point is often a lone point a few millimetres off the
  /// surface, and a patch measured from it holds few of the surface's points (see
  /// docs/classification.md, contact patches). Used with `contact_depth_m` > 0.
  double contact_trim = 0.0;

  /// Throws antipode::Error naming the offending field.
  void validate() const;
};

/// How many closing-region points face each finger (see the sign convention above).
struct AntipodalCount {
  int facing_plus = 0;   ///< n . closing >= cos theta: contacts of the finger at +y
  int facing_minus = 0;  ///< n . closing <= -cos theta: contacts of the finger at -y
};

/// Counts the points `hand.closing_points` whose normal (`normals[i]`, indexed like the
/// cloud; zero vectors count for neither side) lies within `max_angle_deg` of +closing and
/// of -closing. Throws antipode::Error for an index outside `normals`.
AntipodalCount count_antipodal_normals(const Hand& hand,
                                       const std::vector<Eigen::Vector3f>& normals,
                                       double max_angle_deg);

/// The same, counting for each finger only its contact patch when
/// `parameters.contact_depth_m` > 0 (`points` are the cloud's, indexed like `normals`), its
/// first contact at the `parameters.contact_trim` quantile.
/// Throws antipode::Error for an index outside `points` or `normals`.
AntipodalCount count_antipodal_normals(const Hand& hand, const std::vector<Eigen::Vector3f>& points,
                                       const std::vector<Eigen::Vector3f>& normals,
                                       const AntipodalParameters& parameters);

/// The label for `count` with threshold k = `min_points`:
/// - kPositive: at least k points face each finger (Definition 3 holds);
/// - kIndeterminate: at least k face one finger only (another view could see the other side);
/// - kNegative: fewer than k face either finger, so no further view can make the hand near
///   antipodal (assuming its closing region was at least partly seen).
HandLabel antipodal_label(const AntipodalCount& count, int min_points);

/// A continuous score: min(facing_plus, facing_minus) / k, so kPositive <=> score >= 1.
double antipodal_score(const AntipodalCount& count, int min_points);

struct AntipodalLabellingOptions {
  AntipodalParameters antipodal;
  NormalEstimationOptions normals;  ///< its `threads` also sets the labelling's
};

/// The check for every hand of `set`: normals are estimated once, for the union of all
/// hands' closing points (estimate_normals), then each hand's points are counted, in
/// parallel. Returns one count per hand, in order; identical for any thread count. Throws
/// antipode::Error when the set has no cloud, a closing point is outside it, or the options
/// are invalid.
std::vector<AntipodalCount> count_antipodal_normals(const HandSet& set,
                                                    const AntipodalLabellingOptions& options);

}  // namespace antipode
