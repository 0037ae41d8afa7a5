#include "hullinspect/planners/prior_weights.hpp"

#include <algorithm>
#include <vector>

namespace hullinspect::planners {

namespace {

/// 1 − Π over offsets (dx, dy) of (1 − rate·P(a rectangle centred at that offset covers the cell)):
/// the probability that at least one rectangle of a process with `rate` centres per cell covers a
/// given cell. A side is uniform over the m = (l_C + 1)/2 odd values 1 … l_C, so it reaches
/// |d| columns from its centre with probability (m − |d|)/m.
double coverage_probability(double rate, int l_c) {
  if (rate <= 0) return 0.0;
  const int m = (l_c + 1) / 2;
  double none = 1.0;
  for (int dy = -(m - 1); dy <= m - 1; ++dy) {
    for (int dx = -(m - 1); dx <= m - 1; ++dx) {
      const double px = static_cast<double>(m - std::abs(dx)) / m;
      const double py = static_cast<double>(m - std::abs(dy)) / m;
      none *= 1.0 - rate * px * py;
    }
  }
  return 1.0 - none;
}

}  // namespace

CorrosionOdds corrosion_odds(const world::CorrosionZone& zone, double p_tp, double p_fp) {
  // Three independent rectangle processes: true centres that are in the prior (rate p_C·p_TP),
  // true centres the prior missed (p_C·(1 − p_TP)) and false-positive centres ((1 − p_C)·p_FP).
  const double tp = coverage_probability(zone.p_c * p_tp, zone.l_c);
  const double missed = coverage_probability(zone.p_c * (1.0 - p_tp), zone.l_c);
  const double fp = coverage_probability((1.0 - zone.p_c) * p_fp, zone.l_c);
  CorrosionOdds odds;
  odds.outside_prior = missed;  // C' = 0: no prior rectangle; corroded iff a missed one covers it
  const double in_prior = tp + fp - tp * fp;  // P(C' = 1)
  // P(C = 1, C' = 1) = P(a true-positive rectangle) + P(none, a false one, a missed true one).
  odds.in_prior = in_prior > 0 ? (tp + (1.0 - tp) * fp * missed) / in_prior : 1.0;
  return odds;
}

namespace {
/// The odds of the instance generator's zone of every column (one zone when unknown); the
/// default odds ({1, 0}: a prior cell is corroded, no other) without statistics.
std::vector<CorrosionOdds> column_odds(const PlannerContext& context, bool use_statistics) {
  const int width = context.hull.width();
  std::vector<CorrosionOdds> column(static_cast<std::size_t>(width), CorrosionOdds{});
  if (use_statistics && context.corrosion != nullptr) {
    const world::CorrosionParams& c = *context.corrosion;
    const std::vector<world::CorrosionZone> zones =
        c.zones.empty() ? std::vector<world::CorrosionZone>{{0, width}} : c.zones;
    for (const auto& zone : zones) {
      const CorrosionOdds odds = corrosion_odds(zone, c.p_tp, c.p_fp);
      for (int x = std::max(0, zone.x_begin); x < std::min(width, zone.x_end); ++x)
        column[static_cast<std::size_t>(x)] = odds;
    }
  }
  return column;
}
}  // namespace

grid::Grid<double> corrosion_probabilities(const PlannerContext& context, bool use_statistics) {
  const auto& hull = context.hull;
  const std::vector<CorrosionOdds> column = column_odds(context, use_statistics);
  grid::Grid<double> probability(hull.width(), hull.height(), 0.0);
  for (int i : hull.cells()) {
    const CorrosionOdds& odds = column[static_cast<std::size_t>(i % hull.width())];
    probability[i] = context.prior[i] == 1 ? odds.in_prior : odds.outside_prior;
  }
  return probability;
}

grid::Grid<double> prior_work_weights(const PlannerContext& context, bool use_statistics) {
  const auto& p = context.params;
  const double ratio = static_cast<double>(p.s2) / p.s1;
  grid::Grid<double> weights = corrosion_probabilities(context, use_statistics);
  for (int i : context.hull.cells()) weights[i] = 1.0 + weights[i] * ratio;
  return weights;
}

double expected_prior_precision(const PlannerContext& context) {
  if (context.corrosion == nullptr) return -1.0;
  const std::vector<CorrosionOdds> column = column_odds(context, true);
  double sum = 0.0;
  int cells = 0;
  for (int i : context.hull.cells()) {
    if (context.prior[i] != 1) continue;
    sum += column[static_cast<std::size_t>(i % context.hull.width())].in_prior;
    ++cells;
  }
  return cells == 0 ? -1.0 : sum / cells;
}

partition::PartitionRequest partition_request(const PlannerContext& context,
                                              std::uint64_t partition_seed, bool prior_weights,
                                              bool prior_statistics) {
  partition::PartitionRequest request;
  request.hull = &context.hull;
  request.starts.assign(context.starts.begin(), context.starts.end());
  request.seed = partition_seed;
  add_no_fly(request, context);
  if (prior_weights) request.weights = prior_work_weights(context, prior_statistics);
  return request;
}

}  // namespace hullinspect::planners
