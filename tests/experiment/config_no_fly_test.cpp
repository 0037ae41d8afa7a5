// The `no-fly` key of experiment configs (docs/formats.md#no-fly-masks-and-boxes): boxes in metres
// become the cells they touch, a mask file is read relative to the config, the zones reach every
// mission of the plan and the manifest, and bad input names the file, line and key.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "experiment_test_support.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/presets.hpp"

namespace hullinspect::experiment {
namespace {

using testing::ScratchDir;

std::string error_of(const std::string& yaml, const std::string& dir = "/cfg") {
  try {
    ExperimentPlan plan(parse_config(yaml, "nf.yaml", dir));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(NoFlyConfig, BoxesInMetresBecomeCells) {
  const auto c = parse_config(
      "hull: rectangle\ngrid: {width: 20, height: 10, cell_size: 0.5}\n"
      "no-fly:\n  boxes-m: [[1.0, 0, 1.5, 2.2]]\n",
      "nf.yaml", "/cfg");
  ASSERT_TRUE(c.no_fly);
  int count = 0;
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 20; ++x) {
      const bool expect = x >= 2 && x <= 2 && y >= 0 && y <= 4;  // [1.0, 1.5) m, [0, 2.5) m
      EXPECT_EQ((*c.no_fly)(x, y) != 0, expect) << x << "," << y;
      count += (*c.no_fly)(x, y);
    }
  }
  EXPECT_EQ(count, 5);
  const ExperimentPlan plan(c);
  EXPECT_EQ(plan.mission(plan.runs().front()).params.no_fly, c.no_fly);
  EXPECT_TRUE(config_json(c).contains("no_fly"));
  // Without no-fly zones the resolved config (and so every run and cell id) is unchanged.
  EXPECT_FALSE(config_json(parse_config("hull: default\n", "x.yaml", "/cfg")).contains("no_fly"));
}

TEST(NoFlyConfig, MaskFileIsReadBesideTheConfig) {
  ScratchDir dir("mask");
  std::ofstream(dir / "zones.txt") << "....\n.X..\n";
  const auto c =
      parse_config("hull: rectangle\ngrid: {width: 4, height: 2}\nno-fly: {file: zones.txt}\n",
                   "nf.yaml", dir.path());
  ASSERT_TRUE(c.no_fly);
  EXPECT_EQ((*c.no_fly)(1, 0), 1);
  EXPECT_EQ((*c.no_fly)(1, 1), 0);
}

TEST(NoFlyConfig, TheObstaclesPresetHasZones) {
  const auto c = load_preset("obstacles");
  ASSERT_TRUE(c.no_fly);
  EXPECT_EQ((*c.no_fly)(20, 29), 1);   // mooring line at 10 m
  EXPECT_EQ((*c.no_fly)(20, 9), 0);    // which ends 5 m above the keel
  EXPECT_EQ((*c.no_fly)(113, 25), 1);  // the gangway
}

TEST(NoFlyConfig, BadInputNamesFileLineAndKey) {
  const std::string grid = "hull: rectangle\ngrid: {width: 20, height: 10}\n";
  EXPECT_EQ(error_of(grid + "no-fly: {boxes: []}\n"),
            "nf.yaml:3: no-fly.boxes: unknown key (known: file, boxes-m)");
  EXPECT_EQ(error_of(grid + "no-fly:\n  boxes-m: [[0, 0, 1]]\n"),
            "nf.yaml:4: no-fly.boxes-m[0]: expected [x0, y0, x1, y1] in metres");
  EXPECT_EQ(error_of(grid + "no-fly:\n  boxes-m: [[2, 0, 1, 1]]\n"),
            "nf.yaml:4: no-fly.boxes-m[0]: needs x0 <= x1 and y0 <= y1");
  EXPECT_EQ(error_of(grid + "no-fly:\n  boxes-m: [[0, 0, 11, 1]]\n"),
            "nf.yaml:4: no-fly.boxes-m[0]: reaches cell (21, 1), outside the 20 × 10 grid of 0.5 m "
            "cells");
  EXPECT_EQ(error_of(grid + "no-fly:\n  boxes-m: 3\n"),
            "nf.yaml:4: no-fly.boxes-m: expected a list of [x0, y0, x1, y1] boxes in metres");
  // Zones over every hull cell leave no start: found when the plan's cells are validated.
  EXPECT_EQ(error_of(grid + "uavs: 1\nno-fly:\n  boxes-m: [[0, 0, 10, 5]]\n"),
            "nf.yaml:5: no-fly: leaves 0 hull cells outside no-fly zones for 1 UAV to start on");
}

TEST(NoFlyConfig, AScenarioCanHaveItsOwnZones) {
  const auto c = parse_config(
      "hull: rectangle\ngrid: {width: 20, height: 10, cell_size: 0.5}\n"
      "scenarios:\n"
      "  - perfect\n"
      "  - {name: perfect-obstacles, base: perfect, no-fly: {boxes-m: [[1.0, 0, 1.5, 2.2]]}}\n",
      "nf.yaml", "/cfg");
  EXPECT_FALSE(c.no_fly);
  ASSERT_EQ(c.scenarios.size(), 2u);
  EXPECT_FALSE(c.scenarios[0].no_fly);
  ASSERT_TRUE(c.scenarios[1].no_fly);
  EXPECT_EQ((*c.scenarios[1].no_fly)(2, 4), 1);
  EXPECT_EQ((*c.scenarios[1].no_fly)(3, 4), 0);
  const ExperimentPlan plan(c);
  int with_zones = 0;
  for (const auto& run : plan.runs()) {
    const auto& scenario = c.scenarios[static_cast<std::size_t>(plan.cells()[run.cell].scenario)];
    EXPECT_EQ(plan.mission(run).params.no_fly, scenario.no_fly) << scenario.name;
    with_zones += scenario.no_fly ? 1 : 0;
  }
  EXPECT_GT(with_zones, 0);
  // The scenario's zones reach the manifest and its run ids; the plain scenario's ids are the
  // ids of the same scenario in a config without the other one.
  const auto j = config_json(c);
  EXPECT_FALSE(j["scenarios"][0].contains("no_fly"));
  EXPECT_TRUE(j["scenarios"][1].contains("no_fly"));
  EXPECT_EQ(config_from_json(j, "x").scenarios[1].no_fly_spec, j["scenarios"][1]["no_fly"]);
  const ExperimentPlan plain(parse_config(
      "hull: rectangle\ngrid: {width: 20, height: 10, cell_size: 0.5}\nscenarios: [perfect]\n",
      "nf.yaml", "/cfg"));
  EXPECT_EQ(plain.cells().front().id, plan.cells().front().id);
  EXPECT_NE(plan.cells()[0].id, plan.cells()[plan.cells().size() / 2].id);
}

TEST(NoFlyConfig, ScenarioZonesAndTopLevelZonesAreNotCombined) {
  const std::string grid = "hull: rectangle\ngrid: {width: 20, height: 10}\n";
  EXPECT_EQ(error_of(grid + "no-fly: {boxes-m: [[0, 0, 1, 1]]}\nscenarios:\n"
                            "  - {name: a, no-fly: {boxes-m: [[2, 0, 3, 1]]}}\n"),
            "nf.yaml:5: scenarios[0].no-fly: cannot be combined with the top-level 'no-fly' (give "
            "the zones in one place)");
  EXPECT_EQ(error_of(grid + "scenarios:\n  - {name: a, no-fly: {boxes-m: [[2, 0, 1, 1]]}}\n"),
            "nf.yaml:4: scenarios[0].no-fly.boxes-m[0]: needs x0 <= x1 and y0 <= y1");
}

}  // namespace
}  // namespace hullinspect::experiment
