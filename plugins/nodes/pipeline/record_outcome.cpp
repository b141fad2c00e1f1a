#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Counts grasp outcomes over the runs of a loop and logs each with the running success rate.
class RecordOutcome final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"RecordOutcome",
            bt::NodeCategory::kAction,
            {bt::input_port<std::string>("outcome", "how the attempt ended ('success' counts)"),
             bt::input_port<bt::TextTemplate>("label", bt::TextTemplate{},
                                              "names the attempt in the log; may hold {entries}"),
             bt::output_port<int>("successes", "successes so far"),
             bt::output_port<int>("attempts", "attempts so far")},
            0,
            0,
            "Tallies grasp outcomes and logs the success rate so far.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string outcome = get_input<std::string>("outcome");
    ++attempts_;
    if (outcome == to_string(GraspOutcome::kSuccess)) ++successes_;
    const std::string label = expand(get_input<bt::TextTemplate>("label"));
    log((label.empty() ? "attempt " + std::to_string(attempts_) : label) + ": " + outcome + " - " +
        std::to_string(successes_) + " of " + std::to_string(attempts_) + " succeeded (" +
        std::to_string(100 * successes_ / attempts_) + "%)");
    set_output("successes", successes_);
    set_output("attempts", attempts_);
    return bt::Status::kSuccess;
  }

 private:
  int successes_ = 0;
  int attempts_ = 0;
};

}  // namespace

void register_record_outcome(bt::NodeRegistry& registry) {
  registry.register_node<RecordOutcome>();
}

}  // namespace antipode::pipeline
