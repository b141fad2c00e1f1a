#include <gtest/gtest.h>

#include "antipode/interfaces/clearing_run.hpp"

namespace antipode {
namespace {

ClearingCycle cycle(const std::string& outcome, int before, int after) {
  ClearingCycle c;
  c.outcome = outcome;
  c.objects_before = before;
  c.objects_after = after;
  return c;
}

TEST(ClearingRun, CountsObjectsThatLeftOtherThanByAPick) {
  ClearingRun run;
  run.objects_at_start = 10;
  run.cycles = {cycle("success", 10, 9), cycle("success", 9, 7),  // a neighbour left with it
                cycle("slipped", 7, 6), cycle("no grasp found", 6, 6)};
  EXPECT_EQ(run.successes(), 2);
  EXPECT_EQ(run.objects_left(), 6);
  EXPECT_EQ(run.objects_lost(), 2);
}

// An object the filling left outside the box, knocked into it during a run, raises the count
// of objects in the workspace; it does not cancel an object that left earlier.
TEST(ClearingRun, AnObjectComingBackDoesNotCancelOneThatLeft) {
  ClearingRun run;
  run.objects_at_start = 8;
  run.objects_placed = 10;
  run.cycles = {cycle("slipped", 8, 7), cycle("slipped", 7, 8), cycle("success", 8, 7)};
  EXPECT_EQ(run.objects_lost(), 1);
  EXPECT_EQ(run.missed_at_filling(), 2);
}

TEST(ClearingRun, LostIsUnknownWhenACycleDidNotCountTheObjects) {
  ClearingRun run;
  run.objects_at_start = 3;
  run.cycles = {cycle("success", 3, 2), cycle("slipped", -1, -1)};
  EXPECT_EQ(run.objects_lost(), -1);
  run.cycles.pop_back();
  EXPECT_EQ(run.objects_lost(), 0);
  run.objects_at_start = -1;
  EXPECT_EQ(run.objects_lost(), -1);
}

}  // namespace
}  // namespace antipode
