#pragma once
/// @file
/// The hand search of the paper (Algorithms 2 and 3): sample points of a preprocessed cloud,
/// estimate each one's Darboux frame, and search a grid of hand poses around it for hands
/// that do not collide with the cloud and hold part of it between their fingers.
///
/// The algorithm, its parameters and its rejection reasons are described in
/// docs/sampling.md; the pose convention in docs/pose-convention.md.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"
#include "antipode/core/random.hpp"
#include "antipode/geometry/axis_box.hpp"
#include "antipode/geometry/local_frame.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode {

/// Whether the search looks for a support plane (see support_plane.hpp).
enum class SupportPlaneMode : std::uint8_t {
  kNone,  ///< no support: every point may be sampled, hands are limited by points alone
  kAuto,  ///< find the dominant plane with the cloud on its sensor side and treat it as solid
};

struct HandSearchParameters {
  HandGeometry hand;
  /// Points sampled from the cloud (from those in `sample_region`), without replacement; all
  /// of them when there are fewer.
  std::size_t samples = 4000;
  /// Where samples are drawn from; unset: anywhere. The whole cloud still counts for
  /// collisions, so a region around the objects avoids hands on the artificial edges a
  /// workspace crop leaves (e.g. at a table's cut border) without hiding obstacles.
  std::optional<AxisBox> sample_region;
  /// Radius of the ball the Darboux frame is fitted to (the paper's 3 cm).
  double frame_radius_m = 0.03;
  LocalFrameOptions frame;
  /// Hand orientations about the curvature axis, evenly spaced over [-90, 90) degrees from
  /// approaching against the surface normal.
  int orientations = 8;
  /// Tilted approaches, for a robot arm that cannot put its wrist low beside an object (a
  /// flange wider than the hand's height above the support): with a support plane, the
  /// sample's frame is also turned about its binormal by each of these angles (degrees, in
  /// (0, 80]), in the direction that lowers the approach, and searched over the orientations
  /// within `tilted_orientation_range_deg` of phi = 0. At phi = 0 the fingers still close along
  /// the binormal, so on an upright cylinder the hand comes down at the angle and closes
  /// level across it; the paper's hands (the axis along the curvature axis) approach such a
  /// cylinder only level. Samples whose curvature axis is within 15 degrees of level (a
  /// tilt would turn the approach sideways, not down) and clouds without a support plane
  /// get no tilted hands. Empty: the paper's search alone.
  std::vector<double> approach_tilts_deg;
  double tilted_orientation_range_deg = 25.0;
  /// Hand positions along the closing direction, evenly spaced so that the sample lies
  /// between the fingers in all of them.
  int positions = 20;
  /// How far the object must reach between the fingers (from the fingertips towards the
  /// palm) once the hand has been pushed forward until contact. An object wider than the
  /// aperture stops the fingertips early and reaches less far in: with half the finger
  /// depth, cylinders wider than about 7.3 cm give no hand for a 7.2 cm aperture. The default
  /// is half Baxter's finger depth; the `antipodal_sampler` plugin takes half the depth of
  /// its own `hand` unless told otherwise.
  double min_bite_m = 0.03;
  /// How far the hand backs off from the contact that stopped it.
  double clearance_m = 0.001;
  /// With a support plane, the push also stops where the lowest point of the hand's body
  /// comes within this distance of the plane, as it stops at a cloud point: the plane is
  /// solid even where the support's points were removed. A pose whose body starts closer is
  /// rejected (`below_support`).
  double support_clearance_m = 0.005;
  /// How far the object must reach between the fingers in a hand the support stopped (in
  /// place of `min_bite_m`): the fingers then hold a low object down to where they may go,
  /// so a 2.5 cm-high object lying on the table can still be taken from above. The default is
  /// half `min_bite_m` (the plugin's: half its own `min_bite_m`).
  double min_bite_at_support_m = 0.015;
  /// A hand must approach from within this angle of the direction towards a sensor that saw
  /// its sample (the side of the surface that was observed). 180 disables the check.
  double max_view_angle_deg = 90.0;
  /// Reject a hand when a part of a finger lies in space the sensors could not see: more than
  /// `occlusion_margin_m` behind an observed surface in every view (see occlusion.hpp). A
  /// single view shows only the front of an object; a finger placed behind it would meet
  /// the unseen back (a 10 cm cylinder seen from the front "fits" a 7 cm hand approaching
  /// from the side). Tested at three points along each finger's middle.
  bool reject_hidden_fingers = true;
  double occlusion_margin_m = 0.01;
  /// Radius of the surface patch a cloud point stands for in the occlusion test (about the
  /// voxel size).
  double point_radius_m = 0.0025;
  /// false: per sample and orientation, keep one hand, the middle position of the longest
  /// run of consecutive acceptable positions (the hand best centred on the object);
  /// true: keep every acceptable position.
  bool keep_all_positions = false;
  /// kAuto: find the support plane the objects stand on (find_support_plane, with
  /// `support.distance_m` as the inlier distance); when there is one, points within that
  /// distance of it (or below it) are not sampled, and the plane is a solid half-space the
  /// hand's body keeps `support_clearance_m` away from, even where the cloud has no points
  /// (beyond a cropped scene's cut edge, in the shadow of an object).
  SupportPlaneMode support_plane = SupportPlaneMode::kAuto;
  SupportPlaneOptions support;
  /// For a cloud without view origins: unset - seen from (0, 0, 0); set - seen from all
  /// around (an object-centred cloud): each point from the direction away from this
  /// centre, with no support plane. Ignored for clouds with view origins.
  std::optional<Eigen::Vector3f> outward_from_m;
  /// Worker threads (0: as many as the hardware has). Results do not depend on it.
  int threads = 0;

  /// Throws antipode::Error naming the first invalid field (including the hand geometry).
  void validate() const;
};

/// What happened to the samples and hand poses of one search (for "why no hand?").
struct HandSearchStats {
  std::size_t samples = 0;              ///< points sampled
  std::size_t frames_quadric = 0;       ///< samples with a Taubin-quadric frame
  std::size_t frames_planar = 0;        ///< samples with a principal-component frame
  std::size_t skipped_too_few = 0;      ///< samples skipped: too few neighbours
  std::size_t skipped_collinear = 0;    ///< samples skipped: neighbours along a line
  std::size_t orientations_unseen = 0;  ///< orientations approaching from the unobserved side
  std::size_t poses = 0;                ///< hand poses searched (orientation x position)
  std::size_t in_collision = 0;         ///< poses colliding before they could move forward
  std::size_t empty = 0;                ///< poses with nothing between the fingers
  std::size_t too_shallow = 0;          ///< poses where the object reaches less than min_bite
  std::size_t hidden = 0;               ///< poses with a finger in space no sensor saw
  std::size_t below_support = 0;        ///< poses reaching below the support plane
  std::size_t on_support = 0;           ///< cloud points not sampled: on or below the support
  std::size_t acceptable = 0;           ///< poses meeting every condition
  std::size_t hands = 0;                ///< hands returned
  std::size_t tilted_hands = 0;         ///< of which in a tilted frame (approach_tilts_deg)

  HandSearchStats& operator+=(const HandSearchStats& other);
};

struct HandSearchResult {
  /// In sample order, then orientation, then position. Each hand has: X_FrameHand, frame =
  /// the cloud's frame, sample_index = the index in the cloud of the point that produced it,
  /// closing_points = indices of the cloud's points in its closing region (never empty),
  /// width_m = their extent along the closing direction, score = how far the object
  /// reaches between the fingers (metres), label kUnknown, rejection kNone.
  std::vector<Hand> hands;
  /// Index in the cloud of each sampled point, in sample order.
  std::vector<std::int32_t> sample_points;
  HandSearchStats stats;
  /// The support plane found (SupportPlaneMode::kAuto), if any.
  std::optional<SupportPlane> support_plane;
};

/// What the caller already knows about the scene (see scene_layout.hpp).
struct SearchScene {
  /// The support to use; unset: found by the search (SupportPlaneMode::kAuto) or none.
  std::optional<SupportPlane> support;
  /// The only points samples are drawn from (indices into the cloud, e.g. the objects'
  /// points); unset: every point the region and the support allow.
  std::optional<std::vector<std::int32_t>> sample_points;
};

/// Runs the hand search on `cloud`, which should already be preprocessed (finite points,
/// workspace, voxels: see preprocess.hpp). Normals are oriented towards the views in each
/// point's view mask. A cloud without view masks counts as seen by view 0 alone; a cloud
/// without view origins as seen from (0, 0, 0), with no occlusion test (sample_hands()
/// supplies a configurable origin instead).
///
/// Deterministic: the result depends on the cloud, the parameters (not `threads`) and
/// `random`'s seed only (and `scene`). Throws antipode::Error for invalid parameters or an empty or
/// invalid cloud (Cloud::validate); a sample region without points gives no hands (stats.samples
/// 0).
HandSearchResult search_hands(const Cloud& cloud, const HandSearchParameters& parameters,
                              const RandomStream& random, const SearchScene& scene = {});

}  // namespace antipode
