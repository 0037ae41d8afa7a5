#pragma once
// Shared check that a planner cannot reach the ground truth C: run it on two instances with the same
// prior and different truth. Until the first step at which some UAV's readings differ, the two
// missions must make identical decisions — whatever the planner does, it can only react to what
// was sensed.

#include <gtest/gtest.h>

#include <string>

#include "hullinspect/core/options.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::testing {

struct TruthBlindnessReport {
  int first_differing_reading = -1;  ///< t at which readings first differed (-1: never)
  int steps_compared = 0;
};

/// Builds instance A (seed) and instance B = A with extra corrosion in the top six rows (out of
/// sight at t = 0), identical prior, runs `algorithm` on both and compares the applied actions.
::testing::AssertionResult planner_is_truth_blind(const std::string& algorithm, const OptionMap& options,
                                                  const world::MissionParams& params, std::uint64_t seed,
                                                  TruthBlindnessReport* report = nullptr);

}  // namespace hullinspect::testing
