#pragma once
// UAV failures (docs/model.md, "Failures"): fixed (UAV k at step t), a random rate per working UAV
// per step, or one UAV at a random step. Random failures come from streams derived from the
// instance seed alone, so every planner run on that instance sees the same failures (paired).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hullinspect::world {

struct UavFailure {
  int uav = 0;
  int time = 0;  ///< the failure takes effect at the start of step t (t → t+1)
};

struct FailurePlan {
  std::vector<UavFailure> at;  ///< fixed failures
  double rate = 0;             ///< probability that a working UAV fails at a step
  int one_within = 0;          ///< > 0: one uniformly drawn UAV fails at a uniform step in [0, H)

  bool empty() const { return at.empty() && rate <= 0 && one_within <= 0; }
  /// Canonical text, "" when empty: "0@100,2@30;rate=0.001;one<400" (parts present only when set).
  std::string text() const;
};

/// Parses "UAV@T" (ParameterError "fail" naming the text when it is not two integers >= 0).
UavFailure parse_uav_failure(std::string_view text);

/// Throws ParameterError ("fail", "fail-rate", "fail-one-within") for a UAV outside [0, uavs),
/// a negative time, a rate outside [0, 1] or a negative horizon.
void validate(const FailurePlan& plan, int uavs);

/// The step at which each UAV fails (−1: never, within `time_limit`): the earliest of its fixed
/// failures, its random-rate failure and the random one. Depends only on (plan, uavs, seed).
std::vector<int> failure_times(const FailurePlan& plan, int uavs, std::uint64_t seed,
                               int time_limit);

}  // namespace hullinspect::world
