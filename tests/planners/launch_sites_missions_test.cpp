// Every registered planner flies a mission with launch sites to its end: the UAVs fly out, the
// hull is completed, every UAV lands at its site, and T_m is the last landing.

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
  std::vector<grid::Cell> sites;
  int uavs;
};

class LaunchSiteMissions : public ::testing::TestWithParam<Case> {};

TEST_P(LaunchSiteMissions, EveryUavLandsAndTmIsTheLastLanding) {
  const Case& c = GetParam();
  const auto& hull = world::default_hull();
  MissionSpec spec;
  spec.algorithm = c.algorithm;
  spec.seed = 3;
  spec.params.uavs = c.uavs;
  spec.params.launch_sites = c.sites;
  spec.params.launch_transfer_s = 20;
  spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker};
  const auto r = run_mission(spec, hull, options);
  EXPECT_TRUE(checker.ok());
  ASSERT_TRUE(r.complete) << "m = " << r.m_percent(r.steps);
  ASSERT_TRUE(r.t_m.has_value());
  EXPECT_EQ(*r.t_m, r.steps);
  int last = 0;
  for (std::size_t k = 0; k < r.uavs.size(); ++k) {
    EXPECT_GE(r.uavs[k].landed_at, 0) << "UAV " << k;
    EXPECT_GE(r.uavs[k].launch_site, 0) << "UAV " << k;
    // Out and home: at least the transfer and the take-off both ways.
    EXPECT_GE(r.uavs[k].steps_away, 2 * (20 + 2)) << "UAV " << k;
    last = std::max(last, r.uavs[k].landed_at);
  }
  EXPECT_EQ(*r.t_m, last);
  EXPECT_LE(r.bound_t_m, *r.t_m);
  EXPECT_LE(r.bound_t_c, r.t_c.value_or(0));
  // The same mission without launch sites completes sooner: the legs are paid.
  spec.params.launch_sites.clear();
  const auto paper = run_mission(spec, hull);
  ASSERT_TRUE(paper.t_m.has_value());
  EXPECT_GT(*r.t_m, *paper.t_m);
  EXPECT_LT(paper.bound_t_m, r.bound_t_m);
}

std::vector<Case> cases() {
  std::vector<Case> out;
  const auto& hull = world::default_hull();
  const grid::Cell stern{0, 0};
  const grid::Cell bow{hull.width() - 1, hull.height() - 1};
  for (const auto& info : planner_registry()) {
    out.push_back({info.name, {stern}, 4});
    out.push_back({info.name, {stern, bow}, 8});
  }
  return out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& param) {
  std::string name = param.param.algorithm + "_" + std::to_string(param.param.sites.size()) +
                     "sites_" + std::to_string(param.param.uavs) + "uavs";
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryPlanner, LaunchSiteMissions, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace hullinspect::planners
