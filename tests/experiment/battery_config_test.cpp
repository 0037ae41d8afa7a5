// The `battery` key of experiment configs (docs/model.md, "Batteries and sorties"): read into the
// missions, written to the manifest and read back, and part of the run ids only when given.

#include <gtest/gtest.h>

#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"

namespace hullinspect::experiment {
namespace {

constexpr const char* kSite = "instances: 1\nlaunch: {sites: [[115, 0]]}\n";

TEST(BatteryConfig, ReachesTheMissionsTheManifestAndTheRunIds) {
  const std::string with =
      std::string(kSite) + "battery: {endurance: 600, reserve: 30, swap-time: 90}\n";
  const auto c = parse_config(with, "b.yaml", ".");
  ASSERT_TRUE(c.mission.endurance.has_value());
  EXPECT_EQ(*c.mission.endurance, 600);
  EXPECT_EQ(c.mission.reserve, 30);
  EXPECT_EQ(c.mission.swap_time, 90);
  const ExperimentPlan plan(c);
  const auto spec = plan.mission(plan.runs().front());
  EXPECT_EQ(spec.params.endurance_s, 600);
  EXPECT_EQ(spec.params.reserve_s, 30);
  EXPECT_EQ(spec.params.swap_time_s, 90);

  const auto back = config_from_json(config_json(c), "manifest.json");
  EXPECT_EQ(back.mission.endurance, c.mission.endurance);
  EXPECT_EQ(back.mission.reserve, c.mission.reserve);
  EXPECT_EQ(back.mission.swap_time, c.mission.swap_time);

  const auto without = parse_config(kSite, "b.yaml", ".");
  EXPECT_FALSE(without.mission.endurance.has_value());
  EXPECT_FALSE(config_json(without).contains("battery"));
  EXPECT_NE(ExperimentPlan(without).runs().front().id, plan.runs().front().id);
}

}  // namespace
}  // namespace hullinspect::experiment
