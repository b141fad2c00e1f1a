#pragma once
// Internal to the geometry area: Algorithm 3 of the paper (Grid_Search) for one sample.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/geometry/hand_search.hpp"
#include "antipode/geometry/local_frame.hpp"
#include "antipode/geometry/occlusion.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode::geometry {

/// The constants of the grid search, derived once per search from its parameters. Lengths
/// are in metres, in the sample's local frame; `start_m` is the palm's starting position
/// along the approach relative to the sample (negative: before it).
struct GridSpec {
  explicit GridSpec(const HandSearchParameters& parameters);

  float half_aperture_m, finger_width_m, body_half_width_m, depth_m, half_height_m;
  float palm_thickness_m, start_m, clearance_m, min_bite_m, min_bite_at_support_m;
  float slab_half_thickness_m;  ///< half height of the hand plus the search margin
  float max_lateral_m;          ///< largest |closing coordinate| a colliding point can have
  float reach_m;                ///< radius of the ball holding every point that can matter
  float min_view_cosine;        ///< cosine of max_view_angle_deg
  bool keep_all_positions;
  float occlusion_margin_m;
  float support_clearance_m;                   ///< how close the body may come to the support plane
  std::vector<Eigen::Vector3f> finger_probes;  ///< hand-frame points tested for occlusion
  std::vector<float> cos_phi, sin_phi;         ///< per orientation
  std::vector<std::size_t> all_orientations;   ///< 0 .. orientations - 1
  /// The orientations searched in a tilted frame: within tilted_orientation_range_deg of 0.
  std::vector<std::size_t> tilted_orientations;
  std::vector<float> tilts_rad;  ///< approach_tilts_deg
  std::vector<float> offsets_m;  ///< per position: hand centre along closing
};

/// Cell size of the SlabGrid that finds each sample's hand neighbourhood: about the hand's
/// height, so the grid visits few cells outside the slab.
constexpr float kSlabCell_m = 0.02f;

/// What one (orientation, position) pose gave.
struct PoseOutcome {
  bool acceptable = false;
  Rejection rejection = Rejection::kNone;
  float palm_m = 0.0f;  ///< final palm position along the approach
  float bite_m = 0.0f;
};

/// Buffers one worker reuses for every sample, so the search allocates nothing per hand
/// pose (only the hands it returns allocate their closing-point lists).
struct GridScratch {
  std::vector<std::int32_t> frame_neighbours;
  std::vector<std::int32_t> hand_neighbours;
  // Neighbours within the hand's height of the closing plane, in (normal, binormal, axis)
  // coordinates relative to the sample.
  std::vector<float> slab_n, slab_b, slab_a;
  std::vector<std::int32_t> slab_index;
  // The slab points that can touch the hand in one orientation: approach (u) and closing (v)
  // coordinates relative to the sample.
  std::vector<float> u, v, w;
  std::vector<std::int32_t> index;
  std::vector<PoseOutcome> poses;
  std::vector<std::size_t> chosen;
};

/// What grid_search needs to know about one sample.
struct SampleContext {
  const Cloud& cloud;
  const LocalFrame& frame;
  std::int32_t sample;            ///< the sample's index in the cloud
  Eigen::Vector3f toward_viewer;  ///< unit direction to the sensors that saw it (or zero)
  const OcclusionMap* occlusion;  ///< null: no occlusion test
  const SupportPlane* support;    ///< null: no support plane
  bool tilted = false;            ///< a tilted frame: search spec.tilted_orientations only
};

/// Searches the orientation x position grid around the sample's frame using the cloud points
/// `scratch.hand_neighbours` (those within spec.reach_m of the sample and within
/// spec.slab_half_thickness_m of its closing plane); appends the hands it keeps and counts
/// outcomes.
void grid_search(const SampleContext& context, const GridSpec& spec, GridScratch& scratch,
                 std::vector<Hand>& hands, HandSearchStats& stats);

}  // namespace antipode::geometry
