#include "hullinspect/sim/simulator.hpp"

#include <gtest/gtest.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/sim/lower_bound.hpp"
#include "support/printers.hpp"

namespace hullinspect::sim {
namespace {

using grid::Cell;

// A w × h all-hull world with the given corroded cells in C and prior cells in C'.
struct World {
  world::HullMask hull;
  world::Instance instance;
  world::MissionParams params;
  World(int w, int h, std::vector<Cell> truth, std::vector<Cell> prior, int s1, int s2, Cell start)
      : hull(grid::Grid<std::uint8_t>(w, h, 1), "test") {
    instance.truth = grid::Grid<std::int8_t>(w, h, 0);
    instance.prior = grid::Grid<std::int8_t>(w, h, 0);
    for (auto c : truth) instance.truth[c] = 1;
    for (auto c : prior) instance.prior[c] = 1;
    params.uavs = 1;
    params.s1 = s1;
    params.s2 = s2;
    params.starts = {start};
  }
};

std::vector<Action> one(Action a) {
  return {a};
}

TEST(Sensing, DetectionPlaneFollowsTheTable) {
  // 9 × 9, UAV at (4, 4) on z = 2 with a 5 × 5 footprint (cells 2..6).
  const Cell corroded_unknown{2, 2}, corroded_prior{3, 2}, false_prior{4, 2}, clean{5, 2};
  const Cell outside_corroded{7, 7}, outside_prior{8, 8};
  World w(9, 9, {corroded_unknown, corroded_prior, outside_corroded},
          {corroded_prior, false_prior, outside_prior}, 3, 5, {4, 4});
  Simulator sim(w.hull, w.instance, w.params);
  const auto& m = sim.map();
  EXPECT_EQ(m[corroded_unknown], kCorrosionSeen);  // C = 1, M = 0 → 2
  EXPECT_EQ(m[corroded_prior], kCorrosionSeen);    // C = 1, M = 2 → 2
  EXPECT_EQ(m[false_prior], kClean);               // C = 0, M = 2 → 1 (false positive cleared)
  EXPECT_EQ(m[clean], kClean);                     // C = 0, M = 0 → 1
  EXPECT_EQ(m[outside_corroded], kUnknown);        // not in sight
  EXPECT_EQ(m[outside_prior], kCorrosionSeen);     // prior, not in sight
  int sensed = 0;
  int detections = 0;
  for (const auto& r : sim.view().sensed.readings(0)) {
    ++sensed;
    const Cell c = m.cell(r.index);
    EXPECT_LE(std::abs(c.x - 4), 2);
    EXPECT_LE(std::abs(c.y - 4), 2);
    EXPECT_EQ(r.value, w.instance.truth[r.index] == 1 ? kCorrosionSeen : kClean);
    if (r.events & kEventDetection) ++detections;
  }
  EXPECT_EQ(sensed, 25);
  EXPECT_EQ(detections, 2);  // also the prior-known corroded cell: first seen at z = 2
  EXPECT_EQ(sim.result().detections, 2);
}

TEST(Sensing, CloseUpPlaneInspectsAndInspectedCellsStayInspected) {
  World w(9, 9, {{4, 4}, {5, 4}}, {{4, 4}}, 3, 5, {4, 4});
  Simulator sim(w.hull, w.instance, w.params);
  EXPECT_EQ(sim.map()(4, 4), kCorrosionSeen);
  sim.step(one(Action::kChangePlane));  // u_z = 1: arrives at t = 1 and senses 3 × 3
  EXPECT_EQ(sim.uavs()[0].z, 1);
  EXPECT_EQ(sim.map()(4, 4), kInspected);
  EXPECT_EQ(sim.map()(5, 4), kInspected);
  EXPECT_EQ(sim.map()(3, 3), kClean);
  EXPECT_EQ(sim.inspected_corroded(), 2);
  sim.step(one(Action::kChangePlane));  // back to z = 2: 3 is never downgraded to 2
  EXPECT_EQ(sim.uavs()[0].z, 2);
  EXPECT_EQ(sim.map()(4, 4), kInspected);
  for (const auto& r : sim.view().sensed.readings(0)) {
    if (r.index == sim.map().index(4, 4)) {
      EXPECT_EQ(r.value, kCorrosionSeen);       // the camera at z = 2 reports corrosion…
      EXPECT_TRUE(r.events & kEventRedundant);  // …which is nothing new
    }
  }
}

TEST(Sensing, FootprintIsClippedToTheGridAndSkipsNonHull) {
  world::HullMask hull = world::parse_text_mask("XXX..\nXXXXX\nXXXXX\n", "t");
  world::Instance inst;
  inst.truth = grid::Grid<std::int8_t>(5, 3, 0);
  for (int i = 0; i < 15; ++i) {
    if (!hull.is_hull(i)) inst.truth[i] = -1;
  }
  inst.prior = inst.truth;
  world::MissionParams p;
  p.uavs = 1;
  p.s1 = 1;
  p.s2 = 3;
  p.starts = {{4, 1}};
  Simulator sim(hull, inst, p);
  EXPECT_EQ(sim.view().sensed.readings(0).size(), 4u);  // 3 × 3 clipped to 2 × 3, minus 2 non-hull
  EXPECT_EQ(sim.map()(4, 2), kNotHull);
}

TEST(PlaneChange, TakesUzStepsWithoutSensing) {
  World w(15, 15, {}, {}, 3, 9, {7, 7});  // Δζ = 3 → u_z = 3
  Simulator sim(w.hull, w.instance, w.params);
  ASSERT_EQ(sim.plane_change_steps(), 3);
  sim.step(one(Action::kChangePlane));
  EXPECT_TRUE(sim.uavs()[0].in_transit());
  EXPECT_EQ(sim.uavs()[0].z, 2);
  EXPECT_TRUE(sim.view().sensed.readings(0).empty());
  sim.step(one(Action::kEast));  // ignored: still changing plane
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{7, 7}));
  EXPECT_TRUE(sim.view().sensed.readings(0).empty());
  sim.step(one(Action::kHover));
  EXPECT_FALSE(sim.uavs()[0].in_transit());
  EXPECT_EQ(sim.uavs()[0].z, 1);
  EXPECT_EQ(sim.view().sensed.readings(0).size(), 9u);  // arrived at t = 3: senses 3 × 3
  const auto r = sim.result();
  EXPECT_EQ(r.uavs[0].plane_changes, 1);
  EXPECT_EQ(r.uavs[0].steps_transit, 3);
  EXPECT_EQ(r.uavs[0].moves, 0);
}

TEST(Metrics, CoverageAndCorrosionTimes) {
  // 3 × 1 strip, corroded middle cell; s1 = 1, s2 = 3. At t = 0 (z = 2 at x = 1) everything is
  // seen: m = 2/3 (the corroded cell is only 2). Descend (t = 1): the middle turns 3 → complete.
  World w(3, 1, {{1, 0}}, {}, 1, 3, {1, 0});
  Simulator sim(w.hull, w.instance, w.params);
  EXPECT_NEAR(sim.m_percent(), 200.0 / 3, 1e-9);
  EXPECT_EQ(sim.c_percent(), 0);
  EXPECT_FALSE(sim.complete());
  sim.step(one(Action::kChangePlane));
  EXPECT_TRUE(sim.complete());
  const auto r = sim.result();
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.t_c, 1);
  EXPECT_EQ(r.t_m, 1);
  EXPECT_EQ(r.inspected_series, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.known_series, (std::vector<int>{2, 3}));
}

TEST(Metrics, NoCorrosionMeansCIs100FromTheStart) {
  World w(5, 1, {}, {}, 1, 3, {0, 0});
  Simulator sim(w.hull, w.instance, w.params);
  EXPECT_EQ(sim.c_percent(), 100);
  EXPECT_EQ(sim.result().t_c, 0);
}

TEST(TimeLimit, ReportsIncompleteNeverANumber) {
  World w(20, 1, {}, {}, 1, 3, {0, 0});
  w.params.time_limit = 5;
  Simulator sim(w.hull, w.instance, w.params);
  while (!sim.finished()) sim.step(one(Action::kHover));
  const auto r = sim.result();
  EXPECT_FALSE(r.complete);
  EXPECT_FALSE(r.t_m.has_value());
  EXPECT_EQ(r.steps, 5);
  EXPECT_THROW(sim.step(one(Action::kHover)), LogicError);
}

TEST(Moves, OffTheGridIsAPlannerBug) {
  World w(3, 3, {}, {}, 1, 3, {0, 0});
  Simulator sim(w.hull, w.instance, w.params);
  try {
    sim.step(one(Action::kWest));
    FAIL() << "no error";
  } catch (const LogicError& e) {
    EXPECT_STREQ(e.what(), "UAV 0 at (0, 0) was told to move west off the 3 × 3 grid at t = 0");
  }
}

TEST(Failure, AFailedUavNeitherMovesNorSenses) {
  World w(30, 1, {}, {}, 1, 3, {0, 0});
  Simulator sim(w.hull, w.instance, w.params);
  sim.fail_uav_at(0, 2);
  sim.step(one(Action::kEast));
  sim.step(one(Action::kEast));
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{2, 0}));
  sim.step(one(Action::kEast));
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{2, 0}));
  EXPECT_TRUE(sim.uavs()[0].failed);
  EXPECT_TRUE(sim.view().sensed.readings(0).empty());
}

TEST(StepTowards, MovesAlongXFirstThenY) {
  EXPECT_EQ(step_towards({0, 0}, {3, 2}), Action::kEast);
  EXPECT_EQ(step_towards({3, 0}, {3, 2}), Action::kNorth);
  EXPECT_EQ(step_towards({3, 2}, {1, 0}), Action::kWest);
  EXPECT_EQ(step_towards({1, 2}, {1, 0}), Action::kSouth);
  EXPECT_EQ(step_towards({1, 0}, {1, 0}), Action::kHover);
}

TEST(Starts, TheSimulatorPlacesTheUavsOnTheStartsItIsGiven) {
  World w(9, 9, {}, {}, 3, 5, {4, 4});
  w.params.uavs = 2;
  w.params.starts = {{1, 1}, {7, 7}};
  // The caller's start cells, not params.starts: a mission computes them once and hands them on.
  const std::vector<Cell> starts = {{2, 3}, {6, 5}};
  Simulator sim(w.hull, w.instance, w.params, starts);
  ASSERT_EQ(sim.uavs().size(), 2u);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{2, 3}));
  EXPECT_EQ(sim.uavs()[1].pos, (Cell{6, 5}));
  EXPECT_EQ(std::vector<Cell>(sim.starts().begin(), sim.starts().end()), starts);
  // Without them it computes world::start_cells itself.
  Simulator own(w.hull, w.instance, w.params);
  EXPECT_EQ(own.uavs()[0].pos, (Cell{1, 1}));
  EXPECT_EQ(own.uavs()[1].pos, (Cell{7, 7}));
  const std::vector<Cell> one_start = {{2, 3}};
  EXPECT_THROW(Simulator(w.hull, w.instance, w.params, one_start), LogicError);
}

TEST(Starts, TheLowerBoundMeasuresFromTheStartsItIsGiven) {
  // A 30 × 3 strip with one corroded cell at its right end; one UAV, params.starts at the left.
  World w(30, 3, {{29, 1}}, {}, 1, 3, {0, 1});
  const std::vector<Cell> right = {{28, 1}};
  const LowerBound given = lower_bound(w.hull, w.instance.truth, w.params, right);
  const LowerBound own = lower_bound(w.hull, w.instance.truth, w.params);
  w.params.starts = right;
  const LowerBound from_params = lower_bound(w.hull, w.instance.truth, w.params);
  EXPECT_EQ(given.reach_t_c, from_params.reach_t_c);
  EXPECT_EQ(given.t_m, from_params.t_m);
  EXPECT_LT(given.reach_t_c, own.reach_t_c);  // the corroded cell is far from the left start
}

}  // namespace
}  // namespace hullinspect::sim
