// Quick-starts: the smallest component of each kind that still keeps its interface's
// contract (docs/plugins.md#quick-starts-one-component-of-each-kind). Copy one, rename it,
// fill it in. Built with the example, so every skeleton here compiles against the installed
// SDK.
//
// - sampler `every_point`: one hand straight down onto each point of the cloud;
// - selector `best_score`: the best-scored selectable hand first, the others in input order
//   with their reasons ("not selected" for those that had none);
// - planner `never_reaches`: a planner's failure, as a status with a one-line detail;
// - cell `empty_cell`: one view that sees nothing, grasps that close on nothing; an unknown
//   view is an error.
#include <algorithm>
#include <memory>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/interfaces/motion_planner.hpp"
#include "antipode/interfaces/sampler.hpp"
#include "antipode/plugin/abi.hpp"

namespace {
using namespace antipode;

// Hands in the cloud's frame; the set's cloud is the cloud they index; the result depends
// only on the cloud, the parameters and the seed of `random` (not on threads).
class EveryPoint final : public Sampler {
 public:
  explicit EveryPoint(const Parameters& params) : above_m_(params.get("above_m", 0.03)) {
    params.reject_unknown();
    if (!(above_m_ > 0.0)) params.fail("above_m", "above_m must be > 0");
  }
  HandSet sample(const Cloud& cloud, const RandomStream&, const StopToken& stop) const override {
    HandSet set;
    set.cloud = std::make_shared<Cloud>(cloud);
    for (const Eigen::Vector3f& p_m : cloud.points_m) {
      stop.throw_if_stop_requested("every_point");
      Hand hand;
      hand.frame = cloud.frame;
      // x = approach (down), y = closing, z = x cross y.
      hand.X_FrameHand.linear() << 0, 0, 1, 0, 1, 0, -1, 0, 0;
      hand.X_FrameHand.translation() = p_m.cast<double>() + Eigen::Vector3d(0, 0, above_m_);
      set.hands.push_back(hand);
    }
    return set;
  }

 private:
  double above_m_;
};

// The same cloud; the chosen grasps first (each one of the given hands or a mean of some),
// every other hand after them with why it was not chosen.
class BestScore final : public GraspSelector {
 public:
  explicit BestScore(const Parameters& params) { params.reject_unknown(); }
  HandSet select(const HandSet& in, const SelectionContext&) const override {
    HandSet out = in;
    out.hands.clear();
    const Hand* best = nullptr;  // the best-scored hand a selector may choose
    for (const Hand& hand : in.hands)
      if (selectable(hand) && (best == nullptr || hand.score > best->score)) best = &hand;
    if (best != nullptr) out.hands.push_back(*best);
    for (const Hand& hand : in.hands) {  // the others in input order, each with its reason
      if (&hand == best) continue;
      out.hands.push_back(hand);
      if (out.hands.back().rejection == Rejection::kNone)
        out.hands.back().rejection = Rejection::kNotSelected;
    }
    return out;
  }
};

// Failures are statuses with a one-line detail, never exceptions.
class NeverReaches final : public MotionPlanner {
 public:
  explicit NeverReaches(const Parameters& params) { params.reject_unknown(); }
  PlanningResult plan(const PlanningProblem&) const override {
    PlanningResult result;
    result.status = PlanningStatus::kNoIkAtGrasp;
    result.detail = "never_reaches plans no motion";
    return result;
  }
};

// A real cell talks to its robot and sensors here; every attempt returns its record.
class EmptyCell final : public Cell {
 public:
  explicit EmptyCell(const Parameters& params) { params.reject_unknown(); }
  std::vector<std::string> view_names() const override { return {"front"}; }
  Cloud capture(const std::vector<std::string>& views) override {
    Cloud cloud;  // no points, one (empty) view per view asked for
    cloud.frame = "base";
    for (const std::string& view : views) {
      if (view != "front") throw Error("empty_cell has no view '" + view + "' (it has: front)");
      cloud.view_origins_m.emplace_back(Eigen::Vector3f::Zero());
    }
    return cloud;
  }
  JointState arm_state() const override { return {}; }
  GraspAttempt execute(const GraspRequest&) override {
    GraspAttempt attempt;
    attempt.outcome = GraspOutcome::kEmptyGrasp;
    attempt.reason = "the fingers closed on nothing (the cell is empty)";
    return attempt;
  }
  void reset(std::uint64_t) override {}
};

template <typename T>
Component* create(const Parameters& params) {
  return new T(params);
}

const PluginFactory kFactories[] = {
    {"sampler", "every_point", "one hand straight down onto each point", &create<EveryPoint>,
     nullptr},
    {"selector", "best_score", "the best-scored hand", &create<BestScore>, nullptr},
    {"planner", "never_reaches", "plans no motion", &create<NeverReaches>, nullptr},
    {"cell", "empty_cell", "a cell with nothing in it", &create<EmptyCell>, nullptr},
};

}  // namespace

ANTIPODE_PLUGIN("quick_starts", "1.0.0", kFactories)
