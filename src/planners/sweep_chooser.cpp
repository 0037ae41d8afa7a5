#include "hullinspect/planners/sweep_chooser.hpp"

#include <cassert>
#include <utility>

#include "hullinspect/planners/band_sweep.hpp"

namespace hullinspect::planners {

PlanCost manhattan_cost(grid::Cell from, const std::vector<grid::Cell>& waypoints) {
  if (waypoints.empty()) return {};
  return {static_cast<double>(grid::manhattan(from, waypoints.front())),
          static_cast<double>(flight_length(waypoints.front(), waypoints))};
}

std::size_t choose_plan(std::span<const SweepCandidate> candidates) {
  assert(!candidates.empty());
  std::size_t best = 0;
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    // Strictly shorter only: the earlier candidate keeps a tie.
    if (candidates[i].cost.total() < candidates[best].cost.total()) best = i;
  }
  return best;
}

SweepPlan take_chosen(std::vector<SweepCandidate>& candidates) {
  return std::move(candidates[choose_plan(candidates)].plan);
}

}  // namespace hullinspect::planners
