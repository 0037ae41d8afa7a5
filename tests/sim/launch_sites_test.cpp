// Launch sites (docs/model.md, "Launch sites"): UAVs start on the ground at a site, fly out to
// their start cells, and the mission ends when the last one has landed.

#include <gtest/gtest.h>

#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/sim/lower_bound.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/world/launch_sites.hpp"
#include "support/printers.hpp"
#include "support/strip_world.hpp"

namespace hullinspect::sim {
namespace {

using grid::Cell;

using Strip = testing::StripWorld;

TEST(LaunchSites, AUavWaitsOnTheGroundFliesOutThenActs) {
  Strip w;
  w.params.launch_sites = {{0, 0}};
  w.params.launch_transfer_s = 3;
  w.params.takeoff_time_s = 2;
  Simulator sim(w.hull, w.instance, w.params);
  // Transfer 3 + take-off 2 + flight (0, 0) → (5, 2) of 7 steps.
  EXPECT_EQ(sim.uavs()[0].away_left, 12);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{0, 0}));
  EXPECT_TRUE(sim.uavs()[0].in_transit());
  EXPECT_TRUE(sim.view().sensed.readings(0).empty());
  const std::vector<Action> east = {Action::kEast};
  for (int t = 0; t < 5; ++t) {
    sim.step(east);  // on the ground: ignored, no move, nothing sensed
    EXPECT_EQ(sim.uavs()[0].pos, (Cell{0, 0})) << "t = " << sim.time();
    EXPECT_EQ(sim.known_cells(), 0);
  }
  for (int t = 5; t < 11; ++t) sim.step(east);  // the flight out, one cell per step
  EXPECT_EQ(grid::manhattan(sim.uavs()[0].pos, Cell{5, 2}), 1);
  EXPECT_EQ(sim.known_cells(), 0);  // nothing sensed on the way out
  sim.step(east);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{5, 2}));
  EXPECT_FALSE(sim.uavs()[0].in_transit());
  EXPECT_GT(sim.known_cells(), 0);  // arrived: it senses
  sim.step(east);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{6, 2}));
  EXPECT_EQ(sim.result().uavs[0].steps_away, 12);
  EXPECT_EQ(sim.result().uavs[0].launch_site, 0);
}

TEST(LaunchSites, TheMissionEndsWhenTheLastUavHasLanded) {
  Strip w;
  w.params.uavs = 2;
  w.params.starts = {{1, 2}, {18, 2}};
  w.params.launch_sites = {{0, 0}, {19, 4}};
  w.params.launch_transfer_s = 1;
  w.params.takeoff_time_s = 1;
  Simulator sim(w.hull, w.instance, w.params);
  // Each UAV uses the site nearest its start: 0 → (0, 0), 1 → (19, 4).
  ASSERT_EQ(sim.launch_legs().site_of, (std::vector<int>{0, 1}));
  EXPECT_EQ(sim.uavs()[0].away_left, 1 + 1 + 3);
  EXPECT_EQ(sim.uavs()[1].away_left, 1 + 1 + 3);
  // UAV 0 sweeps east along the middle row, UAV 1 hovers; s2 = 3 covers rows 1..3.
  int t_complete = -1;
  Cell at_complete{};
  while (!sim.finished()) {
    const bool done = sim.complete();
    if (done && t_complete < 0) {
      t_complete = sim.time();
      at_complete = sim.uavs()[0].pos;
    }
    sim.step(std::vector<Action>{done ? Action::kHover : Action::kEast, Action::kHover});
  }
  ASSERT_GE(t_complete, 0);
  const auto r = sim.result();
  ASSERT_TRUE(r.complete);
  ASSERT_TRUE(r.t_m.has_value());
  EXPECT_EQ(*r.t_m, r.steps);
  // The hull is known when UAV 0's footprint meets UAV 1's (x = 16); it flies home from there
  // (x + 2 cells to (0, 0)), descends (1) and is carried off (1).
  EXPECT_EQ(at_complete, (Cell{15, 2}));
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{0, 0}));
  EXPECT_EQ(sim.uavs()[1].pos, (Cell{19, 4}));
  EXPECT_EQ(r.uavs[0].landed_at, t_complete + 17 + 1 + 1);
  EXPECT_EQ(r.uavs[1].landed_at, t_complete + 3 + 1 + 1);
  EXPECT_EQ(*r.t_m, std::max(r.uavs[0].landed_at, r.uavs[1].landed_at));
  const LowerBound b = lower_bound(w.hull, w.instance.truth, w.params);
  EXPECT_LE(b.t_m, *r.t_m);
}

TEST(LaunchSites, AUavOnPlaneOneClimbsBeforeFlyingHome) {
  Strip w;
  w.params.s1 = 3;  // covers rows 1..3 from plane 1
  w.params.s2 = 7;  // u_z = 2
  w.params.start_z = 1;
  w.params.starts = {{1, 2}};
  w.params.launch_sites = {{0, 0}};
  Simulator sim(w.hull, w.instance, w.params);
  const int uz = sim.plane_change_steps();
  ASSERT_EQ(uz, 2);
  // Take-off u_z + flight 3 + descent u_z.
  EXPECT_EQ(sim.uavs()[0].away_left, uz + 3 + uz);
  int t_complete = -1;
  Cell at_complete{};
  while (!sim.finished()) {
    if (sim.complete() && t_complete < 0) {
      t_complete = sim.time();
      at_complete = sim.uavs()[0].pos;
      ASSERT_EQ(sim.uavs()[0].z, 1);
    }
    sim.step(std::vector<Action>{sim.complete() ? Action::kHover : Action::kEast});
  }
  const auto r = sim.result();
  ASSERT_TRUE(r.t_m.has_value());
  // Climb u_z, fly from (18, 2) to (0, 0), descend u_z.
  EXPECT_EQ(at_complete, (Cell{18, 2}));
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{0, 0}));
  EXPECT_EQ(sim.uavs()[0].z, 2);
  EXPECT_EQ(*r.t_m, t_complete + uz + 20 + uz);
  EXPECT_EQ(r.uavs[0].landed_at, *r.t_m);
}

TEST(LaunchSites, AreRefusedOutsideTheGridOnNoFlyAndInsideTheHull) {
  Strip w;
  auto refused = [&](const world::MissionParams& p, const std::string& name) {
    try {
      world::validate(p, w.hull);
    } catch (const ParameterError& e) {
      return e.name() == name ? ::testing::AssertionSuccess()
                              : ::testing::AssertionFailure() << "named " << e.name();
    }
    return ::testing::AssertionFailure() << "accepted";
  };
  world::MissionParams p = w.params;
  p.launch_sites = {{20, 0}};
  EXPECT_TRUE(refused(p, "launch"));
  p.launch_sites = {{5, 2}};  // a hull cell inside the grid
  EXPECT_TRUE(refused(p, "launch"));
  p.launch_sites = {{0, 2}};  // a hull cell on the grid's edge: accepted
  EXPECT_NO_THROW(world::validate(p, w.hull));
  grid::Grid<std::uint8_t> zones(20, 5, 0);
  zones(0, 2) = 1;
  p.no_fly = std::make_shared<const grid::Grid<std::uint8_t>>(zones);
  EXPECT_TRUE(refused(p, "launch"));
  p = w.params;
  p.launch_transfer_s = -1;
  EXPECT_TRUE(refused(p, "launch-transfer"));
  p.launch_transfer_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(refused(p, "launch-transfer"));
  p.launch_transfer_s = 0;
  p.takeoff_time_s = -0.5;
  EXPECT_TRUE(refused(p, "takeoff-time"));
}

TEST(LaunchSites, ASiteCutOffByNoFlyPositionsIsRefused) {
  Strip w;
  grid::Grid<std::uint8_t> zones(20, 5, 0);
  zones(1, 0) = 1;
  zones(0, 1) = 1;
  w.params.no_fly = std::make_shared<const grid::Grid<std::uint8_t>>(zones);
  w.params.launch_sites = {{0, 0}};
  try {
    Simulator sim(w.hull, w.instance, w.params);
    FAIL() << "a site no flight reaches was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "launch");
  }
}

TEST(LaunchSites, WithoutSitesNothingIsAway) {
  Strip w;
  Simulator sim(w.hull, w.instance, w.params);
  EXPECT_EQ(sim.uavs()[0].away_left, 0);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{5, 2}));
  EXPECT_TRUE(sim.launch_legs().empty());
  EXPECT_EQ(sim.result().uavs[0].launch_site, -1);
}

}  // namespace
}  // namespace hullinspect::sim
