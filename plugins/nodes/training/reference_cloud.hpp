#pragma once
// The registered cloud that hands found in one view are looked up in, for labelling
// (LabelHands' `reference`) and for describing (CollectExamples' `cloud`).

#include "antipode/core/cloud.hpp"

namespace antipode::training {

/// `cloud` as the sampler prepares what it samples: non-finite points dropped and points
/// merged into voxels of the default edge (PreprocessOptions, 3 mm), so a hand looked up in it
/// meets the points a hand sampled on it would. Not cropped: closing regions are local.
CloudPtr prepared_reference(const Cloud& cloud);

}  // namespace antipode::training
