#pragma once
/// @file
/// The geometric model of a two-finger parallel gripper, as the paper and agile_grasp use
/// it: the one description of the gripper that the sampler searches with, the selector
/// keeps clear of the support with and the cell executes (a hand set carries it from the
/// sampler on). All lengths are metres. The defaults are the Baxter electric gripper with
/// the finger slot the paper used (see shared/reference/baxter.md).
///
/// Hand frame (see docs/pose-convention.md): x = approach (palm -> fingertips),
/// y = closing direction (from the finger at -y towards the finger at +y), z = x cross y.
/// The origin is the centre of the palm face between the fingers' roots.
///
///          y ^
///            |   finger (+y)   [depth_m along x]
///   palm ----+---------------->  x (approach)
///            |   finger (-y)
///   The fingers' inner faces are aperture/2 from the x axis; each finger is finger_width_m
///   thick along y and height_m tall along z. Behind the palm face (x < 0) a palm box
///   palm_thickness_m thick spans the outer diameter: it stands for everything of the
///   gripper behind the closing region.

namespace antipode {

struct HandGeometry {
  double finger_width_m = 0.01;  ///< finger thickness along the closing direction
  /// Outer distance across both fingers when fully open: the 0.072 m aperture plus two
  /// 0.01 m fingers (agile_grasp rounds this to 0.09).
  double outer_diameter_m = 0.092;
  double depth_m = 0.06;           ///< finger length along the approach direction
  double height_m = 0.02;          ///< finger and palm extent along the hand axis (z)
  double init_bite_m = 0.01;       ///< how far points must reach into the closing region
  double min_aperture_m = 0.029;   ///< inner distance between fingers when fully closed
  double max_aperture_m = 0.072;   ///< inner distance between fingers when fully open
  double palm_thickness_m = 0.02;  ///< the palm box behind the palm face

  /// Throws antipode::Error naming the offending field when any value is non-positive or
  /// inconsistent (min >= max aperture, max aperture + 2 fingers > outer diameter + 1 mm,
  /// init bite >= depth), and when the palm thickness is negative.
  void validate() const;
};

}  // namespace antipode
