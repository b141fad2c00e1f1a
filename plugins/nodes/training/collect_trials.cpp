#include <Eigen/Geometry>

#include "antipode/bt/action_node.hpp"
#include "antipode/grasp/training_examples.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"
#include "nodes.hpp"
#include "trial_log.hpp"

namespace antipode::training {
namespace {

nlohmann::ordered_json trial_record(const Hand& hand, const GraspAttempt& attempt,
                                    std::int32_t group, std::uint64_t source,
                                    const std::string& scene, std::size_t views) {
  const Eigen::Quaterniond q(hand.X_FrameHand.linear());
  const Eigen::Vector3d p = hand.X_FrameHand.translation();
  return {{"scene", scene},
          {"source", source},
          {"views", views},
          {"group", group},
          {"outcome", to_string(attempt.outcome)},
          {"held", attempt.outcome == GraspOutcome::kSuccess},
          {"reason", attempt.reason},
          {"antipodal", to_string(hand.label)},
          {"antipodal_score", hand.score},
          {"position_m", {p.x(), p.y(), p.z()}},
          {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}},
          {"width_m", hand.width_m},
          {"lift_m", attempt.lift_m},
          {"examples", 0}};
}

/// Appends trials (TryGrasps) to a trial log: per trial one descriptor of its closing region
/// in the cloud it was found in (what the classifier sees at run time), labelled +1 when the
/// grasp held, and a record with the cell's outcome and the hand's near-antipodal label
/// (LabelHands), so that both label sources exist for the same hands.
class CollectTrials final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"CollectTrials",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("tried", "the hands tried, labelled by LabelHands"),
             bt::input_port<std::vector<GraspAttempt>>("attempts", "TryGrasps' records"),
             bt::input_port<TrialLogPtr>("log", "the trial log to append to"),
             bt::input_port<std::uint64_t>("source", "the scene's seed"),
             bt::input_port<std::string>("scene", std::string(), "what the scene is"),
             bt::input_port<int>("min_points", 10, "fewer closing points give no descriptor"),
             bt::input_port<int>("threads", 0, "workers (0: all cores)")},
            0,
            0,
            "Appends tried hands, their outcomes and descriptors to a trial log.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr tried = get_input<HandSetPtr>("tried");
    const auto& attempts = get_input_ref<std::vector<GraspAttempt>>("attempts");
    if (attempts.size() != tried->hands.size())
      fail("attempts", "there are " + std::to_string(attempts.size()) + " attempts for " +
                           std::to_string(tried->hands.size()) + " tried hands");
    TrialLog& trials = *get_input<TrialLogPtr>("log");
    const std::uint64_t source = get_input<std::uint64_t>("source");
    const std::string scene = get_input<std::string>("scene");
    const auto base = std::int32_t(trials.records.size());  // a trial's group: its record
    HandSet by_outcome = *tried;                            // labels: did it hold?
    for (std::size_t i = 0; i < attempts.size(); ++i)
      by_outcome.hands[i].label = attempts[i].outcome == GraspOutcome::kSuccess
                                      ? HandLabel::kPositive
                                      : HandLabel::kNegative;
    ExampleOptions options;
    options.single_views = {};
    options.all_views = true;
    const int min_points = get_input<int>("min_points");
    if (min_points < 1) fail("min_points", "min_points must be at least 1");
    options.min_points = std::size_t(min_points);
    options.threads = get_input<int>("threads");
    TrainingSet examples;
    add_examples(by_outcome, options, std::int32_t(source), random(), examples);
    const std::size_t views = tried->cloud ? tried->cloud->view_origins_m.size() : 0;
    for (std::size_t i = 0; i < attempts.size(); ++i) {
      trials.records.push_back(
          trial_record(tried->hands[i], attempts[i], base + std::int32_t(i), source, scene, views));
    }
    if (trials.examples.empty() && !examples.empty()) {
      trials.examples.descriptor = examples.descriptor;
      trials.examples.geometry = examples.geometry;
    }
    for (std::size_t e = 0; e < examples.size(); ++e) {
      const std::int32_t group = base + examples.groups[e];  // add_examples numbered from 0
      const std::vector<float> row(examples.row(e), examples.row(e) + examples.dimension);
      trials.examples.add(row, examples.labels[e] > 0, group, std::int32_t(source));
      auto& record = trials.records[std::size_t(group)];
      record["examples"] = record["examples"].get<int>() + 1;
    }
    log(std::to_string(attempts.size()) + " trials, " + std::to_string(examples.size()) +
        " described; " + std::to_string(trials.records.size()) + " in the log");
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_collect_trials(bt::NodeRegistry& registry) {
  registry.register_node<CollectTrials>();
}

}  // namespace antipode::training
