#pragma once
// Combines the results directories of shards (or of separate partial runs) of one experiment.

#include <filesystem>
#include <string>
#include <vector>

namespace hullinspect::experiment {

struct MergeSummary {
  int inputs = 0;
  int runs = 0;        ///< distinct runs merged
  int duplicates = 0;  ///< runs found in more than one input (identical rows, kept once)
  int missing = 0;     ///< runs of the experiment found in no input
  std::vector<std::string> notes;
};

/// Merges `inputs` into `out` (which must not exist or be empty). Every input must hold the same
/// experiment (same config fingerprint); the same run in two inputs must have identical rows. The
/// result is what one unsharded run would have written: the same runs.csv, samples.csv and
/// curves.csv, byte for byte. Missing runs are allowed (status "partial" in the manifest).
MergeSummary merge_results(const std::vector<std::filesystem::path>& inputs,
                           const std::filesystem::path& out);

}  // namespace hullinspect::experiment
