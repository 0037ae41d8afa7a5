// The whole DTC container ship unrolled into one grid (--sides both, docs/hulls.md "The whole
// hull"): it imports, and every registered planner flies a mission on it to completion under the
// shared MissionChecker, in process and from the CLI.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::testing {
namespace {

// 2 m cells keep the missions short (the whole hull at 0.5 m is 1532 × 68 cells).
constexpr double kCellM = 2.0;

TEST(UnrolledDtc, EveryPlannerCompletesAMissionOnTheWholeHull) {
  std::string why;
  if (!installed_dtc(why)) GTEST_SKIP() << "the DTC is not installed (" << why << ")";
  world::MeshImportOptions o = world::dtc_options();
  o.side = world::HullSide::both;
  o.cell_size = kCellM;
  const world::MeshImport imported = world::import_named_mesh_hull("dtc", o);
  const world::HullMask& hull = imported.hull;
  ASSERT_TRUE(hull.geometry()->unrolled());
  // Port, bow and starboard: about twice the 355 m hull's length around.
  EXPECT_GT(hull.width() * kCellM, 2 * 355.0);
  EXPECT_GT(imported.surface_area, hull.cell_count() * kCellM * kCellM);

  std::vector<std::string> names;
  for (const auto& p : planners::planner_registry()) names.push_back(p.name);
  ASSERT_GE(names.size(), 4u);
  for (const auto& algorithm : names) {
    SCOPED_TRACE(algorithm);
    planners::MissionSpec spec;
    spec.algorithm = algorithm;
    spec.params.uavs = 4;
    spec.params.s2 = 7;
    spec.params.cell_size_m = kCellM;
    spec.seed = 3;
    spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
    MissionChecker checker;
    planners::MissionOptions options;
    options.observers = {&checker};
    const auto r = planners::run_mission(spec, hull, options);
    EXPECT_TRUE(r.complete);
    EXPECT_TRUE(checker.ok());
    EXPECT_EQ(r.hull_cells, hull.cell_count());
  }
  const auto cli = run_cli({"run", "--hull", "dtc", "--sides", "both", "--cell-size", "2", "-a",
                            "part-tsp", "-n", "4", "--s2", "7", "--seed", "3", "--json"});
  ASSERT_EQ(cli.status, 0) << cli.err;
  EXPECT_EQ(nlohmann::json::parse(cli.out).at("complete"), true);
}

}  // namespace
}  // namespace hullinspect::testing
