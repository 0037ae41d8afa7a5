// speed and climb-speed in experiment configs (docs/experiments.md): they reach every mission,
// the manifest and the run ids; without them every run keeps its id.

#include <gtest/gtest.h>

#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"

namespace hullinspect::experiment {
namespace {

ExperimentConfig parse(const std::string& yaml) {
  return parse_config(yaml, "speed.yaml", "/cfg");
}

TEST(ExperimentConfigSpeed, SpeedsReachEveryMissionTheManifestAndTheRunIds) {
  const std::string base = "uavs: [2]\ninstances: 1\n";
  const ExperimentPlan paper(parse(base));
  const ExperimentPlan fast(parse(base + "speed: 2\nclimb-speed: 0.25\n"));
  ASSERT_EQ(fast.runs().size(), 1u);
  const auto spec = fast.mission(fast.runs()[0]);
  EXPECT_EQ(spec.params.speed_m_s, 2.0);
  EXPECT_EQ(spec.params.climb_speed_m_s, 0.25);
  EXPECT_DOUBLE_EQ(fast.config().timing().step_seconds(), 0.25);
  EXPECT_FALSE(paper.mission(paper.runs()[0]).params.speed_m_s.has_value());
  EXPECT_EQ(paper.config().timing().step_seconds(), 1.0);
  EXPECT_NE(fast.runs()[0].id, paper.runs()[0].id);
  EXPECT_FALSE(config_json(paper.config()).contains("speed"));
  const auto back = config_from_json(config_json(fast.config()), "manifest.json");
  EXPECT_EQ(config_json(back), config_json(fast.config()));
  EXPECT_EQ(back.mission.speed, 2.0);
  EXPECT_EQ(back.mission.climb_speed, 0.25);
}

TEST(ExperimentConfigSpeed, LaunchTimesMayReachTheTimeLimitInSeconds) {
  // 100 steps of 0.25 s: 25 s of transfer is the most the time limit leaves (checked when the
  // missions are validated, before any runs).
  const std::string base = "uavs: [2]\ninstances: 1\ntime_limit: 100\nspeed: 2\n";
  EXPECT_NO_THROW(ExperimentPlan(parse(base + "launch: {sites: [[0, 0]], transfer: 25}\n")));
  EXPECT_THROW(ExperimentPlan(parse(base + "launch: {sites: [[0, 0]], transfer: 26}\n")),
               InputError);
}

}  // namespace
}  // namespace hullinspect::experiment
