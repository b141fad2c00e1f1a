#include <algorithm>
#include <memory>
#include <vector>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/hand_set.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

// Up to `count` indices of `set`'s hands without a rejection, drawn at random and kept in
// their order in the set.
std::vector<std::size_t> draw_hands(const HandSet& set, std::size_t count, RandomStream random) {
  std::vector<std::size_t> open;
  for (std::size_t h = 0; h < set.hands.size(); ++h)
    if (set.hands[h].rejection == Rejection::kNone) open.push_back(h);
  if (open.size() > count) {
    for (std::size_t i = 0; i < count; ++i)  // partial Fisher-Yates
      std::swap(open[i], open[i + random.below(open.size() - i)]);
    open.resize(count);
    std::sort(open.begin(), open.end());
  }
  return open;
}

/// Tries hands as independent trials: saves the cell's world, then executes each chosen hand
/// with a free-floating gripper from that same saved world, and leaves the world as it was.
/// Each trial's outcome is the cell's (held, slipped, closed on nothing, ...): the label a
/// grasp-success model learns from (docs/training.md, "Outcome labels").
class TryGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"TryGrasps",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "a cell that can save and restore its world"),
             bt::input_port<HandSetPtr>("hands",
                                        "hands to draw trials from (those without a "
                                        "rejection), in the cell's base frame"),
             bt::input_port<int>("trials", 20, "at most this many hands, drawn at random"),
             bt::output_port<HandSetPtr>("tried", "the hands tried, in the order of `hands`"),
             bt::output_port<std::vector<GraspAttempt>>(
                 "attempts", "the cell's record of each trial, in the order of `tried`")},
            0,
            0,
            "Executes hands as independent trials from one saved world.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr in = get_input<HandSetPtr>("hands");
    const int trials = get_input<int>("trials");
    if (trials < 1 || trials > 100000)
      fail("trials", "port 'trials' of " + describe() + " must be in [1, 100000]");
    Cell& cell = component<Cell>("cell");
    const std::shared_ptr<const CellState> saved = cell.save();
    if (saved == nullptr)
      fail("cell", "the cell of " + describe() +
                       " cannot save its world, so trials cannot "
                       "start from one state (a simulated cell such as bullet_cell can)");
    auto tried = std::make_shared<HandSet>(
        HandSet{in->cloud, {}, in->geometry, in->support, in->objects, in->scores});
    std::vector<GraspAttempt> attempts;
    for (const std::size_t h : draw_hands(*in, std::size_t(trials), random())) {
      // Every trial, the first too, meets a restored world: its caches start cold, as theirs.
      cell.restore(*saved);
      attempts.push_back(cell.execute(GraspRequest{in->hands[h], in->geometry, {}}));
      tried->hands.push_back(in->hands[h]);
    }
    if (!attempts.empty()) cell.restore(*saved);
    const auto held = std::count_if(attempts.begin(), attempts.end(), [](const GraspAttempt& a) {
      return a.outcome == GraspOutcome::kSuccess;
    });
    log(std::to_string(held) + " of " + std::to_string(attempts.size()) + " trials held");
    set_output("tried", HandSetPtr(std::move(tried)));
    set_output("attempts", std::move(attempts));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_try_grasps(bt::NodeRegistry& registry) { registry.register_node<TryGrasps>(); }

}  // namespace antipode::pipeline
