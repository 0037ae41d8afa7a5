#pragma once
// Checks of stored runs.csv rows against the experiment's plan, shared by --resume and merge, so a
// hand-edited row (p_tp = 9) is refused, never copied into results.

#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/experiment/plan.hpp"

namespace hullinspect::experiment {

/// The parameter fields of a runs.csv row (run_id … seed): fixed by the plan for each run.
std::vector<std::string> run_parameter_fields(const ExperimentPlan& plan, const RunKey& run);

/// The largest counter a stored row may hold.
inline constexpr long long kMaxStoredCount = 1'000'000'000'000LL;

/// Why a stored runs.csv line cannot be the record of `run` of `plan` (a parameter differs from
/// the plan's, or an outcome is not a non-negative integer), or empty when it can.
std::string run_row_problem(const ExperimentPlan& plan, const RunKey& run, std::string_view line);

}  // namespace hullinspect::experiment
