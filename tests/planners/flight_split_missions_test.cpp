// Whole missions with no-fly walls that cut the flight space in parts (docs/model.md §8, "Flight
// components"): every registered planner completes under the shared MissionChecker, whether the
// parts hold UAVs in unequal numbers or some part holds none (its cells are then unreachable,
// counted and left out of the metrics).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/random.hpp"
#include "support/mission_checker.hpp"
#include "support/no_fly_brute.hpp"
#include "support/no_fly_layouts.hpp"

namespace hullinspect::testing {
namespace {

std::vector<std::string> planner_names() {
  std::vector<std::string> out;
  for (const auto& info : planners::planner_registry()) out.push_back(info.name);
  return out;
}

struct Mission {
  const world::HullMask* hull = nullptr;
  NoFlyMask no_fly;
  std::vector<grid::Cell> starts;  // empty: the default starts
  int uavs = 4;
  std::uint64_t seed = 1;
  int time_limit = 20000;
};

// Runs `algorithm` under the checker and checks completion and the unreachable counts against a
// brute-force recount.
sim::MissionResult expect_completes(const Mission& m, const std::string& algorithm,
                                    const std::string& what) {
  planners::MissionSpec spec;
  spec.algorithm = algorithm;
  if (algorithm.find("part-tsp") != std::string::npos)
    spec.planner_options["tsp-solver"] = "heuristic";
  spec.seed = m.seed;
  spec.params.uavs = m.uavs;
  spec.params.starts = m.starts;
  spec.params.time_limit = m.time_limit;
  spec.params.no_fly = std::make_shared<const NoFlyMask>(m.no_fly);
  MissionChecker checker;
  planners::MissionOptions options;
  options.observers.push_back(&checker);
  const auto result = planners::run_mission(spec, *m.hull, options);
  const std::string label = fmt::format("{} {} seed {}", what, algorithm, m.seed);
  EXPECT_TRUE(checker.ok()) << label;
  EXPECT_TRUE(result.complete) << label << ": m = " << result.m_percent(result.steps)
                               << " at t = " << result.steps;
  const auto starts = world::start_cells(spec.params, *m.hull);
  const auto [u1, u2] =
      brute_unreachable(*m.hull, m.no_fly, starts, spec.params.s1, spec.params.s2);
  EXPECT_EQ(result.unreachable_cells, u1) << label;
  EXPECT_EQ(result.unreachable_z2_cells, u2) << label;
  // Counted cells: those seen at z = 2, less corroded ones no z = 1 footprint reaches.
  EXPECT_LE(result.hull_cells, m.hull->cell_count() - u2) << label;
  EXPECT_GE(result.hull_cells, m.hull->cell_count() - u1) << label;
  return result;
}

class FlightSplitMissions : public ::testing::TestWithParam<std::string> {};

// A wall that cuts the flight space: the default hull, 4 default starts, a full-height wall at x =
// 100 between UAV 1 (86, 15) and UAV 2 (143, 15).
TEST_P(FlightSplitMissions, WallAcrossTheDefaultHull) {
  Mission m;
  m.hull = &world::default_hull();
  m.no_fly = NoFlyMask(m.hull->width(), m.hull->height(), 0);
  no_fly_box(m.no_fly, 100, 0, 100, 29);
  m.seed = 2;
  m.time_limit = 3000;
  expect_completes(m, GetParam(), "wall x = 100");
}

TEST_P(FlightSplitMissions, WallWithUavsOnBothSidesInUnequalNumbers) {
  Mission m;
  m.hull = &small_keel_hull();
  m.no_fly = NoFlyMask(60, 20, 0);
  no_fly_box(m.no_fly, 40, 0, 40, 19);
  m.starts = {{5, 10}, {20, 10}, {35, 10}, {50, 10}};  // three left, one right
  expect_completes(m, GetParam(), "3 | 1");
  m.starts = {{10, 10}, {45, 5}, {50, 15}, {55, 10}};  // one left, three right
  m.seed = 2;
  expect_completes(m, GetParam(), "1 | 3");
}

TEST_P(FlightSplitMissions, WallWithNoUavOnOneSide) {
  Mission m;
  m.hull = &small_keel_hull();
  m.no_fly = NoFlyMask(60, 20, 0);
  no_fly_box(m.no_fly, 30, 0, 30, 19);
  m.starts = {{5, 10}, {15, 5}, {25, 15}};
  m.uavs = 3;
  const auto right_empty = expect_completes(m, GetParam(), "no UAV right of x = 30");
  // From x ≤ 29, z = 1 (half 2) sees up to x = 31: columns 32 … 59 less the 10 corner cells.
  EXPECT_EQ(right_empty.unreachable_cells, 20 * (60 - 32) - 10);
  // Also a part enclosed between two walls, with UAVs on both outer sides.
  no_fly_box(m.no_fly, 45, 0, 45, 19);
  m.starts = {{5, 10}, {50, 10}, {25, 15}};
  const auto middle_empty = expect_completes(m, GetParam(), "empty middle");
  // Seen at z = 1 from the left up to x = 31, from the right down to x = 44.
  EXPECT_EQ(middle_empty.unreachable_cells, 20 * (44 - 32));
}

// Random walls that cut the flight space (staircases across the hull, one or two of them) and
// random starts (2 to 6 UAVs): ten seeds (40 pass; ten keep the suite fast).
TEST_P(FlightSplitMissions, RandomSplittingWallsAndStarts) {
  const auto& hull = small_keel_hull();
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    world::RandomStream rs(seed, 11);
    auto below = [&](int n) { return static_cast<int>(rs.below(static_cast<std::uint64_t>(n))); };
    Mission m;
    m.hull = &hull;
    m.seed = seed;
    m.no_fly = NoFlyMask(hull.width(), hull.height(), 0);
    const int walls = 1 + below(2);
    for (int w = 0; w < walls; ++w) {
      const bool vertical = below(3) != 0;
      const int along = vertical ? hull.height() : hull.width();
      const int across = vertical ? hull.width() : hull.height();
      int at = 3 + below(across - 6);
      for (int t = 0; t < along; ++t) {
        const int next = std::clamp(at + below(3) - 1, 1, across - 2);
        for (int a = std::min(at, next); a <= std::max(at, next); ++a) {
          if (vertical)
            m.no_fly(a, t) = 1;
          else
            m.no_fly(t, a) = 1;
        }
        at = next;
      }
    }
    m.uavs = 2 + below(5);
    while (static_cast<int>(m.starts.size()) < m.uavs) {
      const grid::Cell c = hull.mask().cell(hull.cells()[rs.below(hull.cells().size())]);
      if (m.no_fly[c] || std::find(m.starts.begin(), m.starts.end(), c) != m.starts.end()) continue;
      m.starts.push_back(c);
    }
    expect_completes(m, GetParam(), fmt::format("random walls {}", seed));
  }
}

INSTANTIATE_TEST_SUITE_P(EveryPlanner, FlightSplitMissions, ::testing::ValuesIn(planner_names()),
                         [](const ::testing::TestParamInfo<std::string>& p) {
                           std::string name = p.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace hullinspect::testing
