// The waypoint follower (planners/waypoint_follower.hpp) flies its lanes whole: a UAV moved off a
// straight lane (a side-step that keeps its separation) returns to the lane before it flies on,
// and a lawnmower fleet whose UAVs are side-stepped completes its mission.

#include "hullinspect/planners/waypoint_follower.hpp"

#include <gtest/gtest.h>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect::planners {
namespace {

using sim::Action;

TEST(WaypointFollower, ReturnsToTheLaneItWasMovedOff) {
  WaypointFollower f;
  f.assign({{2, 5}, {10, 5}, {10, 9}});
  EXPECT_EQ(f.next_action({2, 5}), Action::kEast);   // reached (2, 5): along the lane
  EXPECT_EQ(f.next_action({4, 4}), Action::kNorth);  // moved off: back to (4, 5) first
  EXPECT_EQ(f.next_action({4, 5}), Action::kEast);
  EXPECT_EQ(f.next_action({10, 5}), Action::kNorth);  // the vertical lane
  EXPECT_EQ(f.next_action({11, 7}), Action::kWest);   // moved off it: back to (10, 7)
}

TEST(WaypointFollower, HeadsStraightForAWaypointNotReachedFromALane) {
  WaypointFollower f;
  f.assign({{2, 5}, {10, 5}});
  // From its start (no waypoint reached yet) the Manhattan rule: x first.
  EXPECT_EQ(f.next_action({0, 0}), Action::kEast);
  // Beside the lane but beyond its ends: straight for the waypoint.
  f.next_action({2, 5});
  EXPECT_EQ(f.next_action({12, 4}), Action::kWest);
  // A skipped waypoint is no lane's start.
  f.assign({{2, 5}, {10, 5}, {20, 5}});
  f.next_action({2, 5});
  f.skip(1);
  EXPECT_EQ(f.next_action({12, 4}), Action::kEast);
}

// Eight lawnmower UAVs from one launch site with 360 s batteries at separation 1: the
// deconfliction layer side-steps UAVs off their lanes, and every lane is still flown whole.
TEST(WaypointFollower, ALawnmowerFleetSideSteppedOffItsLanesCompletes) {
  const auto& hull = world::default_hull();
  for (const std::uint64_t seed : {1, 2}) {
    MissionSpec spec;
    spec.algorithm = "lawnmower";
    spec.seed = seed;
    spec.params.uavs = 8;
    spec.params.launch_sites = {{115, 0}};
    spec.params.endurance_s = 360;
    spec.params.separation = 1;
    spec.corrosion = world::scenario("perfect").corrosion(hull.width());
    const auto r = run_mission(spec, hull);
    EXPECT_TRUE(r.complete) << "seed " << seed << ": m = " << r.m_percent(r.steps)
                            << " at t = " << r.steps;
    EXPECT_EQ(r.separation_conflicts, 0) << "seed " << seed;
    EXPECT_EQ(r.battery_crashes, 0) << "seed " << seed;
  }
}

}  // namespace
}  // namespace hullinspect::planners
