#pragma once
// The one check of stored result rows, shared by the journal reader (--resume), merge and report:
// a runs.csv row must be the record of a run of the experiment's plan (its parameters equal the
// plan's), its outcome fields must lie in their ranges (T_c and T_m within the time limit,
// hull_cells within the hull, ...) and agree with each other the way the simulator writes them
// (T_c <= T_m, steps = T_m when complete, ...), and its samples.csv row must be counts the run can
// have produced (non-negative, never decreasing, reaching hull_cells exactly at T_m). So a
// hand-edited or corrupted row is refused with its file and line, never summarised or copied.

#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/experiment/plan.hpp"

namespace hullinspect::experiment {

/// The parameter fields of a runs.csv row (run_id … seed): fixed by the plan for each run.
std::vector<std::string> run_parameter_fields(const ExperimentPlan& plan, const RunKey& run);

/// The failures field of a runs.csv row (a parameter written among the outcomes).
std::string run_failures_field(const ExperimentPlan& plan, const RunKey& run);

/// The largest counter a stored row may hold.
inline constexpr long long kMaxStoredCount = 1'000'000'000'000LL;

/// Why a stored runs.csv line cannot be the record of `run` of `plan` (a parameter differs from
/// the plan's, an outcome is out of its range, or two outcomes contradict each other), or empty
/// when it can.
std::string run_row_problem(const ExperimentPlan& plan, const RunKey& run, std::string_view line);

/// Why a stored samples.csv line cannot hold the curve samples of `run`, whose runs.csv line
/// `runs_line` has passed run_row_problem, or empty when it can.
std::string samples_row_problem(const ExperimentPlan& plan, const RunKey& run,
                                std::string_view runs_line, std::string_view samples_line);

}  // namespace hullinspect::experiment
