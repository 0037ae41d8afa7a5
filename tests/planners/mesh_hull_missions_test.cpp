// Whole missions of every planner on mesh hulls: a Wigley hull and the DTC (when installed), with
// generated maps and with the user's own truth, under the shared MissionChecker.
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mesh_fixtures.hpp"
#include "support/mission_checker.hpp"
#include "support/seam_hull.hpp"

namespace hullinspect::planners {
namespace {

const char* const kPlanners[] = {"lawnmower", "part-tsp", "part-tsp0", "coop-frontier"};

void run_every_planner(const world::HullMask& hull, int uavs, int s2, const world::UserMaps& maps) {
  for (const char* algorithm : kPlanners) {
    MissionSpec spec;
    spec.algorithm = algorithm;
    spec.params.uavs = uavs;
    spec.params.s2 = s2;
    spec.params.cell_size_m = hull.geometry()->cell_size;
    spec.seed = 5;
    spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
    spec.maps = maps;
    testing::MissionChecker checker;
    MissionOptions options;
    options.observers = {&checker};
    const auto r = run_mission(spec, hull, options);
    EXPECT_TRUE(r.complete) << algorithm << " on " << hull.source();
    EXPECT_TRUE(checker.ok()) << algorithm;
    EXPECT_EQ(r.hull_cells, hull.cell_count());
  }
}

TEST(MeshHullMissions, EveryPlannerCompletesOnAWigleyHull) {
  world::MeshImportOptions o;
  o.cell_size = 1.0;  // 100 × 8 cells
  const world::HullMask hull =
      world::import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o).hull;
  run_every_planner(hull, 3, 7, {});
  // With the user's own truth: one corroded strip along the keel.
  auto truth = std::make_shared<world::CorrosionMap>();
  truth->source = "keel";
  truth->cells = grid::Grid<std::int8_t>(hull.width(), hull.height(), -1);
  for (int i : hull.cells()) truth->cells[i] = hull.mask().cell(i).y == 0 ? 1 : 0;
  world::UserMaps maps;
  maps.truth = truth;
  run_every_planner(hull, 3, 7, maps);
}

// Counts the steps some UAV spent flying to a distant neighbour.
struct LongFlights final : MissionObserver {
  long long steps = 0;
  void on_start(const sim::Simulator&, const Planner&) override {}
  void on_step(const sim::Simulator& sim, const Planner&) override {
    for (const sim::UavState& u : sim.uavs()) steps += u.flight_left > 0 ? 1 : 0;
  }
};

// Every registered planner's mission on `hull` (`uavs` UAVs, the imperfect scenario) completes
// under the shared MissionChecker; `watch` observes each mission and `after(name)` runs after it.
// `configure` sets anything else of the spec (starts, no-fly zones).
void every_registered_planner_completes(
    const world::HullMask& hull, int uavs, MissionObserver& watch,
    const std::function<void(const std::string&)>& after,
    const std::function<void(MissionSpec&)>& configure = [](MissionSpec&) {}) {
  for (const auto& info : planner_registry()) {
    SCOPED_TRACE(info.name);
    MissionSpec spec;
    spec.algorithm = info.name;
    spec.params.uavs = uavs;
    spec.params.cell_size_m = hull.geometry()->cell_size;
    spec.seed = 5;
    spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
    configure(spec);
    testing::MissionChecker checker;
    MissionOptions options;
    options.observers = {&checker, &watch};
    const auto r = run_mission(spec, hull, options);
    EXPECT_TRUE(r.complete);
    EXPECT_TRUE(checker.ok());
    EXPECT_EQ(r.hull_cells, hull.cell_count());
    EXPECT_EQ(r.unreachable_cells, 0);
    after(info.name);
  }
}

TEST(MeshHullMissions, EveryRegisteredPlannerFliesTheUnrolledHullsRealFlights) {
  world::MeshImportOptions o;
  o.side = world::HullSide::both;
  o.cell_size = 1.0;
  const world::HullMask hull =
      world::import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o).hull;
  LongFlights flights;
  every_registered_planner_completes(hull, 3, flights, [&](const std::string& name) {
    // Around the bow the UAVs cannot avoid flights longer than one step.
    EXPECT_GT(flights.steps, 0) << name;
    flights.steps = 0;
  });
}

// Counts the moves across the seam of a grid that closes on itself (a row's two ends).
struct SeamCrossings final : MissionObserver {
  std::vector<grid::Cell> last;
  long long moves = 0;
  void on_start(const sim::Simulator& sim, const Planner&) override {
    last.clear();
    for (const sim::UavState& u : sim.uavs()) last.push_back(u.pos);
  }
  void on_step(const sim::Simulator& sim, const Planner&) override {
    const int w = sim.map().width();
    for (std::size_t k = 0; k < last.size(); ++k) {
      const grid::Cell now = sim.uavs()[k].pos;
      if (now.y == last[k].y && std::abs(now.x - last[k].x) == w - 1) ++moves;
      last[k] = now;
    }
  }
};

TEST(MeshHullMissions, EveryRegisteredPlannerCompletesOnAHullClosedAtItsSeam) {
  world::MeshImportOptions o;
  o.side = world::HullSide::both;
  o.include_transom = true;  // the Wigley stern is a point: the grid closes there
  o.cell_size = 1.0;
  const world::HullMask hull =
      world::import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o).hull;
  ASSERT_TRUE(hull.geometry()->seam);
  SeamCrossings seam;
  every_registered_planner_completes(hull, 4, seam, [](const std::string&) {});
  // The planners that follow the distance service's paths take the short way across the stern.
  EXPECT_GT(seam.moves, 0);
}

// A small hull round a cylinder, a no-fly wall across it from keel to deck: every UAV starts west
// of the wall, and the cells east of it are reached only across the seam.
TEST(MeshHullMissions, EveryRegisteredPlannerReachesTheFarSideOfAWallAcrossTheSeam) {
  std::string rows;
  for (int y = 0; y < 6; ++y) rows += std::string(36, 'X') + "\n";
  const world::HullMask hull = testing::seam_cylinder_hull(rows);
  auto wall = std::make_shared<world::NoFlyMask>(hull.width(), hull.height(), 0);
  for (int y = 0; y < hull.height(); ++y) (*wall)(12, y) = 1;
  SeamCrossings seam;
  int missions = 0;
  every_registered_planner_completes(
      hull, 3, seam,
      [&](const std::string& name) {
        EXPECT_GT(seam.moves, 0) << name;
        seam.moves = 0;
        ++missions;
      },
      [&](MissionSpec& spec) {
        spec.params.starts = {{2, 1}, {6, 3}, {10, 4}};
        spec.params.no_fly = wall;
      });
  EXPECT_GE(missions, 4);
}

TEST(MeshHullMissions, EveryPlannerCompletesOnTheDtc) {
  std::string why;
  const auto dtc = testing::installed_dtc(why);
  if (!dtc) GTEST_SKIP() << why;
  world::MeshImportOptions o = world::dtc_options();
  o.cell_size = 4.0;  // 94 × 9 cells keeps the four missions short
  const world::HullMask hull = world::import_mesh_file(*dtc, o).hull;
  run_every_planner(hull, 4, 7, {});
}

}  // namespace
}  // namespace hullinspect::planners
