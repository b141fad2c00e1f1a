#pragma once
/// @file
/// Correcting a depth sensor's scale error against a support of known height. A depth
/// camera whose depths are all off by one factor (Dex-Net's multiplicative noise draws one
/// per image, a 3% standard deviation; a real sensor's calibration drifts the same way)
/// moves the whole scene along its rays: at 0.6 m, 2 cm - more than the fingers' clearance.
/// The error scales every point about the camera's origin, which keeps planes parallel, so
/// the support plane seen in a view tells the factor: the table the cell stands on is at a
/// known height, and the view's points are scaled about its origin until its table is there.
///
/// Frames: the cloud's; the support is the horizontal plane z = `support_height_m` (the
/// cloud's frame has z up, as the robot's base frame). Threads: none. Deterministic for a
/// given `random`.

#include <cstddef>
#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/random.hpp"

namespace antipode {

struct DepthScaleOptions {
  double support_height_m = 0.0;  ///< where the support plane is (z, the cloud's frame)
  double max_correction = 0.1;    ///< factors beyond 1 +- this are not applied
  double max_tilt_deg = 10.0;     ///< the seen plane must be this close to horizontal
};

/// What was done to one view.
struct ViewScale {
  bool corrected = false;
  double factor = 1.0;         ///< the view's points were scaled about its origin by this
  double seen_height_m = 0.0;  ///< where the view saw the support, before the correction
  std::size_t points = 0;      ///< the view's points
};

/// Scales each view's points (those whose view mask has only that view's bit) about the
/// view's origin so that the support plane found among them lies at
/// `options.support_height_m`. A view without a support plane, with one tilted more than
/// `max_tilt_deg`, or needing a factor beyond `max_correction` is left as it is. Throws
/// antipode::Error for a cloud without view origins.
std::vector<ViewScale> correct_depth_scale(Cloud& cloud, const DepthScaleOptions& options,
                                           const RandomStream& random);

}  // namespace antipode
