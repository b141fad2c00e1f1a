#pragma once
/// @file
/// The record of a clear-the-box run (ClearingRun): the loop that picks objects from a box
/// until it is empty, one entry per cycle (the `ClearBox` node, docs/trees.md).
///
/// A cycle captures views, detects and selects grasps; when it chooses a grasp the arm plans
/// a motion and the cell executes it. Counting follows the paper's dense-clutter experiment
/// (section 5.3):
/// - an *attempt* is a cycle that chose a grasp: one the cell executed, or one the arm could
///   not reach ("no IK", "no motion plan");
/// - a *localisation failure* is a cycle that found no grasp ("no grasp found", or "no grasp
///   predicted to hold" when the classifier accepted no hand);
/// - an object is *removed* when an attempt lifted it out (a success).
///
/// Units: seconds of wall time. Object counts are -1 where the cell cannot tell (a real
/// cell without ground truth); the counts that need them are then -1 too.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "antipode/core/hand.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"

namespace antipode {

/// The outcome a cycle reports when it found no grasp to try.
inline constexpr const char* kNoGraspFound = "no grasp found";
/// The outcome a cycle reports when the classifier predicted no hand in the scene to hold
/// (none scored above its threshold): trying again on the same scene is pointless, and the
/// run ends (ClearingStop::kNothingHolds).
inline constexpr const char* kNothingPredictedToHold = "no grasp predicted to hold";

/// One cycle of the loop.
struct ClearingCycle {
  /// How the cycle ended: a GraspOutcome's name ("success", "slipped", ...) when the cell
  /// executed a grasp, else "no grasp found", "no grasp predicted to hold", "no IK" or "no
  /// motion plan".
  std::string outcome;
  std::optional<GraspAttempt> attempt;  ///< the cell's record, when it executed a grasp
  std::optional<Hand> grasp;            ///< the grasp it executed
  int objects_before = -1;              ///< objects in the cell when the cycle began
  int objects_after = -1;               ///< ... and when it ended
  double seconds = 0.0;                 ///< wall time, capture to outcome

  bool chose_grasp() const {
    return outcome != kNoGraspFound && outcome != kNothingPredictedToHold;
  }
  bool succeeded() const { return outcome == to_string(GraspOutcome::kSuccess); }
};

/// Why a run ended.
enum class ClearingStop : std::uint8_t {
  kRunning,        ///< not ended yet
  kCleared,        ///< no object is left
  kMissStreak,     ///< that many consecutive cycles found no grasp
  kCycleLimit,     ///< the run used all its cycles
  kFailureStreak,  ///< that many consecutive attempts failed (VGN's rule)
  kNothingHolds,   ///< a cycle found no grasp predicted to hold (kNothingPredictedToHold)
};

const char* to_string(ClearingStop stop);

/// A whole run: its cycles in order and why it ended.
struct ClearingRun {
  int objects_at_start = -1;
  /// Objects the cell placed (Cell::objects_placed; -1: unknown): those beyond
  /// objects_at_start came to rest outside the workspace while the box was filled.
  int objects_placed = -1;
  std::vector<ClearingCycle> cycles;
  ClearingStop stop = ClearingStop::kRunning;

  int attempts() const;      ///< cycles that chose a grasp
  int successes() const;     ///< attempts that lifted an object out = objects removed
  int objects_left() const;  ///< objects in the cell at the end (-1: unknown)
  /// Objects that left the cell's workspace without being picked (knocked off the table or
  /// out of the box; -1: unknown): per cycle, the objects gone beyond the one a success
  /// removed. An object that comes back into the workspace does not cancel one that left.
  int objects_lost() const;
  /// Objects placed that were not in the workspace when the run began (-1: unknown).
  int missed_at_filling() const;
  /// Consecutive cycles at the end of the run that found no grasp.
  int trailing_misses() const;
  /// Consecutive attempts (cycles that chose a grasp) at the end of the run that failed.
  int trailing_failures() const;
  /// "cleared X of Y objects; Z of W attempts succeeded" (Y "?" when unknown), with "(N more
  /// fell out while the box was filled)" after Y when objects were missed at filling.
  std::string summary() const;
};

}  // namespace antipode
