#pragma once
/// @file
/// Labelled descriptors for training and evaluating a hand classifier (paper section 4.3):
/// one row per descriptor, a +1 / -1 label each, and a group id that ties together the
/// descriptors of one hand (its C1, C2 and C12 images), so that cross-validation can keep a
/// hand's views in one fold.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "antipode/core/hand_geometry.hpp"
#include "antipode/grasp/hand_image.hpp"

namespace antipode {

struct TrainingSet {
  HandImageOptions descriptor;        ///< how the descriptors were computed
  HandGeometry geometry;              ///< the hand whose closing region they image
  std::size_t dimension = 0;          ///< numbers per descriptor (0 until the first add)
  std::vector<float> features;        ///< size() x dimension numbers, row-major
  std::vector<std::int8_t> labels;    ///< +1 positive (a grasp), -1 negative
  std::vector<std::int32_t> groups;   ///< examples of one group share a fold
  std::vector<std::int32_t> sources;  ///< which scene (or object) an example came from

  std::size_t size() const { return labels.size(); }
  bool empty() const { return labels.empty(); }
  std::size_t positives() const;
  std::size_t negatives() const { return size() - positives(); }
  const float* row(std::size_t i) const { return features.data() + i * dimension; }

  /// Appends one example. The first fixes `dimension`; later ones must match it (else an
  /// antipode::Error naming both lengths). Non-finite numbers are an error too.
  void add(const std::vector<float>& descriptor, bool positive, std::int32_t group,
           std::int32_t source);

  /// A group id not used yet (one more than the largest so far, 0 when empty).
  std::int32_t next_group() const;

  /// The examples at `indices` (in that order), with their groups and sources.
  TrainingSet subset(const std::vector<std::size_t>& indices) const;

  /// Throws antipode::Error when the columns disagree in length or a label is not +-1.
  void validate() const;
};

/// Writes `set` to `path` in antipode's binary training-set format (a header with a magic
/// word, version, sizes and a checksum, then the columns), all-or-nothing.
void save_training_set(const TrainingSet& set, const std::string& path);

/// Reads a file written by save_training_set(). A missing, truncated, corrupted (checksum)
/// or foreign file is an antipode::Error naming the file and what is wrong.
TrainingSet load_training_set(const std::string& path);

}  // namespace antipode
