#pragma once
// Sweep-Inspect's one rule for choosing among candidate sweep plans (docs/sweep-inspect.md, "The
// sweep"). Each way of planning a sweep — rows or columns, an approach along the region's edge,
// the UAV's own bands first, two blocks of columns, rejoining a band or planning anew — is a
// generator of candidates; choose_plan alone decides between them, so that every choice is the
// same comparison of the same cost terms.

#include <cstddef>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

/// A sweep's waypoints, the first `approach` of them its approach's.
struct SweepPlan {
  std::vector<grid::Cell> waypoints;
  std::size_t approach = 0;
  bool own_band_first = false;  ///< the sweep begins with the bands on one side of the UAV's
};

/// A candidate plan's cost, in steps (the flight's estimate its generator uses: Manhattan, or
/// the distance service's flights among no-fly zones).
struct PlanCost {
  double reach = 0;  ///< from the UAV to the first band: the flight there, or the approach
  double bands = 0;  ///< from the first band's start to the plan's end
  [[nodiscard]] double total() const { return reach + bands; }
};

/// One plan a generator offers, with its cost.
struct SweepCandidate {
  SweepPlan plan;
  PlanCost cost;
};

/// The cost of flying `waypoints` from `from` (Manhattan): reach to the first, then along them.
PlanCost manhattan_cost(grid::Cell from, const std::vector<grid::Cell>& waypoints);

/// The index of the candidate to fly: the smallest total cost (reach + bands); among equal
/// totals the earliest, and every generator lists its plain plan (or the plan already being
/// flown) first, so a tie keeps it. `candidates` must not be empty.
std::size_t choose_plan(std::span<const SweepCandidate> candidates);

/// choose_plan's candidate, moved out of `candidates`.
SweepPlan take_chosen(std::vector<SweepCandidate>& candidates);

}  // namespace hullinspect::planners
