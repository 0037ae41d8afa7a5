// Work sharing in Part-TSP (share-work, docs/part-tsp.md "Work sharing"): hand-overs
// keep the local maps' counts exact, the split is balanced and deterministic, and whole missions
// complete under the shared MissionChecker — with failures too, which plain Part-TSP never does.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/part_tsp_share.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"
#include "support/no_fly_layouts.hpp"

namespace hullinspect::planners {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(HULLINSPECT_SANITIZED)
constexpr int kSeeds = 1;
#else
constexpr int kSeeds = 2;
#endif

using part_tsp::LocalMaps;

// Brute-force recount of every count LocalMaps keeps, against its values and owners.
::testing::AssertionResult counts_match(const LocalMaps& maps,
                                        const grid::Grid<std::int16_t>& owner) {
  for (int k = 0; k < maps.uavs(); ++k) {
    int zeros = 0;
    int twos = 0;
    int cells = 0;
    for (int i = 0; i < owner.size(); ++i) {
      if (owner[i] != k) continue;
      ++cells;
      zeros += maps.value(i) == sim::kUnknown ? 1 : 0;
      twos += maps.value(i) == sim::kCorrosionSeen ? 1 : 0;
    }
    if (zeros != maps.unknown_cells(k) || twos != maps.corrosion_to_inspect(k) ||
        cells != maps.region_cells(k)) {
      return ::testing::AssertionFailure() << "totals of UAV " << k;
    }
    for (int z = 1; z <= 2; ++z) {
      const auto& layout = maps.layout(z);
      for (int j = 0; j < layout.strips(); ++j) {
        for (int x = 0; x < owner.width(); ++x) {
          int c = 0;
          int v0 = 0;
          int v2 = 0;
          for (int y = layout.first_row(j); y <= layout.last_row(j); ++y) {
            if (owner(x, y) != k) continue;
            ++c;
            v0 += maps.value(owner.index(x, y)) == sim::kUnknown ? 1 : 0;
            v2 += maps.value(owner.index(x, y)) == sim::kCorrosionSeen ? 1 : 0;
          }
          if (c != maps.column_cells(k, z, j, x) ||
              v0 != maps.column_count(k, z, sim::kUnknown, j, x) ||
              v2 != maps.column_count(k, z, sim::kCorrosionSeen, j, x)) {
            return ::testing::AssertionFailure()
                   << "UAV " << k << " z " << z << " strip " << j << " column " << x;
          }
          if (c > 0 && (x < maps.x_begin(k) || x >= maps.x_end(k)))
            return ::testing::AssertionFailure() << "column " << x << " outside UAV " << k;
        }
      }
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(PartTspShare, HandOverMovesValuesAndCountsAndWidensTheRegion) {
  // 12 × 5: UAV 0 owns columns 0–3, UAV 1 columns 4–11; prior 2s at (6, 1) and (9, 3).
  grid::Grid<std::int16_t> owner(12, 5, 1);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 4; ++x) owner(x, y) = 0;
  grid::Grid<std::int8_t> prior(12, 5, 0);
  prior(6, 1) = 1;
  prior(9, 3) = 1;
  LocalMaps maps(owner, prior, true, 2, 1, 3);
  // UAV 1 learns something: (8, 0) clean, (9, 3) inspected.
  const std::vector<sim::Reading> r = {{owner.index(8, 0), sim::kClean, 0},
                                       {owner.index(9, 3), sim::kInspected, 0}};
  maps.ingest(1, r);
  // Columns 8–11 go to UAV 0 with UAV 1's knowledge.
  std::vector<int> piece;
  for (int y = 0; y < 5; ++y)
    for (int x = 8; x < 12; ++x) piece.push_back(owner.index(x, y));
  maps.hand_over(piece, 0, false);
  for (int i : piece) owner[i] = 0;
  EXPECT_TRUE(counts_match(maps, owner));
  EXPECT_EQ(maps.x_begin(0), 0);
  EXPECT_EQ(maps.x_end(0), 12);
  EXPECT_EQ(maps.value(owner.index(8, 0)), sim::kClean);
  EXPECT_EQ(maps.value(owner.index(9, 3)), sim::kInspected);
  EXPECT_EQ(maps.unknown_cells(0), 20 + 20 - 2);
  EXPECT_EQ(maps.corrosion_to_inspect(1), 1);  // (6, 1) stays with UAV 1
  // UAV 0's readings now update the handed cells, UAV 1's no longer do.
  maps.ingest(1, std::vector<sim::Reading>{{owner.index(10, 0), sim::kClean, 0}});
  EXPECT_EQ(maps.value(owner.index(10, 0)), sim::kUnknown);
  maps.ingest(0, std::vector<sim::Reading>{{owner.index(10, 0), sim::kClean, 0}});
  EXPECT_EQ(maps.value(owner.index(10, 0)), sim::kClean);
  // A forgetful hand-over (a failed UAV's region): back to the start values.
  std::vector<int> all;
  for (int i = 0; i < owner.size(); ++i)
    if (owner[i] == 0) all.push_back(i);
  maps.hand_over(all, 1, true);
  for (int i : all) owner[i] = 1;
  EXPECT_TRUE(counts_match(maps, owner));
  EXPECT_EQ(maps.value(owner.index(9, 3)), sim::kCorrosionSeen);
  EXPECT_EQ(maps.value(owner.index(8, 0)), sim::kUnknown);
  EXPECT_EQ(maps.corrosion_to_inspect(1), 2);
  EXPECT_EQ(maps.unknown_cells(1), 58);
  EXPECT_EQ(maps.region_cells(0), 0);
}

TEST(PartTspShare, TheHelpersPieceIsTheNearHalfOfTheWork) {
  // One row of 40 unknown cells owned by UAV 1; UAV 0 (the helper) at x = 39, the owner at x = 0.
  grid::Grid<std::int16_t> owner(40, 1, 1);
  LocalMaps maps(owner, grid::Grid<std::int8_t>(40, 1, 0), true, 2, 1, 1);
  std::vector<int> cells;
  part_tsp::region_cells(maps, 1, false, cells);
  ASSERT_EQ(cells.size(), 40U);
  grid::DistanceService open(40, 1);
  grid::Grid<int> helper(40, 1, 0);
  grid::Grid<int> own(40, 1, 0);
  part_tsp::flight_field(open, grid::Cell{39, 0}, helper);
  part_tsp::flight_field(open, grid::Cell{0, 0}, own);
  std::vector<std::pair<long long, int>> order;
  std::vector<int> piece;
  ASSERT_TRUE(part_tsp::helper_piece(maps, cells, helper, own, 40, 1, order, piece));
  // W = 40, the helper is on the work (d = 0): 20 cells, x = 20 … 39.
  ASSERT_EQ(piece.size(), 20U);
  EXPECT_EQ(piece.front(), 20);
  EXPECT_EQ(piece.back(), 39);
  // A helper 30 cells away from the nearest work (s2 = 1 cell per step): (40 − 30) / 2 = 5 cells.
  grid::Grid<std::int16_t> wide(80, 1, -1);
  for (int x = 0; x < 40; ++x) wide(x, 0) = 1;
  LocalMaps far_maps(wide, grid::Grid<std::int8_t>(80, 1, 0), true, 2, 1, 1);
  part_tsp::region_cells(far_maps, 1, false, cells);
  grid::DistanceService far_open(80, 1);
  grid::Grid<int> far_helper(80, 1, 0);
  grid::Grid<int> far_own(80, 1, 0);
  part_tsp::flight_field(far_open, grid::Cell{69, 0}, far_helper);
  part_tsp::flight_field(far_open, grid::Cell{0, 0}, far_own);
  ASSERT_TRUE(part_tsp::helper_piece(far_maps, cells, far_helper, far_own, 40, 1, order, piece));
  EXPECT_EQ(piece.size(), 5U);
  EXPECT_EQ(piece.front(), 35);
  // Not worth it when that is below the minimum.
  EXPECT_FALSE(part_tsp::helper_piece(far_maps, cells, far_helper, far_own, 40, 6, order, piece));
  EXPECT_TRUE(piece.empty());
}

TEST(PartTspShare, ThePlansTailEndsBothSoonest) {
  // Four segments along row 0 flown left to right: [0, 9], [10, 19], [20, 29], [30, 39].
  std::vector<part_tsp::PlannedVisit> visits;
  std::vector<grid::Cell> waypoints;
  for (int i = 0; i < 4; ++i) {
    const grid::Cell entry{10 * i, 0};
    const grid::Cell exit{10 * i + 9, 0};
    visits.push_back({part_tsp::StripSegment{0, 0, entry.x, exit.x}, entry, exit});
    waypoints.push_back(entry);
    waypoints.push_back(exit);
  }
  // Owner at (0, 0): 39 steps alone. Helper at (39, 0): the owner keeps three segments (29 steps)
  // while the helper flies 9 to (30, 0) and 9 along the last one; m = 2 would end at 38.
  EXPECT_EQ(part_tsp::plan_tail(visits, waypoints, {0, 0}, {39, 0}, 10), 3);
  EXPECT_EQ(part_tsp::plan_tail(visits, waypoints, {0, 0}, {39, 0}, 11), -1);  // saves 10 only
  // The first segment begun (owner at (5, 0), its entry passed): 34 steps alone, 24 with help.
  const std::span<const grid::Cell> begun(waypoints.begin() + 1, waypoints.end());
  EXPECT_EQ(part_tsp::plan_tail(visits, begun, {5, 0}, {39, 0}, 10), 3);
  // A helper far away takes nothing; one segment left: nothing to split.
  EXPECT_EQ(part_tsp::plan_tail(visits, waypoints, {0, 0}, {200, 0}, 1), -1);
  EXPECT_EQ(part_tsp::plan_tail(std::span(visits).subspan(3), std::span(waypoints).subspan(6),
                                {30, 0}, {0, 0}, 0),
            -1);
  // The cells a visit targets: strip 0 of z = 2 (s2 = 3: rows 0–2), columns 2–4, value 0.
  grid::Grid<std::int16_t> owner(12, 5, 0);
  owner(3, 1) = 1;
  grid::Grid<std::int8_t> prior(12, 5, 0);
  prior(4, 2) = 1;
  LocalMaps maps(owner, prior, true, 2, 1, 3);
  std::vector<int> cells;
  part_tsp::visit_cells(maps, 0, 2, sim::kUnknown,
                        {part_tsp::StripSegment{0, 1, 2, 4}, {2, 1}, {4, 1}}, cells);
  EXPECT_EQ(cells.size(), 7U);  // 9 less UAV 1's cell and the prior's 2
  EXPECT_EQ(std::count(cells.begin(), cells.end(), owner.index(3, 1)), 0);
}

MissionSpec spec_for(const std::string& scenario_name, int s2, int n, std::uint64_t seed,
                     bool share) {
  MissionSpec spec;
  spec.algorithm = "part-tsp";
  spec.params.uavs = n;
  spec.params.s2 = s2;
  spec.corrosion = world::scenario(scenario_name).corrosion(world::default_hull().width());
  spec.seed = seed;
  if (share) spec.planner_options = {{"share-work", "true"}};
  return spec;
}

// Records the planner's hand-over counters at the end of a mission.
struct ShareCounter final : MissionObserver {
  int failed_regions = 0;
  int pieces = 0;
  void on_start(const sim::Simulator&, const Planner&) override {}
  void on_step(const sim::Simulator&, const Planner& planner) override {
    const auto* p = dynamic_cast<const PartTspPlanner*>(&planner);
    ASSERT_NE(p, nullptr);
    failed_regions = p->failed_regions_taken();
    pieces = p->pieces_taken();
  }
};

struct SharedRun {
  sim::MissionResult result;
  ShareCounter counter;
};

SharedRun run_checked(const MissionSpec& spec, const world::HullMask& hull) {
  SharedRun run;
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker, &run.counter};
  run.result = run_mission(spec, hull, options);
  EXPECT_TRUE(checker.ok());
  return run;
}

// The paper's scenarios × s2 × n, with and without one failure at a random time: every mission
// completes under the checker; without the option, every mission with a failure whose region was
// unfinished is incomplete (so the option is what recovers).
struct Cell {
  std::string scenario;
  int s2;
};
class PartTspShareMatrix : public ::testing::TestWithParam<Cell> {};

TEST_P(PartTspShareMatrix, CompletesWithAndWithoutAFailure) {
  const auto& hull = world::default_hull();
  int recovered = 0;
  int shared = 0;
  for (int n : {4, 6, 8}) {
    for (std::uint64_t seed = 1; seed <= static_cast<std::uint64_t>(kSeeds); ++seed) {
      for (bool failure : {false, true}) {
        auto spec = spec_for(GetParam().scenario, GetParam().s2, n, seed, true);
        if (failure) spec.failures.one_within = 200;
        SCOPED_TRACE(::testing::Message() << GetParam().scenario << " s2=" << GetParam().s2 << " n="
                                          << n << " seed=" << seed << " failure=" << failure);
        const SharedRun with = run_checked(spec, hull);
        ASSERT_TRUE(with.result.complete);
        EXPECT_FALSE(with.result.stopped_idle);
        EXPECT_EQ(with.result.failed_uavs, failure ? 1 : 0);
        EXPECT_EQ(with.counter.failed_regions, failure ? 1 : 0);
        shared += with.counter.pieces;
        if (failure) {
          spec.planner_options.clear();
          const auto without = run_mission(spec, hull);
          if (!without.complete) ++recovered;
          EXPECT_TRUE(without.complete || without.stopped_idle);
        }
      }
    }
  }
  EXPECT_GT(recovered, 0);  // some failure left plain Part-TSP incomplete
  EXPECT_GT(shared, 0);     // pieces of working UAVs were taken
}

INSTANTIATE_TEST_SUITE_P(PaperScenarios, PartTspShareMatrix,
                         ::testing::Values(Cell{"perfect", 7}, Cell{"imperfect", 11},
                                           Cell{"inhomogeneous", 7}, Cell{"combined", 11}),
                         [](const auto& test) {
                           return test.param.scenario + "_s2_" + std::to_string(test.param.s2);
                         });

TEST(PartTspShare, AFixedFailureIsRecoveredWhereThePaperPlannerStopsIncomplete) {
  const auto& hull = world::default_hull();
  auto spec = spec_for("perfect", 7, 4, 3, false);
  spec.failures.at = {{2, 40}};
  const auto without = run_mission(spec, hull);
  EXPECT_FALSE(without.complete);
  EXPECT_TRUE(without.stopped_idle);
  spec.planner_options = {{"share-work", "true"}};
  const SharedRun with = run_checked(spec, hull);
  EXPECT_TRUE(with.result.complete);
  EXPECT_EQ(with.counter.failed_regions, 1);
  // Two failures: both regions are taken over.
  spec.failures.at = {{0, 25}, {3, 60}};
  const SharedRun two = run_checked(spec, hull);
  EXPECT_TRUE(two.result.complete);
  EXPECT_EQ(two.result.failed_uavs, 2);
  EXPECT_EQ(two.counter.failed_regions, 2);
}

// No-fly zones (docs/model.md §8): a piece changes hands only within a flight part. On a 60 × 20
// hull with a full wall at x = 40 (three UAVs left of it, one right): a failed left UAV's region is
// taken over and the mission completes; the right UAV's region, which no working UAV can reach, is
// not, and the mission ends (idle) incomplete instead of hovering to the time limit. With a gap in
// the wall, the right UAV's region is taken over too.
TEST(PartTspShare, NoFlyWallsKeepHandOversInsideAFlightPart) {
  const world::HullMask& hull = testing::small_keel_hull();
  auto wall = std::make_shared<testing::NoFlyMask>(60, 20, 0);
  testing::no_fly_box(*wall, 40, 0, 40, 19);
  auto gap = std::make_shared<grid::Grid<std::uint8_t>>(*wall);
  for (int y = 0; y < 3; ++y) (*gap)(40, y) = 0;
  MissionSpec spec;
  spec.algorithm = "part-tsp";
  spec.planner_options = {{"share-work", "true"}, {"tsp-solver", "heuristic"}};
  spec.params.uavs = 4;
  spec.params.time_limit = 20000;
  spec.params.starts = {{5, 10}, {20, 10}, {35, 10}, {50, 10}};
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    spec.seed = seed;
    spec.params.no_fly = wall;
    spec.failures.at = {{1, 5}};
    const SharedRun left = run_checked(spec, hull);
    EXPECT_TRUE(left.result.complete);
    EXPECT_EQ(left.counter.failed_regions, 1);
    spec.failures.at = {{3, 5}};
    const SharedRun right = run_checked(spec, hull);
    EXPECT_FALSE(right.result.complete);
    EXPECT_TRUE(right.result.stopped_idle);
    EXPECT_EQ(right.counter.failed_regions, 0);
    spec.params.no_fly = gap;
    const SharedRun through_gap = run_checked(spec, hull);
    EXPECT_TRUE(through_gap.result.complete);
    EXPECT_EQ(through_gap.counter.failed_regions, 1);
  }
}

TEST(PartTspShare, IsDeterministic) {
  const auto& hull = world::default_hull();
  auto spec = spec_for("combined", 7, 5, 4, true);
  spec.failures.one_within = 300;
  const auto a = run_mission(spec, hull);
  const auto b = run_mission(spec, hull);
  EXPECT_EQ(a.t_c, b.t_c);
  EXPECT_EQ(a.t_m, b.t_m);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.totals().moves, b.totals().moves);
  EXPECT_EQ(a.totals().steps_z1, b.totals().steps_z1);
}

TEST(PartTspShare, OffByDefaultForEveryPartTspVariant) {
  for (const char* name : {"part-tsp", "part-tsp0", "oracle-part-tsp"}) {
    const auto options = resolve_planner_options(name, {});
    ASSERT_EQ(options.count("share-work"), 1U) << name;
    EXPECT_EQ(options.at("share-work"), "false") << name;
  }
}

}  // namespace
}  // namespace hullinspect::planners
