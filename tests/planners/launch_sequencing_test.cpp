// Take-offs and landings at shared launch sites under separation (docs/model.md, "Take-offs and
// landings under separation"): every registered planner, with two and four UAVs on one site, at
// D = 1, 2 and 3, with and without batteries, completes its mission without a single conflict, and
// every UAV ends it landed at its site.

#include <gtest/gtest.h>

#include <algorithm>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

struct Case {
  std::string algorithm;
  int uavs;  // all on one site
  int separation;
  double endurance;  // 0: unlimited
};

class LaunchSequencing : public ::testing::TestWithParam<Case> {};

TEST_P(LaunchSequencing, SharedSiteWithoutConflictEveryUavLanded) {
  const Case& c = GetParam();
  const auto& hull = world::default_hull();
  MissionSpec spec;
  spec.algorithm = c.algorithm;
  spec.seed = 1;
  spec.params.uavs = c.uavs;
  spec.params.separation = c.separation;
  // The middle of the bottom edge, shared by the whole fleet.
  spec.params.launch_sites = {{hull.width() / 2, 0}};
  if (c.endurance > 0) {
    spec.params.endurance_s = c.endurance;
    spec.params.swap_time_s = 30;
  }
  spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker};
  const auto r = run_mission(spec, hull, options);
  EXPECT_TRUE(checker.ok());
  EXPECT_EQ(r.separation_conflicts, 0);
  EXPECT_EQ(r.battery_crashes, 0);
  EXPECT_EQ(r.failed_uavs, 0);
  ASSERT_TRUE(r.complete) << "m = " << r.m_percent(r.steps) << " at t = " << r.steps;
  int sorties = 0;
  for (std::size_t k = 0; k < r.uavs.size(); ++k) {
    const auto& u = r.uavs[k];
    ASSERT_FALSE(u.sorties.empty()) << "UAV " << k;
    EXPECT_GE(u.landed_at, 0) << "UAV " << k << " never landed for good";
    EXPECT_EQ(u.landed_at, u.sorties.back().landing) << "UAV " << k;
    EXPECT_LE(u.landed_at, *r.t_m) << "UAV " << k;
    sorties += static_cast<int>(u.sorties.size());
  }
  // One site: the take-offs are one after another, never two in one step.
  std::vector<int> takeoffs;
  for (const auto& u : r.uavs) {
    for (const auto& s : u.sorties) takeoffs.push_back(s.takeoff);
  }
  std::sort(takeoffs.begin(), takeoffs.end());
  EXPECT_EQ(std::adjacent_find(takeoffs.begin(), takeoffs.end()), takeoffs.end());
  EXPECT_EQ(static_cast<int>(takeoffs.size()), sorties);
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const auto& info : planner_registry()) {
    for (const int n : {2, 4}) {
      for (const int d : {1, 2, 3}) {
        for (const double e : {0.0, 400.0}) out.push_back({info.name, n, d, e});
      }
    }
  }
  return out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& param) {
  std::string name =
      param.param.algorithm + "_" + std::to_string(param.param.uavs) + "uavs_D" +
      std::to_string(param.param.separation) + "_" +
      (param.param.endurance > 0 ? std::to_string(static_cast<int>(param.param.endurance)) + "s"
                                 : std::string("unlimited"));
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryPlanner, LaunchSequencing, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace hullinspect::planners
