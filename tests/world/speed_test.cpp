// --speed and --climb-speed (docs/model.md, "Speed and time"): the step's duration, the plane
// change in steps, the times given in seconds, and the speeds refused.

#include <gtest/gtest.h>

#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/launch_sites.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::world {
namespace {

TEST(Speed, DefaultsAreThePapersOneSecondStep) {
  MissionParams p;
  EXPECT_EQ(p.step_seconds(), 1.0);
  EXPECT_EQ(p.seconds(37), 37.0);
  EXPECT_EQ(p.steps_for_seconds(3.0000000001), 3);
  EXPECT_EQ(p.steps_for_seconds(3.5), 4);
  EXPECT_EQ(p.plane_change_steps(), 1);
}

TEST(Speed, AStepLastsACellAtTheSpeed) {
  MissionParams p;
  p.cell_size_m = 0.5;
  p.speed_m_s = 2.0;  // four cells per second
  EXPECT_DOUBLE_EQ(p.step_seconds(), 0.25);
  EXPECT_EQ(p.seconds(10), 2.5);
  EXPECT_EQ(p.steps_for_seconds(1.0), 4);
  p.speed_m_s = 5.0;  // steps of 0.1 s: 3 steps print as 0.3, not 0.30000000000000004
  EXPECT_EQ(p.seconds(3), 0.3);
}

TEST(Speed, PlaneChangeFollowsTheClimbSpeed) {
  MissionParams p;    // s2 = 7: Δζ = 1 cell = 0.5 m
  p.speed_m_s = 1.0;  // steps of 0.5 s
  // The default climb speed stays the paper's 0.5 m/s: 1 s of climbing is 2 steps now.
  EXPECT_EQ(p.plane_change_steps(), 2);
  p.climb_speed_m_s = 1.0;  // 0.5 m in 0.5 s: one step
  EXPECT_EQ(p.plane_change_steps(), 1);
  p.climb_speed_m_s = 0.1;  // 5 s: 10 steps
  EXPECT_EQ(p.plane_change_steps(), 10);
  p.speed_m_s.reset();  // one-second steps, climbing 0.1 m/s: 5 steps
  EXPECT_EQ(p.plane_change_steps(), 5);
}

TEST(Speed, LaunchTimesBecomeStepsOfTheStep) {
  MissionParams p;
  p.speed_m_s = 1.0;  // steps of 0.5 s
  p.climb_speed_m_s = 1.0;
  p.launch_sites = {{0, 0}};
  p.launch_transfer_s = 3;  // 6 steps
  p.takeoff_time_s = 1.2;   // 2.4 steps: 3
  const auto& hull = default_hull();
  const auto starts = start_cells(p, hull);
  const Reachability reach = compute_reachability(hull, nullptr, p.s1, p.s2, starts);
  const auto legs = plan_launch_legs(p, reach, starts);
  EXPECT_EQ(legs.transfer_steps, 6);
  EXPECT_EQ(legs.takeoff_steps, 3);
}

TEST(Speed, RefusedUnlessPositiveAndFinite) {
  for (const char* field : {"speed", "climb-speed"}) {
    for (double v : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity(), 1e-4, 1e4}) {
      MissionParams p;
      (std::string(field) == "speed" ? p.speed_m_s : p.climb_speed_m_s) = v;
      try {
        validate(p, default_hull());
        ADD_FAILURE() << field << " = " << v << " accepted";
      } catch (const ParameterError& e) {
        EXPECT_EQ(e.name(), field);
      }
    }
  }
  MissionParams p;
  p.speed_m_s = 3.0;
  p.climb_speed_m_s = 0.5;
  EXPECT_NO_THROW(validate(p, default_hull()));
}

}  // namespace
}  // namespace hullinspect::world
