#pragma once
// DARP (Kapoutsis et al. 2017) as specified in model.md §5.1: divides the hull into connected
// regions, one per UAV, each holding its start cell, with region weights balanced within a
// tolerance. The algorithm, its parameters and measurements are described in docs/partition.md.

#include <vector>

#include "hullinspect/core/parameters.hpp"
#include "hullinspect/partition/partitioner.hpp"

namespace hullinspect::partition {

struct DarpOptions {
  /// Iterations tried at the first tolerance. Each time the goal is missed the tolerance grows by
  /// one cell and the limit halves (never below 1), so a run does at most about twice this many
  /// iterations in total. (The public Python reference uses 80000; this implementation usually
  /// converges in a few hundred.)
  int iteration_limit = 2000;
  /// Work budget, in millions of (UAV, hull cell) evaluations: an iteration costs n · #cells of
  /// them, so the first tolerance's iterations are also capped at work_budget · 10⁶ / (n · #cells)
  /// (the later tolerances halve that). The default leaves the limit at 2000 for up to 15 UAVs on
  /// the default hull (the paper's scale and more) and stops DARP in under a second where it does
  /// not converge anyway (700 × 70 hull, 16 UAVs: 415 iterations instead of 3000); a mission then
  /// falls back to `transfer` (fallback.hpp). 0: no cap.
  int work_budget = 200;
  /// Connectivity correction variation: a split region's correction factors span [1 − cc, 1 + cc].
  double cc = 0.01;
  /// Random level: each evaluation entry is multiplied by a random factor in [1 − rl, 1 + rl] per
  /// iteration (breaks ties between equidistant cells).
  double rl = 1e-4;
  /// Largest tolerance, in cells (weight units of the heaviest cell when weighted), before DARP
  /// gives up and returns the best connected partition it found (with a warning).
  int max_discrepancy = 2;
  /// Largest (and initial) gain of the fairness multiplier. In an iteration in which some UAV is
  /// over its share, UAV r's evaluation matrix is multiplied by exp(g_r · (w_r − d_r) / d_r), where
  /// w_r is its region's weight and d_r its desired weight (the exponent clamped to ±0.1);
  /// otherwise the multiplier is 1.
  double fairness_gain = 1.0;
  /// Each UAV's gain g_r is multiplied by gain_growth after a step that kept the sign of its share
  /// error (up to fairness_gain) …
  double gain_growth = 1.25;
  /// … and by gain_shrink after a step that flipped it (down to fairness_gain / 1000), so the steps
  /// become fine enough to split a block of equidistant cells between two UAVs.
  double gain_shrink = 0.7;
  /// When DARP does not converge: also consider the best-balanced iterate with its stray pieces
  /// handed to the regions they touch (always connected), and return whichever connected partition
  /// is better balanced. When false, only connected DARP iterates are returned (Error if none).
  bool repair_fallback = true;
};

/// The declared options ("iteration-limit", "cc", …; defaults from DarpOptions{}).
const Params<DarpOptions>& darp_params();
std::vector<ParamSpec> darp_option_specs();
/// Reads DarpOptions from named options; throws ParameterError("darp.<key>", …) out of range or for
/// an unknown key.
DarpOptions read_darp_options(const OptionMap& options);

class DarpPartitioner final : public Partitioner {
 public:
  explicit DarpPartitioner(DarpOptions options = {});
  /// Start cells outside the grid are rejected (ParameterError "starts"); start cells that are not
  /// hull cells are snapped to the nearest hull cell (HullMask::snap, model.md §1). Two UAVs on one
  /// cell (also after snapping) is a ParameterError("starts", …). Returns a partition whose regions
  /// are all 4-connected and hold their start cells: the balanced one when DARP converges, else the
  /// best connected one found with a warning (converged = false); throws Error when none was found.
  Partition partition(const PartitionRequest& request) const override;
  const DarpOptions& options() const { return options_; }

 private:
  DarpOptions options_;
};

}  // namespace hullinspect::partition
