#pragma once
/// @file
/// Outward surface normals at the points of a cloud, for labelling hands (paper section 4).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

struct NormalEstimationOptions {
  /// Radius of the ball whose points the surface is fitted to (Taubin quadric, or a plane
  /// where the ball is flat; see local_frame.hpp). Smaller than the 3 cm of the sampler's
  /// frames so that a normal describes the surface a finger meets, not its surroundings.
  double radius_m = 0.01;
  /// Fewer neighbours than this (the point included) give no normal (at least 9).
  std::size_t min_neighbours = 10;
  /// Where normals of a cloud without view origins point away from; unset: its centroid
  /// (such a cloud is one seen from all around, as sample_hands() treats it).
  std::optional<Eigen::Vector3f> outward_from_m;
  /// Worker threads (0: as many as the hardware has). Results do not depend on it.
  int threads = 0;

  /// Throws antipode::Error naming the offending field.
  void validate() const;
};

/// Unit surface normals of the points of `cloud`, one entry per cloud point, each flipped
/// towards the sensors that saw its point (the normalised sum of the unit directions to the
/// origins of the views in its view mask; no masks: view 0) - for an object, its outward
/// normal. A cloud without view origins counts as seen from all around: normals point away
/// from `outward_from_m` (or the centroid).
///
/// Only the points listed in `which` are estimated when it is given (the others get zero);
/// a point whose neighbourhood is too small or collinear, or whose viewing directions cancel
/// out, gets zero too. Estimated in parallel, once per cloud; the result does not depend on
/// the thread count. Throws antipode::Error for an invalid cloud, an index out of range or
/// invalid options.
std::vector<Eigen::Vector3f> estimate_normals(const Cloud& cloud,
                                              const NormalEstimationOptions& options,
                                              const std::vector<std::int32_t>* which = nullptr);

/// estimate_normals() of `set`'s cloud for the union of all its hands' closing points, each
/// estimated once (the others get zero). Throws antipode::Error when the set has hands but
/// no cloud, or a closing point is outside the cloud (`who` names the caller in messages).
std::vector<Eigen::Vector3f> closing_point_normals(const HandSet& set,
                                                   const NormalEstimationOptions& options,
                                                   const std::string& who);

}  // namespace antipode
