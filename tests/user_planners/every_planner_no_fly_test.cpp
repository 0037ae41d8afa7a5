// Every planner a user can name — the built-in ones and the example user planners of
// examples/planners, which this test links like the CLI does — flies missions among no-fly zones on
// the default hull under the shared MissionChecker (the model's motion rules of sim/uav_rules.hpp,
// and no UAV ever on a no-fly position), for several seeds and fleet sizes. The planners come from
// the registry, so a planner registered later is checked without editing this file.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "support/mission_checker.hpp"
#include "support/no_fly_layouts.hpp"

namespace hullinspect::testing {
namespace {

// `run -a nearest-first --uavs 4 --seed 2 --no-fly-box 40,10,40,29 --no-fly-box 110,18,117,29`
// flew onto a no-fly position at t = 172 before nearest-first took its steps from the mission's
// distance service.
NoFlyMask two_zones(const world::HullMask& hull) {
  NoFlyMask zones(hull.width(), hull.height(), 0);
  no_fly_box(zones, 40, 10, 40, 29);
  no_fly_box(zones, 110, 18, 117, 29);
  return zones;
}

class EveryPlannerAmongNoFlyZones : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryPlannerAmongNoFlyZones, FollowsTheRulesAndCompletes) {
  const std::string& algorithm = GetParam();
  const auto& hull = world::default_hull();
  const auto zones = std::make_shared<const NoFlyMask>(two_zones(hull));
  for (int uavs : {1, 4, 7}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      planners::MissionSpec spec;
      spec.algorithm = algorithm;
      // The exact TSP solver's time is not what this test is about.
      if (planners::planners().get(algorithm).resolve({}).contains("tsp-solver")) {
        spec.planner_options["tsp-solver"] = "heuristic";
      }
      spec.seed = seed;
      spec.params.uavs = uavs;
      spec.params.no_fly = zones;
      MissionChecker checker;
      planners::MissionOptions options;
      options.observers.push_back(&checker);
      const auto result = planners::run_mission(spec, hull, options);
      const auto where = fmt::format("{} with {} UAVs, seed {}", algorithm, uavs, seed);
      EXPECT_TRUE(checker.ok()) << where;
      EXPECT_GT(checker.steps_checked(), 0) << where;
      EXPECT_TRUE(result.complete) << where << ": m = " << result.m_percent(result.steps);
    }
  }
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const auto& info : planners::planner_registry()) names.push_back(info.name);
  return names;
}

std::string case_name(const ::testing::TestParamInfo<std::string>& param) {
  std::string name = param.param;
  for (char& ch : name) {
    if (ch == '-' || ch == '.') ch = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryPlannerAmongNoFlyZones,
                         ::testing::ValuesIn(planner_names()), case_name);

TEST(EveryPlannerAmongNoFlyZones, TheExampleUserPlannerIsRegistered) {
  const auto names = planner_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "nearest-first"), names.end());
}

}  // namespace
}  // namespace hullinspect::testing
