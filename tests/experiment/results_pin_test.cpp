// Pins the results of a reduced paper-quick experiment (a hash of its runs.csv), so that a change
// meant to leave results alone — e.g. the distance service, which without no-fly zones must give
// Manhattan answers and paths (docs/model.md) — is checked to do so. A deliberate change of
// results updates kPinnedRunsHash; the new value comes from:
//
//   build/release/test_experiment --gtest_filter=ResultsPin.*   (prints the new hash on failure)
// or, equivalently, `hullinspect experiment --config pin.yaml --out DIR` with kPinConfig saved as
// pin.yaml, then experiment::stable_id() of DIR/runs.csv.

#include <gtest/gtest.h>

#include "experiment_test_support.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/hash.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/runner.hpp"

namespace hullinspect::experiment {
namespace {

using testing::read;
using testing::ScratchDir;

/// paper-quick's grid with one instance, two scenarios (one with a noisy prior, one
/// inhomogeneous) and the smallest and largest s2: 2 × 2 × 2 × 4 × 1 = 32 missions.
const char* kPinConfig =
    "name: pin\n"
    "hull: default\n"
    "grid: {cell_size: 0.5}\n"
    "scenarios: [imperfect, combined]\n"
    "s1: 5\n"
    "s2: [7, 11]\n"
    "theta: 90\n"
    "uavs: [4, 8]\n"
    "algorithms:\n"
    "  - lawnmower\n"
    "  - {name: part-tsp, options: {r1: 2, r2: 0}}\n"
    "  - {name: part-tsp0, options: {r1: 2, r2: 0}}\n"
    "  - coop-frontier\n"
    "instances: 1\n"
    "time_limit: 20000\n"
    "curve: {step: 5, end: 1500}\n";

// The pin covers every column, run_id, cell_id and planner_options included, so declaring a new
// option (which enters the effective options) or a new column changes it even when no mission
// does. Before re-pinning for such a change, check that runs.csv without run_id, cell_id,
// planner_options and the new column is identical to the previous build's: only then is the
// change the declaration alone.
constexpr const char* kPinnedRunsHash = "128cdbd6aef6be2b";

TEST(ResultsPin, ReducedPaperQuickRunsCsvIsUnchanged) {
  ScratchDir dir("pin");
  const ExperimentPlan plan(parse_config(kPinConfig, "pin.yaml", "."));
  RunnerOptions options;
  options.jobs = 2;
  run_experiment(plan, dir / "out", options);
  const std::string runs = read(dir / "out" / "runs.csv");
  EXPECT_EQ(stable_id(runs), kPinnedRunsHash) << "runs.csv:\n" << runs;
}

}  // namespace
}  // namespace hullinspect::experiment
