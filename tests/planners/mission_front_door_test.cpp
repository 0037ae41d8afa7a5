// run_mission(spec, …) is the one place a mission is assembled: the instance it draws, the planner
// it builds and the failures it applies are the same whichever entry a caller takes.

#include <gtest/gtest.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::planners {
namespace {

MissionSpec small_spec() {
  MissionSpec spec;
  spec.algorithm = "part-tsp";
  spec.params.uavs = 2;
  spec.seed = 5;
  return spec;
}

TEST(MissionFrontDoor, AGivenInstanceIsTheOneTheSpecDraws) {
  const world::HullMask hull(grid::Grid<std::uint8_t>(40, 12, 1), "plate");
  MissionSpec spec = small_spec();
  spec.failures.at.push_back({1, 30});
  const auto starts = validate(spec, hull);
  const auto whole = run_mission(spec, hull);
  const auto given = run_mission(spec, hull, mission_instance(spec, hull), starts);
  EXPECT_EQ(whole.t_c, given.t_c);
  EXPECT_EQ(whole.t_m, given.t_m);
  EXPECT_EQ(whole.steps, given.steps);
  EXPECT_EQ(given.failed_uavs, 1);  // the spec's failures are applied on either entry
}

TEST(MissionFrontDoor, TheInstanceGivenIsTheOneFlown) {
  const world::HullMask hull = world::default_hull();
  const MissionSpec spec = small_spec();
  auto clean = mission_instance(spec, hull);
  for (int i : hull.cells()) clean.truth[i] = clean.prior[i] = 0;
  const auto r = run_mission(spec, hull, clean, validate(spec, hull));
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.corroded_cells, 0);
  EXPECT_GT(run_mission(spec, hull).corroded_cells, 0);
}

TEST(MissionFrontDoor, FailuresGivenInsteadOfTheSpecsAreChecked) {
  const world::HullMask hull(grid::Grid<std::uint8_t>(40, 12, 1), "plate");
  const MissionSpec spec = small_spec();
  MissionOptions options;
  options.failures.at.push_back({7, 3});  // no UAV 7 in a fleet of 2
  const auto starts = validate(spec, hull);
  EXPECT_THROW(run_mission(spec, hull, mission_instance(spec, hull), starts, options),
               ParameterError);
}

TEST(MissionFrontDoor, ValidationReturnsTheMissionsStartCells) {
  const world::HullMask hull = world::default_hull();
  MissionSpec spec = small_spec();
  spec.params.uavs = 5;
  spec.planner_options["partitioner"] = "stripes";  // its check partitions from the same cells
  EXPECT_EQ(validate(spec, hull), world::start_cells(spec.params, hull));
}

}  // namespace
}  // namespace hullinspect::planners
