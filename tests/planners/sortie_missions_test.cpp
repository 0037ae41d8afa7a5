// Every registered planner flies missions with batteries through the sortie layer: the hull is
// completed, no UAV crashes, no sortie is longer than the endurance, every UAV lands with at least
// the reserve left, and the shared mission checker finds every step (battery included) lawful.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

struct Case {
  std::string algorithm;
  std::string scenario;
  int uavs;
  double endurance;
};

class SortieMissions : public ::testing::TestWithParam<Case> {};

TEST_P(SortieMissions, EveryPlannerCompletesWithoutACrash) {
  const Case& c = GetParam();
  const auto& hull = world::default_hull();
  MissionSpec spec;
  spec.algorithm = c.algorithm;
  spec.seed = 2;
  spec.params.uavs = c.uavs;
  // The middle of the bottom edge, and a swap of 30 s.
  spec.params.launch_sites = {{hull.width() / 2, 0}};
  spec.params.endurance_s = c.endurance;
  spec.params.swap_time_s = 30;
  spec.corrosion = world::scenario(c.scenario).corrosion(hull.width());
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker};
  const auto r = run_mission(spec, hull, options);
  EXPECT_TRUE(checker.ok());
  EXPECT_EQ(r.battery_crashes, 0);
  EXPECT_EQ(r.failed_uavs, 0);
  ASSERT_TRUE(r.complete) << "m = " << r.m_percent(r.steps) << " at t = " << r.steps;
  const int endurance = static_cast<int>(c.endurance);
  const int reserve = static_cast<int>(std::ceil(0.1 * c.endurance - 1e-9));
  int swaps = 0;
  for (std::size_t k = 0; k < r.uavs.size(); ++k) {
    const auto& u = r.uavs[k];
    ASSERT_FALSE(u.sorties.empty()) << "UAV " << k;
    EXPECT_EQ(u.swaps + 1, static_cast<int>(u.sorties.size())) << "UAV " << k;
    for (const auto& s : u.sorties) {
      ASSERT_GE(s.landing, 0) << "UAV " << k << " took off at " << s.takeoff << " and never landed";
      EXPECT_LE(s.landing - s.takeoff, endurance - reserve) << "UAV " << k;
    }
    EXPECT_GE(u.min_battery, 0) << "UAV " << k;
    EXPECT_EQ(u.landed_at, u.sorties.back().landing) << "UAV " << k;
    swaps += u.swaps;
  }
  // The shortest endurance forces swaps on every planner.
  if (c.endurance <= 400) {
    EXPECT_GT(swaps, 0);
  }
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const auto& info : planner_registry()) {
    for (const double e : {400.0, 900.0}) {
      out.push_back({info.name, "imperfect", 4, e});
      out.push_back({info.name, "perfect", 8, e});
    }
    out.push_back({info.name, "combined", 2, 500.0});
  }
  return out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& param) {
  std::string name = param.param.algorithm + "_" + param.param.scenario + "_" +
                     std::to_string(param.param.uavs) + "uavs_" +
                     std::to_string(static_cast<int>(param.param.endurance)) + "s";
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryPlanner, SortieMissions, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace hullinspect::planners
