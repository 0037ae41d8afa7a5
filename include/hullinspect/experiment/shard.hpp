#pragma once
// Shards: a deterministic 1/N of an experiment's runs, so that N processes or machines can share
// the work and `hullinspect merge` can combine their results.

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace hullinspect::experiment {

struct Shard {
  int index = 1;  ///< K, 1-based
  int count = 1;  ///< N

  /// Run at canonical position p belongs to shard K of N when p mod N = K − 1 (round robin, so
  /// every shard gets a similar mix of cells).
  bool contains(int position) const { return position % count == index - 1; }
  bool whole() const { return count == 1; }
  std::string text() const;  ///< "K/N"
};

/// Parses "K/N" with 1 ≤ K ≤ N (ParameterError "shard" otherwise).
Shard parse_shard(std::string_view text);

/// The shard of a Slurm job-array task: K = (SLURM_ARRAY_TASK_ID − SLURM_ARRAY_TASK_MIN) /
/// SLURM_ARRAY_TASK_STEP + 1 and N = SLURM_ARRAY_TASK_COUNT (MIN defaults to 0 and STEP to 1).
/// Empty when SLURM_ARRAY_TASK_ID or SLURM_ARRAY_TASK_COUNT is not set. `getenv` is injectable for
/// tests.
using EnvLookup = std::function<const char*(const char*)>;
std::optional<Shard> shard_from_slurm(const EnvLookup& getenv);

}  // namespace hullinspect::experiment
