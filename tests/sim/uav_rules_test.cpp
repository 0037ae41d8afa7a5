// The model's motion rules (sim/uav_rules.hpp) that the trace reader and the MissionChecker share:
// every transition the simulator makes is allowed, and each broken rule is named.

#include "hullinspect/sim/uav_rules.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace hullinspect::sim {
namespace {

UavState at(int x, int y, int z, int transit_left = 0, bool failed = false) {
  UavState s;
  s.pos = {x, y};
  s.z = z;
  s.transit_left = transit_left;
  s.failed = failed;
  return s;
}

std::string step(const UavState& a, const UavState& b, int uz) {
  return step_violation(a, b, uz).value_or("ok");
}

TEST(UavRules, WhatTheSimulatorDoesIsAllowed) {
  for (int uz : {1, 3}) {
    SCOPED_TRACE(uz);
    EXPECT_EQ(step(at(3, 3, 2), at(3, 3, 2), uz), "ok");  // hover
    EXPECT_EQ(step(at(3, 3, 2), at(4, 3, 2), uz), "ok");  // one cell
    EXPECT_EQ(step(at(3, 3, 1), at(3, 2, 1), uz), "ok");
    EXPECT_EQ(step(at(3, 3, 2), at(3, 3, 2, 0, true), uz), "ok");  // fails in place
    EXPECT_EQ(step(at(3, 3, 2, 0, true), at(3, 3, 2, 0, true), uz), "ok");
  }
  // A plane change lands at once with u_z = 1; with u_z = 3 it counts 2, 1, then lands.
  EXPECT_EQ(step(at(3, 3, 2), at(3, 3, 1), 1), "ok");
  EXPECT_EQ(step(at(3, 3, 2), at(3, 3, 2, 2), 3), "ok");
  EXPECT_EQ(step(at(3, 3, 2, 2), at(3, 3, 2, 1), 3), "ok");
  EXPECT_EQ(step(at(3, 3, 2, 1), at(3, 3, 1, 0), 3), "ok");
  // A UAV failing during a change stays in transit.
  EXPECT_EQ(step(at(3, 3, 2, 1), at(3, 3, 2, 1, true), 3), "ok");
}

TEST(UavRules, EachBrokenRuleIsNamed) {
  EXPECT_EQ(step(at(0, 0, 1), at(3, 0, 1), 1), "moved 3 cells in one step");
  EXPECT_EQ(step(at(0, 0, 1), at(1, 1, 1), 1), "moved 2 cells in one step");
  EXPECT_EQ(step(at(0, 0, 1, 0, true), at(0, 0, 1), 1), "came back after it failed");
  EXPECT_EQ(step(at(0, 0, 1, 0, true), at(1, 0, 1, 0, true), 1),
            "moved or changed plane while failed");
  EXPECT_EQ(step(at(0, 0, 1), at(1, 0, 1, 0, true), 1), "moved or changed plane while failed");
  EXPECT_EQ(step(at(0, 0, 2, 2), at(1, 0, 2, 1), 3), "moved while changing plane");
  EXPECT_EQ(step(at(0, 0, 2, 2), at(0, 0, 2, 2), 3),
            "went from plane 2 with 2 change steps left to plane 2 with 2");
  EXPECT_EQ(step(at(0, 0, 2, 2), at(0, 0, 1, 1), 3),
            "went from plane 2 with 2 change steps left to plane 1 with 1");
  EXPECT_EQ(step(at(0, 0, 2), at(1, 0, 1), 1), "moved and changed plane in one step");
  EXPECT_EQ(step(at(0, 0, 2), at(0, 0, 1), 3),
            "went from plane 2 to plane 1 with 0 change steps left in one step");
  EXPECT_EQ(step(at(0, 0, 2), at(0, 0, 2, 1), 3),
            "went from plane 2 to plane 2 with 1 change steps left in one step");
}

// Away at its launch site (flying home for a swap): the simulator flies the leg, but a climb or
// descent still happens at one cell, as on the hull.
TEST(UavRules, AnAwayUavChangesPlaneWhereItIs) {
  auto away = [](UavState s, int left) {
    s.away_left = left;
    return s;
  };
  EXPECT_EQ(step(away(at(3, 3, 1), 5), away(at(3, 3, 2), 4), 1), "ok");  // the climb home
  EXPECT_EQ(step(away(at(3, 3, 2), 4), away(at(4, 3, 2), 3), 1), "ok");  // then on plane 2
  EXPECT_EQ(step(away(at(3, 3, 2), 1), at(3, 3, 1), 1), "ok");           // the descent at resume
  EXPECT_EQ(step(away(at(3, 3, 1), 5), away(at(4, 3, 2), 4), 1),
            "moved from (3, 3) on plane 1 to (4, 3) on plane 2 in one step");
  EXPECT_EQ(step(away(at(3, 3, 2), 5), away(at(3, 4, 1), 4), 1),
            "moved from (3, 3) on plane 2 to (3, 4) on plane 1 in one step");
}

TEST(UavRules, StatesAndFootprints) {
  EXPECT_EQ(state_violation(at(0, 0, 2, 2), 3), std::nullopt);
  EXPECT_EQ(state_violation(at(0, 0, 3), 1).value_or("ok"), "is on plane 3 (expected 1 or 2)");
  EXPECT_EQ(state_violation(at(0, 0, 2, 99), 1).value_or("ok"),
            "has 99 plane-change steps left (at most 0 with u_z = 1)");
  EXPECT_EQ(state_violation(at(0, 0, 2, -1), 3).value_or("ok"),
            "has -1 plane-change steps left (at most 2 with u_z = 3)");
  EXPECT_EQ(footprint_violation(5, 7), std::nullopt);
  EXPECT_EQ(footprint_violation(3, 1).value_or("ok"),
            "s2 = 1 is not an odd integer greater than s1 = 3");
  EXPECT_EQ(footprint_violation(4, 7).value_or("ok"), "s1 = 4 is not a positive odd integer");
  EXPECT_EQ(footprint_violation(5, 8).value_or("ok"),
            "s2 = 8 is not an odd integer greater than s1 = 5");
}

}  // namespace
}  // namespace hullinspect::sim
