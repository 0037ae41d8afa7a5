#pragma once
// The prior-aware partition (docs/model.md §5.5, the paper's future work 1): DARP weighted by the
// expected work of each hull cell — its coverage at z = 2 plus the z = 1 inspection the prior
// predicts there — so a region with many expected corroded cells gets fewer cells. One option pair
// for every partitioned planner (lawnmower, Part-TSP, Sweep-Inspect): `prior-weights` switches it
// on, `prior-statistics` makes the odds aware of the prior's quality (p_TP, p_FP).

#include <cstdint>
#include <string>

#include "hullinspect/core/parameters.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::planners {

/// The probability that a hull cell is corroded given the prior's value there.
struct CorrosionOdds {
  double in_prior = 1.0;       ///< P(C = 1 | C' = 1)
  double outside_prior = 0.0;  ///< P(C = 1 | C' = 0)
  bool operator==(const CorrosionOdds&) const = default;
};

/// The odds in one zone of the instance generator (docs/model.md §2) with the prior's p_TP and
/// p_FP: centres are independent per cell, rectangle sides uniform over the odd numbers up to
/// l_C, the hull's edges ignored. A prior cell is covered by a true-positive rectangle (then
/// corroded) or only by false-positive ones (then corroded as often as a cell outside the
/// prior); a cell outside the prior is corroded when a missed true rectangle (probability
/// 1 − p_TP per true centre) covers it. p_TP = 1, p_FP = 0 gives exactly {1, 0}.
CorrosionOdds corrosion_odds(const world::CorrosionZone& zone, double p_tp, double p_fp);

/// P(C = 1 | C') of every hull cell (0 elsewhere): the odds of its column's zone from
/// `context.corrosion` when `use_statistics` and it is known; otherwise a prior cell is corroded
/// and no other is.
grid::Grid<double> corrosion_probabilities(const PlannerContext& context, bool use_statistics);

/// The weight of every hull cell for the partition (0 elsewhere), in units of one z = 2 sweep
/// step per s2 cells: 1 + P(corroded | C')·s2/s1 (a z = 1 pass over a corroded cell costs 1/s1
/// of a step, a z = 2 pass over any cell 1/s2), P from corrosion_probabilities.
grid::Grid<double> prior_work_weights(const PlannerContext& context, bool use_statistics);

/// The mean of P(C = 1 | C' = 1) over the prior's cells from `context.corrosion` (what a cell of
/// the prior is worth, by the statistics the instance was drawn with); −1 when the statistics are
/// unknown (a user's prior map) or the prior is empty.
double expected_prior_precision(const PlannerContext& context);

/// The request of a planner that partitions the hull among its UAVs: the hull, the start cells,
/// the partitioner's seed, the no-fly zones and neighbour flights (add_no_fly), and with
/// `prior_weights` the expected work per cell as weights (else none: uniform).
partition::PartitionRequest partition_request(const PlannerContext& context,
                                              std::uint64_t partition_seed, bool prior_weights,
                                              bool prior_statistics);

/// The same for a planner whose options struct has the fields `partition_seed`, `prior_weights`
/// and `prior_statistics`.
template <class Options>
partition::PartitionRequest partition_request(const PlannerContext& context,
                                              const Options& options) {
  return partition_request(context, options.partition_seed, options.prior_weights,
                           options.prior_statistics);
}

inline constexpr const char* kPriorWeightsHelp =
    "partition weighted by the expected work per cell: its coverage at z = 2 plus the z = 1 "
    "inspection the prior predicts (docs/model.md 5.5)";
inline constexpr const char* kPriorStatisticsHelp =
    "with prior-weights: the odds that a cell is corroded use the scenario's p_TP and p_FP "
    "(false: every prior cell is corroded, no other)";

/// Declares `prior-weights` and `prior-statistics` on a planner whose options struct has the
/// fields `prior_weights` and `prior_statistics` (defaults: the struct's initialisers).
template <class Options>
void declare_prior_weight_options(Params<Options>& p) {
  p.flag("prior-weights", &Options::prior_weights, kPriorWeightsHelp)
      .flag("prior-statistics", &Options::prior_statistics, kPriorStatisticsHelp);
}

}  // namespace hullinspect::planners
