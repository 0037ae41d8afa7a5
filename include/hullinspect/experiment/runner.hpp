#pragma once
// The experiment runner: runs an expanded experiment's missions (or one shard of them) on a pool
// of worker threads, appending each finished run to the journals in the output directory, then
// writes the final sorted tables, curves.csv and manifest.json. Resumable after any interruption.

#include <filesystem>
#include <functional>
#include <string>

#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/shard.hpp"

namespace hullinspect::experiment {

struct Progress {
  int total = 0;       ///< runs of this shard
  int done = 0;        ///< finished, including those found when resuming
  int resumed = 0;     ///< found finished when the runner started
  double elapsed = 0;  ///< seconds since this invocation started running missions
};

/// The most worker threads an experiment may ask for.
inline constexpr int kMaxJobs = 4096;

struct RunnerOptions {
  int jobs = 0;         ///< worker threads (0 = every core), at most kMaxJobs
  bool resume = false;  ///< continue the experiment in a non-empty output directory
  Shard shard;          ///< the part of the runs to do
  /// Called after every finished run (and once before the first), serialised, from a worker
  /// thread. Must be quick.
  std::function<void(const Progress&)> on_progress;
  /// Notices (repairs made when resuming), serialised.
  std::function<void(const std::string&)> on_note;
  /// True once the caller has stopped the experiment (Ctrl-C in Python's run_experiment): the
  /// first error is then rethrown as it is and the manifest stays `running`, as a command killed
  /// by the signal leaves it.
  std::function<bool()> interrupted;
};

struct RunnerSummary {
  int total = 0;    ///< runs of this shard
  int ran = 0;      ///< missions run by this invocation
  int resumed = 0;  ///< runs found finished
  double seconds = 0;
  int jobs = 0;
  int partitions_computed = 0;
};

/// Runs the experiment into `out`. Without `resume`, `out` must not exist or be empty (InputError
/// otherwise). With `resume`, `out` must hold this same experiment and shard (same config
/// fingerprint); finished runs are kept and only the missing ones run. A mission that throws
/// stops the runner (the finished runs stay in the journals) and the error is rethrown with the
/// run's parameters.
RunnerSummary run_experiment(const ExperimentPlan& plan, const std::filesystem::path& out,
                             const RunnerOptions& options);

}  // namespace hullinspect::experiment
