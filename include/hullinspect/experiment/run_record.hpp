#pragma once
// What one finished run contributes to the result files, as CSV lines (without line breaks):
//   runs.csv    — its parameters, outcome and counters (deterministic: identical for any --jobs,
//                 shard or machine);
//   samples.csv — inspected and known cell counts at each curve time (the input of curves.csv);
//   timings.csv — wall-clock and planner CPU times (the only values that vary between runs).

#include <string>
#include <vector>

#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/sim/mission_result.hpp"

namespace hullinspect::experiment {

struct RunRecord {
  std::string runs;
  std::string samples;
  std::string timings;
};

std::vector<std::string> runs_header();
std::vector<std::string> samples_header(const CurveGrid& grid);
std::vector<std::string> timings_header();

/// The value of a series at time t; a mission that ended before t holds its final value.
int value_at(const std::vector<int>& series, int t);

RunRecord make_record(const ExperimentPlan& plan, const RunKey& run, const sim::MissionResult& result,
                      double wall_seconds);

}  // namespace hullinspect::experiment
