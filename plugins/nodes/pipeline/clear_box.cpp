#include <chrono>
#include <cstdio>

#include "antipode/bt/decorator_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/clearing_run.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

// True when `outcome` names one of the cell's outcomes: the cell executed the grasp
// (GraspOutcome's enumerators run from kSuccess to kNotExecuted).
bool cell_executed(const std::string& outcome) {
  for (auto o = int(GraspOutcome::kSuccess); o <= int(GraspOutcome::kNotExecuted); ++o)
    if (outcome == to_string(GraspOutcome(o))) return true;
  return false;
}

/// Runs its child - one pick attempt that reports `outcome` - again and again until the cell
/// has no object left, a cycle found no grasp predicted to hold (kNothingPredictedToHold),
/// `max_misses` consecutive cycles found no grasp, or the run has used `max_cycles` cycles (the
/// paper's dense-clutter protocol, section 5.3). Each cycle is logged on one line and kept in the
/// run record; the summary line ends the run.
///
/// Returns RUNNING after each cycle (the tree stays responsive), SUCCESS when a rule ends the
/// run, FAILURE when the child fails (the child is expected to report failed picks through
/// `outcome`, not by failing).
class ClearBox final : public bt::DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static bt::NodeManifest manifest() {
    return {"ClearBox",
            bt::NodeCategory::kDecorator,
            {bt::component_port<Cell>("cell", "the cell whose objects are picked (it counts them)"),
             bt::input_port<std::string>("outcome", "the child's outcome of each cycle"),
             bt::input_port<GraspAttempt>("attempt",
                                          "the cell's record, read when the cell executed the "
                                          "cycle's grasp (`outcome` is a cell outcome)"),
             bt::input_port<Hand>("grasp", "the grasp executed, read with `attempt`"),
             bt::input_port<int>("max_cycles", 0,
                                 "cycles at most; 0 = twice the objects at the start (20 when "
                                 "the cell cannot count them)"),
             bt::input_port<int>("max_misses", 3,
                                 "stop after this many consecutive cycles without a grasp"),
             bt::input_port<int>("max_failures", 0,
                                 "stop after this many consecutive failed attempts; 0 = never "
                                 "(VGN's protocol: 2)"),
             bt::input_port<std::string>("picture_prefix", std::string(),
                                         "names each cycle's picture: PREFIXcycle-NN.png "
                                         "(\"\" = no pictures)"),
             bt::output_port<std::string>("picture",
                                          "the file the cycle about to run may draw itself to "
                                          "(\"\" when picture_prefix is empty)"),
             bt::input_port<std::string>("selection_prefix", std::string(),
                                         "names the file of each cycle's selection: "
                                         "PREFIXcycle-NN.json (\"\" = none)"),
             bt::output_port<std::string>("selection",
                                          "the file the cycle about to run may write its "
                                          "selection to (\"\" when selection_prefix is empty)"),
             bt::output_port<std::string>("cloud_file",
                                          "beside the selection, the file the cycle may write "
                                          "its captured cloud to: PREFIXcycle-NN.pcd"),
             bt::output_port<std::string>("objects_file",
                                          "beside the selection, the file the cycle may write "
                                          "the cell's objects to: PREFIXcycle-NN-objects.json"),
             bt::output_port<std::string>("path_file",
                                          "beside the selection, the file the cycle may write "
                                          "its arm's planned path to: PREFIXcycle-NN-path.json"),
             bt::output_port<ClearingRun>("run", "the record of the run, cycle by cycle")},
            1,
            1,
            "Repeats a pick attempt until the box is empty, nothing is predicted to hold, "
            "grasps run out or the cycles do.",
            {}};
  }

 protected:
  bt::Status tick() override {
    if (starting()) start_run();
    if (const ClearingStop stop = stop_rule(); stop != ClearingStop::kRunning) return end_run(stop);
    if (!cycle_started_) begin_cycle();
    const bt::Status status = child().execute_tick();
    if (status == bt::Status::kRunning) return status;
    halt_child(0);
    cycle_started_ = false;
    if (status == bt::Status::kFailure) {
      set_failure_reason("cycle " + std::to_string(run_.cycles.size() + 1) +
                         ": the attempt failed: " + child().failure_reason());
      return bt::Status::kFailure;
    }
    record_cycle();
    return bt::Status::kRunning;  // one cycle per tick: let the tree breathe
  }

  void halt() override {
    cycle_started_ = false;
    DecoratorNode::halt();
  }

 private:
  int objects_now() const { return component<Cell>("cell").objects_left().value_or(-1); }

  void start_run() {
    run_ = ClearingRun{};
    run_.objects_at_start = objects_now();
    run_.objects_placed = component<Cell>("cell").objects_placed().value_or(-1);
    cycle_started_ = false;
    const int given = get_input<int>("max_cycles");
    const int misses = get_input<int>("max_misses");
    const int failures = get_input<int>("max_failures");
    if (given < 0) fail("max_cycles", "port 'max_cycles' of " + describe() + " must be 0 or more");
    if (misses < 1) fail("max_misses", "port 'max_misses' of " + describe() + " must be 1 or more");
    if (failures < 0)
      fail("max_failures", "port 'max_failures' of " + describe() + " must be 0 or more");
    max_cycles_ = given > 0 ? given : run_.objects_at_start >= 0 ? 2 * run_.objects_at_start : 20;
    max_misses_ = misses;
    max_failures_ = failures;
    const int missed = run_.missed_at_filling();
    log("clearing " + (run_.objects_at_start >= 0 ? std::to_string(run_.objects_at_start) : "?") +
        " objects" +
        (missed > 0
             ? " (" + std::to_string(missed) + " of the " + std::to_string(run_.objects_placed) +
                   " placed fell out while the box was filled)"
             : "") +
        ", at most " + std::to_string(max_cycles_) + " cycles");
    set_output("run", run_);
  }

  ClearingStop stop_rule() const {
    if (run_.objects_left() == 0) return ClearingStop::kCleared;
    if (!run_.cycles.empty() && run_.cycles.back().outcome == kNothingPredictedToHold)
      return ClearingStop::kNothingHolds;
    if (run_.trailing_misses() >= max_misses_) return ClearingStop::kMissStreak;
    if (max_failures_ > 0 && run_.trailing_failures() >= max_failures_)
      return ClearingStop::kFailureStreak;
    if (int(run_.cycles.size()) >= max_cycles_) return ClearingStop::kCycleLimit;
    return ClearingStop::kRunning;
  }

  void begin_cycle() {
    char number[16];
    std::snprintf(number, sizeof number, "%02zu", run_.cycles.size() + 1);
    // PREFIXcycle-NN.EXT for the cycle about to run; "" without a prefix.
    const auto cycle_file = [&](const std::string& prefix_port, const std::string& extension) {
      const std::string prefix = get_input<std::string>(prefix_port);
      return prefix.empty() ? std::string() : prefix + "cycle-" + number + extension;
    };
    set_output("picture", cycle_file("picture_prefix", ".png"));
    set_output("selection", cycle_file("selection_prefix", ".json"));
    set_output("cloud_file", cycle_file("selection_prefix", ".pcd"));
    set_output("objects_file", cycle_file("selection_prefix", "-objects.json"));
    set_output("path_file", cycle_file("selection_prefix", "-path.json"));
    cycle_started_ = true;
    cycle_start_ = std::chrono::steady_clock::now();
    objects_before_ = run_.objects_left();
  }

  void record_cycle() {
    ClearingCycle cycle;
    cycle.outcome = get_input<std::string>("outcome");
    if (cell_executed(cycle.outcome)) {
      cycle.attempt = get_input<GraspAttempt>("attempt");
      cycle.grasp = get_input<Hand>("grasp");
    }
    cycle.objects_before = objects_before_;
    cycle.objects_after = objects_now();
    cycle.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - cycle_start_).count();
    log(progress_line(cycle));
    run_.cycles.push_back(std::move(cycle));
    set_output("run", run_);
  }

  std::string progress_line(const ClearingCycle& cycle) const {
    std::string line = "cycle " + std::to_string(run_.cycles.size() + 1) + ": " + cycle.outcome;
    if (cycle.attempt && !cycle.succeeded() && !cycle.attempt->reason.empty())
      line += " - " + cycle.attempt->reason;
    if (cycle.attempt && cycle.succeeded()) line += " (" + cycle.attempt->pinched_object + ")";
    if (cycle.objects_after >= 0) line += "; " + std::to_string(cycle.objects_after) + " left";
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, " [%.1f s]", cycle.seconds);
    return line + seconds;
  }

  bt::Status end_run(ClearingStop stop) {
    run_.stop = stop;
    set_output("run", run_);
    std::string why = to_string(stop);
    if (stop == ClearingStop::kMissStreak) why = std::to_string(max_misses_) + " " + why;
    if (stop == ClearingStop::kFailureStreak) why = std::to_string(max_failures_) + " " + why;
    log("stopped: " + why);
    log(run_.summary());
    return bt::Status::kSuccess;
  }

  ClearingRun run_;
  int max_cycles_ = 0;
  int max_misses_ = 3;
  int max_failures_ = 0;
  bool cycle_started_ = false;
  int objects_before_ = -1;
  std::chrono::steady_clock::time_point cycle_start_;
};

}  // namespace

void register_clear_box(bt::NodeRegistry& registry) { registry.register_node<ClearBox>(); }

}  // namespace antipode::pipeline
