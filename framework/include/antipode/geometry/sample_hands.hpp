#pragma once
/// @file
/// The whole sampling stage of the paper (Algorithm 2) as one call: preprocess a raw cloud,
/// then search it for hands. The antipodal_sampler plugin is a thin wrapper around it.

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"
#include "antipode/core/random.hpp"
#include "antipode/geometry/hand_search.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/geometry/scene_layout.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

/// Which points hands are sampled from.
enum class ObjectMode : std::uint8_t {
  kAll,   ///< every point the workspace, the sample region and the support leave
  kAuto,  ///< only the objects standing on the support (scene_layout.hpp), when one is found;
          ///< else as kAll
};

struct HandSamplingOptions {
  PreprocessOptions preprocess;
  HandSearchParameters search;
  ObjectMode objects = ObjectMode::kAll;
  SceneOptions scene;  ///< for ObjectMode::kAuto
  /// Points farther than this from the sensor that saw them are dropped after
  /// preprocessing (0: no limit): the room behind a table, 2 m away.
  float max_range_m = 0.0f;
  /// The sensor origin assumed for a cloud that has no view origins (view 0 for every
  /// point), e.g. a cloud in a depth sensor's own frame.
  Eigen::Vector3f default_view_origin_m = Eigen::Vector3f::Zero();
};

/// preprocess() then search_hands().
///
/// A single-view cloud whose sensor origin lies strictly inside the bounding box of the
/// preprocessed cloud (typically an object-centred cloud, such as a segmented object or a
/// model merged from views all around it, read from a file without a viewpoint) cannot have
/// been seen from there: a depth sensor sees only what is in front of it. Such a cloud is
/// searched as seen from all around (HandSearchParameters::outward_from_m = its centroid):
/// normals point away from the centroid, hands approach from outside, there is no occlusion
/// test and no support plane; the returned cloud then has no view origins and no view masks. The
/// returned set's cloud is the preprocessed cloud the hands' closing_points and sample_index refer
/// to; every hand's frame is its frame. With ObjectMode::kAuto (and a cloud seen from its view
/// origins), the scene's support and objects are found first: the search uses that support, samples
/// only the objects' points, and the set carries the objects, each hand the id of the object it
/// closes on; without a support surface the whole cloud is searched as with kAll. `stats`, when
/// given, receives the search's counts. Throws antipode::Error for unusable input (see preprocess()
/// and search_hands()) or an invalid cloud (Cloud::validate).
HandSet sample_hands(const Cloud& cloud, const HandSamplingOptions& options,
                     const RandomStream& random, HandSearchStats* stats = nullptr);

}  // namespace antipode
