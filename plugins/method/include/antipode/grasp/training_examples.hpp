#pragma once
/// @file
/// Turning labelled hands into training examples (paper section 4.3, "Creating the Training
/// Set"): hands found on a registered two-view cloud C12 are labelled by the near-antipodal
/// check, and every positive or negative hand gives one HOG descriptor per view of its
/// closing region - HOG(I(C1, h)), HOG(I(C2, h)) and HOG(I(C12, h)) - all with its label, so
/// the classifier also learns what a grasp looks like when only one sensor saw it.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/random.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/training_set.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

/// The hands of `set` (same poses, order, labels and scores) with their closing points found
/// in `reference` instead of the set's cloud, and `reference` as the set's cloud: e.g. hands
/// found in one view, to be labelled against the registered cloud of two views. Every point
/// of `reference` inside a hand's closing region (hand_body.hpp) counts. Parallel; the
/// result does not depend on `threads` (0: all cores). Throws antipode::Error for a null or
/// invalid reference.
HandSet with_closing_points_in(const HandSet& set, std::shared_ptr<const Cloud> reference,
                               int threads = 0);

/// Which views of a hand's closing region make descriptors.
struct ExampleOptions {
  /// Views whose points alone make a descriptor (view v = bit v of the cloud's view masks:
  /// C1 is view 0, C2 view 1). Each must exist in the cloud. The descriptor is computed on
  /// the points of the cloud that view saw (points_of_views()), normals re-estimated on them
  /// alone, as on a single-view capture.
  std::vector<int> single_views = {0, 1};
  /// Also a descriptor of all the closing points (C12).
  bool all_views = true;
  /// A view with fewer closing points than this gives no descriptor: too little of the hand
  /// was seen from there to tell anything (a sampler would not propose such a hand).
  std::size_t min_points = 10;
  /// At most this many positive and this many negative hands per call, drawn at random
  /// (0: all). Keeps one object with thousands of easy grasps from swamping the set and
  /// balances the classes as the paper's training set was (3,405 positive, 3,095 negative).
  std::size_t max_hands_per_label = 0;
  HandImageOptions descriptor;
  int threads = 0;  ///< workers (0: all cores); the result does not depend on it
};

/// What add_examples() took from a hand set.
struct ExampleCounts {
  std::size_t positive_hands = 0;
  std::size_t negative_hands = 0;
  std::size_t skipped_hands = 0;  ///< indeterminate or unlabelled: no example
  std::size_t dropped_hands = 0;  ///< over max_hands_per_label
  std::size_t positive_examples = 0;
  std::size_t negative_examples = 0;
};

/// Appends examples of every hand of `labelled` whose label is kPositive or kNegative to
/// `out`: one descriptor per view of ExampleOptions with at least `min_points` closing points,
/// all in a new group (one per hand) with source `source`. Examples come hand by hand, each
/// hand's in the order of `single_views` and then all views. `random` draws the hands kept under
/// max_hands_per_label (kept in their original order). An empty `out` takes the options'
/// descriptor and the set's geometry; a non-empty one must have the same, or an
/// antipode::Error says what differs. Deterministic for any thread count.
ExampleCounts add_examples(const HandSet& labelled, const ExampleOptions& options,
                           std::int32_t source, RandomStream random, TrainingSet& out);

}  // namespace antipode
