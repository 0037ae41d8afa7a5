#pragma once
// The report's tables: mean ± standard deviation of T_c and T_m per scenario × s2 × n × algorithm,
// with the count of incomplete missions and, with batteries, the sorties, computed from a finished
// runs.csv.

#include <optional>
#include <string>
#include <vector>

#include "hullinspect/experiment/csv.hpp"

namespace hullinspect::experiment {

struct TimeStats {
  int count = 0;    ///< missions that reached it
  double mean = 0;  ///< over those missions, seconds
  double std = 0;   ///< sample standard deviation (0 with fewer than two)
  /// 95 % percentile-bootstrap interval of the mean, as the paired comparisons compute theirs
  /// (bootstrap_mean, 2000 resamples, seed 1); the figures' error bars.
  double ci_low = 0, ci_high = 0;
};

struct SummaryRow {
  std::string scenario, sweep, sweep_value, algorithm;
  int s2 = 0;
  int uavs = 0;
  int runs = 0;
  int incomplete = 0;  ///< missions that hit the time limit
  TimeStats t_c, t_m;
  /// Mean analytic lower bounds over the runs (docs/model.md §11); count 0 when runs.csv has none.
  TimeStats bound_t_c, bound_t_m;
  /// The mean lower bound over only the missions that reached T_c (T_m), 0 when none has both:
  /// the ratio "(×r)" pairs each mean with the bound of the same missions.
  double t_c_bound = 0, t_m_bound = 0;
  /// The mean T_c (T_m) of those same missions, which "(×r)" divides; 0: the mean over every
  /// mission that reached it (every one of them has a bound).
  double t_c_paired = 0, t_m_paired = 0;
  /// Sorties (docs/model.md, "Batteries and sorties"), from the runs that flew any (launch sites):
  /// per UAV the mean sorties and flight seconds, the smallest battery margin flown (seconds left
  /// while airborne, over every UAV of every run; unset with unlimited flight) and the crashes.
  struct Sorties {
    int runs = 0;
    double per_uav = 0;
    double flight_s_per_uav = 0;
    std::optional<double> min_battery_s;
    long long battery_crashes = 0;
  } sorties;
};

/// One row per (scenario, s2, uavs, algorithm), in the order they first appear in runs.csv.
/// `source` names the table in errors.
std::vector<SummaryRow> summarize_runs(const CsvTable& runs, const std::string& source);

/// summary.csv: scenario, sweep, sweep_value, s2, uavs, algorithm, runs, incomplete, T_c_count,
/// T_c_mean, T_c_std, T_m_count, T_m_mean, T_m_std, bound_T_c_mean, bound_T_m_mean, T_c_ci_low,
/// T_c_ci_high, T_m_ci_low, T_m_ci_high, then the sorties: sortie_runs, sorties_per_uav,
/// flight_s_per_uav, min_battery_s, battery_crashes (empty for a cell without any). Later columns
/// are added last, so readers of the earlier columns by position are unaffected.
std::string summary_csv(const std::vector<SummaryRow>& rows);

/// Markdown: per scenario, a T_c table and a T_m table with one row per (s2, n) and one column per
/// algorithm; per sweep the same with one row per (swept value, s2, n) ("mean ± std", "[k
/// incomplete]" when some missions did not complete), and, where runs.csv has the lower bound, a
/// "lower bound" column and each mean's ratio to the mean bound of the same missions ("(×r)");
/// where runs flew sorties, a table of them per (s2, n, algorithm). Columns are padded so the text
/// also reads well in a terminal.
std::string summary_markdown(const std::vector<SummaryRow>& rows);

}  // namespace hullinspect::experiment
