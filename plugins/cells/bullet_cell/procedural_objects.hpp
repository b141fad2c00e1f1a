#pragma once
// Objects built from simple solids, with exact sizes or sizes drawn from a seeded stream.

#include <string>
#include <vector>

#include "antipode/core/random.hpp"
#include "object_model.hpp"

namespace antipode::cells {

/// The ranges random objects are drawn from.
struct ProceduralRanges {
  /// Share of objects whose graspable width lies in [min_graspable_m, max_graspable_m]; the
  /// others are narrower or (mostly) wider, so that a detector also meets objects it must not
  /// grasp.
  double graspable_share = 0.8;
  double min_graspable_m = 0.03;
  double max_graspable_m = 0.07;
  double min_density_kg_m3 = 400.0;
  double max_density_kg_m3 = 1000.0;
  double min_friction = 0.6;
  double max_friction = 1.0;
};

/// Shapes make_random_object() knows.
const std::vector<std::string>& procedural_shapes();

/// "unknown object shape 'NAME' (did you mean ...?) (known: ...)".
std::string unknown_shape_message(const std::string& shape);

/// An object of `shape` with sizes, density and friction drawn from `random`.
/// Throws antipode::Error for an unknown shape.
ObjectModel make_random_object(const std::string& shape, const ProceduralRanges& ranges,
                               RandomStream& random);

/// An object of `shape` with explicit dimensions: box {x, y, z}; cylinder {diameter, height};
/// sphere {diameter}; capsule {diameter, total length}; ellipsoid {x, y, z} (full axes);
/// bottle {body diameter, height, neck diameter, neck length}; mug {body diameter, height};
/// banana {diameter, length along its curve, bend radius}; l_shape {bar width, long leg,
/// short leg, height}; t_shape {bar width, cross bar length, stem length, height}.
/// Upright objects stand on z; the banana, L and T lie flat (their curve or bars in xy).
ObjectModel make_object(const std::string& shape, const std::vector<double>& size_m,
                        double density_kg_m3, double friction);

}  // namespace antipode::cells
