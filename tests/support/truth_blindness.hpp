#pragma once
// Shared check that a planner cannot reach the ground truth C: run it on two instances with the
// same prior and different truth. Until the first step at which some UAV's readings differ, the two
// missions must make identical decisions — whatever the planner does, it can only react to what
// was sensed.

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "hullinspect/core/options.hpp"
#include "hullinspect/world/failures.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::testing {

struct TruthBlindnessReport {
  int first_differing_reading = -1;  ///< t at which readings first differed (-1: never)
  int steps_compared = 0;
};

/// Builds instance A (seed) and instance B = A with extra corrosion in the top six rows (out of
/// sight at t = 0), identical prior, runs `algorithm` on both (with the same `failures`) and
/// compares the applied actions. `alter_truth`, when given, makes B's truth instead of the top
/// rows (to place the difference where it is seen late).
::testing::AssertionResult planner_is_truth_blind(
    const std::string& algorithm, const OptionMap& options, const world::MissionParams& params,
    std::uint64_t seed, TruthBlindnessReport* report = nullptr,
    const world::FailurePlan& failures = {},
    const std::function<void(grid::Grid<std::int8_t>&)>& alter_truth = {});

/// An `alter_truth` for planner_is_truth_blind that places the difference where `algorithm` looks
/// last: it flies instance A (the same hull, scenario and seed) once and makes corroded the clean
/// hull cells it first sensed last (those first sensed at or after 90 % of the time at which the
/// last new cell was sensed). The top rows of the default change are seen within about 20 steps,
/// so late decisions (help, hand-overs, the end game) were never compared; with this change
/// they are. `last_first_sensed` receives that time, `altered` the number of cells changed.
std::function<void(grid::Grid<std::int8_t>&)> corrosion_where_sensed_last(
    const std::string& algorithm, const OptionMap& options, const world::MissionParams& params,
    std::uint64_t seed, const world::FailurePlan& failures = {}, int* last_first_sensed = nullptr,
    int* altered = nullptr);

}  // namespace hullinspect::testing
