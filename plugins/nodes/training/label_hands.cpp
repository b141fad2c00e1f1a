#include <algorithm>
#include <memory>

#include "antipode/bt/action_node.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/grasp/antipodal.hpp"
#include "antipode/grasp/training_examples.hpp"
#include "nodes.hpp"

namespace antipode::training {
namespace {

/// Labels hands by the near-antipodal check (Definition 3), on their own cloud or on a
/// reference cloud (a registered two-view cloud for hands found in one view). The reference
/// is prepared as the sampler prepares what it samples (non-finite points dropped, 3 mm
/// voxels: PreprocessOptions), so that a hand looked up in it meets the points a hand sampled
/// on it would; it is not cropped, closing regions being local.
class LabelHands final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"LabelHands",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("hands", "hands to label"),
             bt::input_port<CloudPtr>("reference", CloudPtr{},
                                      "label against this cloud (voxelised at 3 mm first); "
                                      "unset: the hands' own cloud"),
             bt::input_port<int>("min_points", 6, "k of Definition 3"),
             bt::input_port<double>("max_angle_deg", 20.0, "theta of Definition 3"),
             bt::input_port<double>("contact_depth_m", AntipodalParameters{}.contact_depth_m,
                                    "count each finger's contact patch this deep (0: the whole "
                                    "closing region, as Definition 3)"),
             bt::input_port<double>("normal_radius_m", 0.01, "ball the normals are fitted over"),
             bt::input_port<int>("threads", 0, "workers (0: all cores)"),
             bt::output_port<HandSetPtr>("labelled", "the same hands, labelled and scored"),
             bt::output_port<HandSetPtr>("judged",
                                         "the labelled hands as the check saw them: with their "
                                         "closing points in the prepared reference (e.g. for "
                                         "CollectExamples to describe them there); without a "
                                         "reference, as `labelled`")},
            0,
            0,
            "Labels hands positive, negative or indeterminate by the near-antipodal check.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr hands = get_input<HandSetPtr>("hands");
    AntipodalLabellingOptions options;
    options.antipodal.min_points = get_input<int>("min_points");
    options.antipodal.max_angle_deg = get_input<double>("max_angle_deg");
    options.antipodal.contact_depth_m = get_input<double>("contact_depth_m");
    options.normals.radius_m = get_input<double>("normal_radius_m");
    options.normals.threads = get_input<int>("threads");
    auto labelled = std::make_shared<HandSet>(*hands);
    auto judged = std::make_shared<HandSet>(judged_set(*hands, options.normals.threads));
    labelled->scores = judged->scores = ScoreMeaning::kOrder;  // the check's scores replace any
    const auto counts = count_antipodal_normals(*judged, options);
    for (std::size_t i = 0; i < counts.size(); ++i) {
      for (HandSet* set : {labelled.get(), judged.get()}) {
        set->hands[i].label = antipodal_label(counts[i], options.antipodal.min_points);
        set->hands[i].score = antipodal_score(counts[i], options.antipodal.min_points);
      }
    }
    log(summary(*labelled));
    set_output("labelled", HandSetPtr(std::move(labelled)));
    set_output("judged", HandSetPtr(std::move(judged)));
    return bt::Status::kSuccess;
  }

 private:
  // The hands with the closing points the check counts: their own, or the reference's.
  HandSet judged_set(const HandSet& hands, int threads) const {
    const CloudPtr reference = get_input<CloudPtr>("reference");
    if (reference == nullptr) return hands;
    const auto prepared = std::make_shared<Cloud>(
        voxelize(remove_non_finite(*reference), PreprocessOptions{}.voxel_size_m));
    return with_closing_points_in(hands, prepared, threads);
  }

  static std::string summary(const HandSet& set) {
    auto count = [&](HandLabel label) {
      return std::to_string(std::count_if(set.hands.begin(), set.hands.end(),
                                          [&](const Hand& h) { return h.label == label; }));
    };
    return count(HandLabel::kPositive) + " positive, " + count(HandLabel::kNegative) +
           " negative, " + count(HandLabel::kIndeterminate) + " indeterminate of " +
           std::to_string(set.hands.size()) + " hands";
  }
};

}  // namespace

void register_label_hands(bt::NodeRegistry& registry) { registry.register_node<LabelHands>(); }

}  // namespace antipode::training
