#pragma once
// The trials of an outcome-data run as they travel between nodes: their descriptors, labelled
// by whether the grasp held, and one JSON record per trial (docs/training.md, "Outcome labels").

#include <memory>

#include <nlohmann/json.hpp>

#include "antipode/grasp/training_set.hpp"

namespace antipode::training {

struct TrialLog {
  /// One descriptor per trial whose closing region showed enough points; label +1 when the
  /// grasp held; group = the trial's "group" in `records`; source = the scene's seed.
  TrainingSet examples;
  /// Per trial: scene, source, group, outcome, reason, antipodal label and score, hand, lift.
  nlohmann::ordered_json records = nlohmann::ordered_json::array();
};

using TrialLogPtr = std::shared_ptr<TrialLog>;

}  // namespace antipode::training
