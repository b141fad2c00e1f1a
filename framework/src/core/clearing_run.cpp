#include "antipode/interfaces/clearing_run.hpp"

#include <algorithm>

namespace antipode {

const char* to_string(ClearingStop stop) {
  switch (stop) {
    case ClearingStop::kRunning:
      return "running";
    case ClearingStop::kCleared:
      return "the box is empty";
    case ClearingStop::kMissStreak:
      return "consecutive cycles found no grasp";
    case ClearingStop::kCycleLimit:
      return "the run used all its cycles";
    case ClearingStop::kFailureStreak:
      return "consecutive attempts failed";
    case ClearingStop::kNothingHolds:
      return "no grasp was predicted to hold";
  }
  return "?";
}

int ClearingRun::attempts() const {
  return int(std::count_if(cycles.begin(), cycles.end(),
                           [](const ClearingCycle& c) { return c.chose_grasp(); }));
}

int ClearingRun::successes() const {
  return int(std::count_if(cycles.begin(), cycles.end(),
                           [](const ClearingCycle& c) { return c.succeeded(); }));
}

int ClearingRun::objects_left() const {
  if (cycles.empty()) return objects_at_start;
  return cycles.back().objects_after;
}

// Counted cycle by cycle, so that an object that comes back into the workspace (knocked in
// from where the filling left it outside) cannot cancel one that left.
int ClearingRun::objects_lost() const {
  if (objects_at_start < 0) return -1;
  int lost = 0;
  for (const ClearingCycle& c : cycles) {
    if (c.objects_before < 0 || c.objects_after < 0) return -1;
    lost += std::max(0, c.objects_before - c.objects_after - int(c.succeeded()));
  }
  return lost;
}

int ClearingRun::missed_at_filling() const {
  if (objects_at_start < 0 || objects_placed < 0) return -1;
  return std::max(0, objects_placed - objects_at_start);
}

int ClearingRun::trailing_misses() const {
  int misses = 0;
  for (auto c = cycles.rbegin(); c != cycles.rend() && !c->chose_grasp(); ++c) ++misses;
  return misses;
}

int ClearingRun::trailing_failures() const {
  int failures = 0;
  for (auto c = cycles.rbegin(); c != cycles.rend() && c->chose_grasp() && !c->succeeded(); ++c)
    ++failures;
  return failures;
}

std::string ClearingRun::summary() const {
  const std::string objects = objects_at_start >= 0 ? std::to_string(objects_at_start) : "?";
  const int missed = missed_at_filling();
  const std::string fell =
      missed > 0 ? " (" + std::to_string(missed) + " more fell out while the box was filled)" : "";
  return "cleared " + std::to_string(successes()) + " of " + objects + " objects" + fell + "; " +
         std::to_string(successes()) + " of " + std::to_string(attempts()) + " attempts succeeded";
}

}  // namespace antipode
