// Whole Part-TSP / Part-TSP₀ missions on the default hull: every model.md §6 scenario, s2 ∈ {7, 9,
// 11}, n = 1…8, 20 seeds each, with the shared invariant checker — every mission must complete.
//
// The planners are built through the registry with the "heuristic" TSP solver: completion does not
// depend on the tours being optimal, and the exact solver is too slow for the large segment TSPs of
// n = 1–3 (docs/part-tsp.md). PartTspExactMissions runs the default solver on a smaller sweep.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/partition_cache.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::testing {
namespace {

/// Checks, after every step, that each UAV's plan only targets its own region: every segment lies
/// on its strip's flight row, between its ends, over columns where the strip holds cells of R_k.
class PlanInRegionChecker final : public planners::MissionObserver {
 public:
  void on_start(const sim::Simulator& sim, const planners::Planner& planner) override {
    on_step(sim, planner);
  }
  void on_step(const sim::Simulator&, const planners::Planner& planner) override {
    const auto& p = dynamic_cast<const planners::PartTspPlanner&>(planner);
    const auto& maps = p.local_maps();
    for (int k = 0; k < maps.uavs(); ++k) {
      const int z = p.plan_plane(k);
      if (z == 0) continue;
      for (const auto& v : p.path(k).visits()) {
        const auto& s = v.segment;
        const auto& layout = maps.layout(z);
        if (s.row != layout.flight_row(s.strip) || v.entry.y != s.row || v.exit.y != s.row) {
          fail(fmt::format("UAV {}: segment off its flight row", k));
        }
        for (int x = s.x_left; x <= s.x_right; ++x) {
          if (maps.column_cells(k, z, s.strip, x) == 0) {
            fail(fmt::format("UAV {}: segment column {} of strip {} has no cell of its region", k,
                             x, s.strip));
          }
        }
      }
    }
  }
  ::testing::AssertionResult ok() const {
    if (failures_.empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << failures_.front();
  }

 private:
  void fail(std::string what) {
    if (failures_.size() < 5) failures_.push_back(std::move(what));
  }
  std::vector<std::string> failures_;
};

// Under AddressSanitizer every step costs about ten times more: the sweep then runs 3 seeds per
// cell instead of 20 (the release build runs all 20).
#if defined(__SANITIZE_ADDRESS__) || defined(HULLINSPECT_SANITIZED)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

struct Cell {
  std::string scenario;
  int s2;
};

class PartTspMissions : public ::testing::TestWithParam<Cell> {};

planners::PartitionCache& shared_partitions() {
  static planners::PartitionCache cache;
  return cache;
}

std::unique_ptr<planners::Planner> make_registered(bool use_prior, OptionMap options) {
  return planners::make_planner(use_prior ? "part-tsp" : "part-tsp0", options);
}

/// Runs one mission with both checkers and asserts completion; returns false on failure.
::testing::AssertionResult completes(const world::Instance& instance,
                                     const world::MissionParams& params,
                                     planners::Planner& planner) {
  MissionChecker checker;
  PlanInRegionChecker plans;
  planners::MissionOptions mo;
  mo.observers = {&checker, &plans};
  mo.partitions = &shared_partitions();
  const auto r = planners::run_mission(world::default_hull(), instance, params, planner, mo);
  if (!r.complete) return ::testing::AssertionFailure() << "did not complete by t = " << r.steps;
  if (!r.t_c) return ::testing::AssertionFailure() << "T_c missing";
  if (r.planner.tsp_fallbacks != 0) {
    return ::testing::AssertionFailure() << r.planner.tsp_fallbacks << " TSP solver fallbacks";
  }
  if (auto ok = checker.ok(); !ok) return ok;
  return plans.ok();
}

TEST_P(PartTspMissions, EveryMissionCompletes) {
  const auto& [scenario_name, s2] = GetParam();
  const auto& hull = world::default_hull();
  const auto scenario = world::scenario(scenario_name);
  const auto corrosion = scenario.corrosion(hull.width());
  constexpr int kSeeds = kSanitized ? 3 : 20;
  for (int n = 1; n <= 8; ++n) {
    world::MissionParams params;
    params.uavs = n;
    params.s2 = s2;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const auto instance =
          world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed));
      for (bool use_prior : {true, false}) {
        auto planner = make_registered(use_prior, {{"tsp-solver", "heuristic"}});
        ASSERT_TRUE(completes(instance, params, *planner))
            << fmt::format("{} s2={} n={} seed={} {}", scenario_name, s2, n, seed,
                           use_prior ? "part-tsp" : "part-tsp0");
      }
    }
  }
}

// The refinements beyond the paper (off by default) must keep every mission complete too.
TEST(PartTspMissionsWithRefinements, EveryMissionCompletes) {
  const auto& hull = world::default_hull();
  for (const auto& scenario : world::scenarios().names()) {
    const auto corrosion = world::scenario(scenario).corrosion(hull.width());
    for (int s2 : {7, 11}) {
      for (int n : {1, 6}) {
        world::MissionParams params;
        params.uavs = n;
        params.s2 = s2;
        for (int seed = 1; seed <= 2; ++seed) {
          const auto instance =
              world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed));
          for (int refinements = 1; refinements <= 3; ++refinements) {
            for (bool use_prior : {true, false}) {
              const bool skip = (refinements & 1) != 0;
              const bool trim = (refinements & 2) != 0;
              auto planner = make_registered(use_prior, {{"tsp-solver", "heuristic"},
                                                         {"skip-resolved", skip ? "true" : "false"},
                                                         {"trim-ends", trim ? "true" : "false"}});
              ASSERT_TRUE(completes(instance, params, *planner))
                  << fmt::format("{} s2={} n={} seed={} prior={} skip={} trim={}", scenario, s2, n,
                                 seed, use_prior, skip, trim);
            }
          }
        }
      }
    }
  }
}

// The default solver ("exact") on the fleet sizes of the paper's evaluation, every scenario:
// every mission completes and no segment TSP falls back (the combined scenario at n = 8, seed 1
// is where the branch-and-cut once gave up, tests/tsp/regression_test.cpp).
TEST(PartTspExactMissions, EveryMissionCompletes) {
  const auto& hull = world::default_hull();
  for (const auto& scenario_name : world::scenarios().names()) {
    const auto corrosion = world::scenario(scenario_name).corrosion(hull.width());
    for (int s2 : {7, 11}) {
      for (int n : {4, 8}) {
        world::MissionParams params;
        params.uavs = n;
        params.s2 = s2;
        for (int seed = 1; seed <= 2; ++seed) {
          const auto instance =
              world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed));
          for (bool use_prior : {true, false}) {
            auto planner = make_registered(use_prior, {});
            ASSERT_TRUE(completes(instance, params, *planner))
                << fmt::format("{} s2={} n={} seed={} {}", scenario_name, s2, n, seed,
                               use_prior ? "part-tsp" : "part-tsp0");
          }
        }
      }
    }
  }
}

std::vector<Cell> all_cells() {
  std::vector<Cell> cells;
  for (const auto& s : world::scenarios().entries()) {
    for (int s2 : {7, 9, 11}) cells.push_back({s.name, s2});
  }
  return cells;
}

INSTANTIATE_TEST_SUITE_P(AllScenarios, PartTspMissions, ::testing::ValuesIn(all_cells()),
                         [](const auto& param_info) {
                           return fmt::format("{}_s2_{}", param_info.param.scenario,
                                              param_info.param.s2);
                         });

}  // namespace
}  // namespace hullinspect::testing
