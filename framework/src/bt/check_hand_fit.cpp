// A tree's classifiers must describe the hands its samplers find. A HOG + SVM model images the
// closing region of the gripper it was trained for; given another gripper's hands it can only
// refuse them, and without this check it did so at the first classification, after the
// sampling, with exit 1. Checked once the components exist (the model is loaded, the sampler
// knows its hand), before any node runs: a load error, exit 2, naming both components.

#include "antipode/core/error.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/interfaces/sampler.hpp"
#include "checks.hpp"

namespace antipode::bt::detail {

void check_classifiers_fit_samplers(const FileSpec& spec, const TreeContext& context) {
  for (const ComponentSpec& classifier_spec : spec.components) {
    const auto classifier =
        std::dynamic_pointer_cast<const Classifier>(context.components.at(classifier_spec.name));
    if (!classifier) continue;
    for (const ComponentSpec& sampler_spec : spec.components) {
      const auto sampler =
          std::dynamic_pointer_cast<const Sampler>(context.components.at(sampler_spec.name));
      if (!sampler) continue;
      const std::optional<HandGeometry> hand = sampler->hand();
      if (!hand) continue;
      const std::string problem = classifier->hand_problem(*hand);
      if (problem.empty()) continue;
      throw Error("component '" + classifier_spec.name + "' (" + classifier_spec.plugin +
                      ") cannot score the hands of component '" + sampler_spec.name + "' (" +
                      sampler_spec.plugin + "): " + problem,
                  classifier_spec.where);
    }
  }
}

}  // namespace antipode::bt::detail
