#pragma once
// Paired comparisons for the report: every algorithm of an experiment runs on the same seeds, so
// per scenario cell (scenario, s2, n) the difference between two algorithms is taken seed by seed.
// Each comparison gives the mean difference, a 95 % percentile-bootstrap confidence interval (a
// fixed seed, so a report is reproducible) and the win rate; a ranking orders the algorithms of a
// cell; and the paper's claims are checked against these numbers (docs/experiments.md).

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "hullinspect/experiment/csv.hpp"

namespace hullinspect::experiment {

/// One metric of one mission, by seed: the time reached, or absent (incomplete).
struct CellKey {
  std::string scenario;
  int s2 = 0;
  int uavs = 0;
  friend bool operator==(const CellKey&, const CellKey&) = default;
  friend auto operator<=>(const CellKey&, const CellKey&) = default;
};

struct PairedDiff {
  CellKey cell;
  std::string metric;  ///< "T_c" or "T_m"
  std::string a, b;    ///< algorithms; the difference is a − b (negative: a is faster)
  int pairs = 0;       ///< seeds where both reached the metric
  double mean = 0;     ///< mean of a − b over those seeds, seconds
  double ci_low = 0, ci_high = 0;  ///< 95 % percentile-bootstrap interval of the mean
  double win_rate = 0;             ///< share of those seeds with a < b (ties count one half)
  /// The interval excludes 0: a is faster (−1) or slower (+1); 0 when it includes 0.
  int verdict() const { return ci_high < 0 ? -1 : ci_low > 0 ? 1 : 0; }
};

struct RankEntry {
  std::string algorithm;
  double mean_rank =
      0;            ///< mean over the seeds of the algorithm's rank by the metric (1 = fastest)
  double mean = 0;  ///< mean of the metric over the seeds where every algorithm reached it
};

struct CellRanking {
  CellKey cell;
  std::string metric;
  int seeds = 0;                 ///< seeds where every ranked algorithm reached the metric
  std::vector<RankEntry> order;  ///< best first
};

struct PairedOptions {
  std::vector<std::string> metrics = {"T_c", "T_m"};
  /// Algorithms to compare, in this order; empty: all, in order of first appearance.
  std::vector<std::string> algorithms;
  int resamples = 2000;
  std::uint64_t seed = 1;  ///< of the bootstrap stream: fixed so reports are reproducible
};

struct PairedAnalysis {
  std::vector<std::string> algorithms;  ///< compared, in order
  /// Labels whose planner sees the ground truth (oracles): compared, never ranked or claimed.
  std::set<std::string> references;
  std::vector<PairedDiff> diffs;      ///< every ordered pair a before b, per cell and metric
  std::vector<CellRanking> rankings;  ///< per cell and metric
  /// The difference a − b for a cell and metric, or nullptr when it was not computed.
  const PairedDiff* find(const CellKey& cell, const std::string& metric, const std::string& a,
                         const std::string& b) const;
  /// Every cell with data, in order of first appearance.
  std::vector<CellKey> cells() const;
};

/// Reads T_c and T_m per (cell, algorithm, seed) from runs.csv and compares. `source` names the
/// table in errors. Throws InputError for a malformed number or an algorithm named in
/// options.algorithms that the runs do not hold.
PairedAnalysis analyse_pairs(const CsvTable& runs, const std::string& source,
                             const PairedOptions& options = {});

/// The mean and its 95 % percentile-bootstrap interval of `values` (exposed for tests).
struct BootstrapMean {
  double mean = 0, low = 0, high = 0;
};
BootstrapMean bootstrap_mean(const std::vector<double>& values, int resamples, std::uint64_t seed);

/// One checked claim of the paper.
struct ClaimCheck {
  std::string id;       ///< e.g. "C1"
  std::string claim;    ///< the paper's words, shortened, with the section
  std::string verdict;  ///< "held", "not held", "partly held (k of m cells)" or "not testable: …"
  std::string evidence;  ///< the numbers behind the verdict, one line
};

/// Checks the paper's claims that the experiment's cells can test (docs/experiments.md lists them).
std::vector<ClaimCheck> check_paper_claims(const PairedAnalysis& analysis);

/// Markdown: per cell a ranking line and a table of paired differences, then the claims.
std::string paired_markdown(const PairedAnalysis& analysis, const std::vector<ClaimCheck>& claims);

/// paired.csv: scenario, s2, uavs, metric, a, b, pairs, mean_diff, ci_low, ci_high, win_rate.
std::string paired_csv(const PairedAnalysis& analysis);

}  // namespace hullinspect::experiment
