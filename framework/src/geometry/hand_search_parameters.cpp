#include <cmath>
#include <sstream>
#include <string>

#include "antipode/core/error.hpp"
#include "antipode/geometry/hand_search.hpp"

namespace antipode {
namespace {

// `value` as a user wrote it: whole numbers without decimals.
std::string shown(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15)
    return std::to_string(static_cast<long long>(value));
  std::ostringstream text;
  text << value;
  return text.str();
}

void require(bool ok, const std::string& field, const std::string& rule, double value) {
  if (!ok) throw Error("hand search: " + field + " must be " + rule + ", got " + shown(value));
}

}  // namespace

void HandSearchParameters::validate() const {
  hand.validate();
  if (sample_region) sample_region->validate("sample region");
  require(samples > 0, "samples", "at least 1", static_cast<double>(samples));
  require(frame_radius_m > 0.0 && std::isfinite(frame_radius_m), "frame_radius_m", "> 0",
          frame_radius_m);
  require(orientations >= 1 && orientations <= 360, "orientations", "in 1..360", orientations);
  for (const double tilt : approach_tilts_deg) {
    require(tilt > 0.0 && tilt <= 80.0, "approach_tilts_deg", "in (0, 80]", tilt);
  }
  require(tilted_orientation_range_deg >= 0.0 && tilted_orientation_range_deg <= 90.0,
          "tilted_orientation_range_deg", "in [0, 90]", tilted_orientation_range_deg);
  require(positions >= 1 && positions <= 1000, "positions", "in 1..1000", positions);
  require(min_bite_m >= 0.0 && min_bite_m <= hand.depth_m, "min_bite_m", "in [0, depth_m]",
          min_bite_m);
  require(clearance_m >= 0.0 && clearance_m < hand.depth_m, "clearance_m", "in [0, depth_m)",
          clearance_m);
  require(support_clearance_m >= 0.0 && support_clearance_m < 0.1, "support_clearance_m",
          "in [0, 0.1)", support_clearance_m);
  require(min_bite_at_support_m >= 0.0 && min_bite_at_support_m <= min_bite_m,
          "min_bite_at_support_m", "in [0, min_bite_m]", min_bite_at_support_m);
  require(max_view_angle_deg > 0.0 && max_view_angle_deg <= 180.0, "max_view_angle_deg",
          "in (0, 180]", max_view_angle_deg);
  require(occlusion_margin_m >= 0.0 && std::isfinite(occlusion_margin_m), "occlusion_margin_m",
          ">= 0", occlusion_margin_m);
  require(point_radius_m > 0.0 && point_radius_m < 0.1, "point_radius_m", "in (0, 0.1)",
          point_radius_m);
  require(support.distance_m > 0.0f && support.distance_m < 0.1f, "support.distance_m",
          "in (0, 0.1)", support.distance_m);
  require(support.min_inlier_fraction >= 0.0f && support.min_inlier_fraction <= 1.0f,
          "support.min_inlier_fraction", "in [0, 1]", support.min_inlier_fraction);
  require(support.max_below_fraction >= 0.0f && support.max_below_fraction <= 1.0f,
          "support.max_below_fraction", "in [0, 1]", support.max_below_fraction);
  require(support.min_supported_fraction >= 0.0f && support.min_supported_fraction <= 1.0f,
          "support.min_supported_fraction", "in [0, 1]", support.min_supported_fraction);
  require(support.min_facing_fraction >= 0.0f && support.min_facing_fraction <= 1.0f,
          "support.min_facing_fraction", "in [0, 1]", support.min_facing_fraction);
  require(support.min_above_fraction >= 0.0f && support.min_above_fraction <= 1.0f,
          "support.min_above_fraction", "in [0, 1]", support.min_above_fraction);
  require(support.iterations >= 1, "support.iterations", "at least 1", support.iterations);
  require(threads >= 0 && threads <= 256, "threads", "in 0..256 (0: one per core)", threads);
  require(frame.min_points >= 9, "frame.min_points", "at least 9",
          static_cast<double>(frame.min_points));
  require(frame.axis_normals >= 2, "frame.axis_normals", "at least 2",
          static_cast<double>(frame.axis_normals));
  require(frame.planar_ratio >= 0.0f && frame.planar_ratio < 1.0f, "frame.planar_ratio",
          "in [0, 1)", frame.planar_ratio);
  require(frame.collinear_ratio >= 0.0f && frame.collinear_ratio < 1.0f, "frame.collinear_ratio",
          "in [0, 1)", frame.collinear_ratio);
}

HandSearchStats& HandSearchStats::operator+=(const HandSearchStats& o) {
  samples += o.samples;
  frames_quadric += o.frames_quadric;
  frames_planar += o.frames_planar;
  skipped_too_few += o.skipped_too_few;
  skipped_collinear += o.skipped_collinear;
  orientations_unseen += o.orientations_unseen;
  poses += o.poses;
  in_collision += o.in_collision;
  empty += o.empty;
  too_shallow += o.too_shallow;
  hidden += o.hidden;
  below_support += o.below_support;
  on_support += o.on_support;
  acceptable += o.acceptable;
  hands += o.hands;
  tilted_hands += o.tilted_hands;
  return *this;
}

}  // namespace antipode
