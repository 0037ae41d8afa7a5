#pragma once
// A results directory: the journals runs.csv, samples.csv and timings.csv (appended while running,
// rewritten in canonical order when finished), curves.csv (derived from runs.csv and samples.csv)
// and manifest.json. The same code finalises a run, a resumed run and a merge, so a merge of shards
// is byte-identical to the unsharded result.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/run_record.hpp"

namespace hullinspect::experiment {

inline constexpr const char* kRunsFile = "runs.csv";
inline constexpr const char* kSamplesFile = "samples.csv";
inline constexpr const char* kTimingsFile = "timings.csv";
inline constexpr const char* kCurvesFile = "curves.csv";
inline constexpr const char* kManifestFile = "manifest.json";

struct StoredRuns {
  /// Finished runs by id: those with a row in both runs.csv and samples.csv (a missing timings row
  /// is left empty).
  std::unordered_map<std::string, RunRecord> records;
  /// What reading repaired: torn last lines dropped, rows of unfinished runs ignored.
  std::vector<std::string> notes;
};

/// The plan of the experiment whose results are in `dir`, from its manifest; an InputError when the
/// manifest's config does not reproduce its fingerprint.
ExperimentPlan results_plan(const std::filesystem::path& dir, const nlohmann::json& manifest);

/// Reads the journals in `dir` (missing files hold no rows). Every row passes the row checks
/// (run_row_check.hpp): a row whose id is not a run of `plan` (another experiment's results), a
/// run twice, or a row its run cannot have produced is an InputError naming the file and line.
/// `finished` results (written whole by a finished run or merge) may hold no torn line and no
/// unfinished run; otherwise those are dropped and noted.
StoredRuns read_stored_runs(const std::filesystem::path& dir, const ExperimentPlan& plan,
                            bool finished = false);

/// The records' lines per journal, in canonical order (plan position).
struct OrderedLines {
  std::vector<std::string> runs, samples, timings;
};
OrderedLines canonical_lines(const ExperimentPlan& plan, const StoredRuns& stored);

/// curves.csv: per cell and curve time, the number of runs and the mean and sample standard
/// deviation of c(t) and m(t) in percent (std empty with fewer than two runs).
std::string curves_csv(const ExperimentPlan& plan, const OrderedLines& lines);

/// Writes runs.csv, samples.csv and timings.csv in canonical order, and curves.csv (each file
/// atomically).
void write_final_tables(const std::filesystem::path& dir, const ExperimentPlan& plan,
                        const StoredRuns& stored);

/// True when `dir` does not exist or is an empty directory.
bool is_empty_dir(const std::filesystem::path& dir);

}  // namespace hullinspect::experiment
