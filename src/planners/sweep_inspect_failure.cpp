// Sweep-Inspect after a UAV fails (docs/sweep-inspect.md, "Failures"): the cells not yet
// observed are re-split among the working UAVs so that they end together (runs of the band
// order, band_partition.hpp, or column slabs, slab_split.hpp).

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include <algorithm>

#include "hullinspect/planners/band_partition.hpp"
#include "hullinspect/planners/slab_split.hpp"
#include "hullinspect/world/no_fly.hpp"

#include "sweep_inspect_detail.hpp"

namespace hullinspect::planners {

using sweep_inspect_detail::unobserved;

void SweepInspectPlanner::resplit(const sim::PlannerView& view) {
  const std::size_t n = uavs_.size();
  for (int i : hull_cells_) owner_[i] = -1;
  resplit_ = true;
  // The working UAVs' loads: the prior's cells each still has to visit, in cells (a visit costs
  // about kPriorVisitSteps steps, a step of sweep sees about kSweepRate·s2 new cells); on the
  // band partition's grid in steps.
  const double cells_per_step = kSweepRate * s2_;
  const bool on_bands = !band_start_.empty();
  split_load_.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    if (view.uavs[k].failed) continue;
    split_load_[k] = kPriorVisitSteps * (on_bands ? 1.0 : cells_per_step) *
                     static_cast<double>(prior_[k].size());
    uavs_[k].replan = true;
  }
  // One split per flight part (docs/model.md §8; one part without a no-fly wall): the cells not
  // yet observed that the part sees, in column order (then row), among its working UAVs in the
  // order of their positions (x).
  for (std::size_t g = 0; g < n; ++g) {
    if (view.uavs[g].failed) continue;
    bool first_of_part = true;
    for (std::size_t k = 0; k < g; ++k) {
      if (!view.uavs[k].failed && uav_distances_[k] == uav_distances_[g]) first_of_part = false;
    }
    if (!first_of_part) continue;
    split_helpers_.clear();
    for (std::size_t k = g; k < n; ++k) {
      if (!view.uavs[k].failed && uav_distances_[k] == uav_distances_[g])
        split_helpers_.push_back({static_cast<int>(k), view.uavs[k].pos});
    }
    std::stable_sort(split_helpers_.begin(), split_helpers_.end(),
                     [](const auto& a, const auto& b) { return a.second.x < b.second.x; });
    split_cells_.clear();
    for (int i : hull_cells_) {
      // Detected cells not yet inspected are work too: a band passing abreast inspects them
      // (else they would wait, unowned, for the helpers at the end); resplit_detection_ keeps
      // them in the share's sweep.
      const bool detected = view.map[i] == sim::kCorrosionSeen && view.seen[i] != 0;
      if (unobserved(view, i) && reachable(static_cast<int>(g), i, world::kReachZ2)) {
        split_cells_.push_back(i);
      } else if (detected && reachable(static_cast<int>(g), i, world::kReachZ1)) {
        split_cells_.push_back(i);
        resplit_detection_[i] = 1;
      }
    }
    const auto assign = [&](int k, int i) { owner_[i] = static_cast<std::int16_t>(k); };
    if (on_bands) {
      // On the band partition's grid: runs of its boustrophedon, in steps (a row of a band at
      // the sweep rate with its inspections, a band begun about one more).
      split_in_band_order(split_cells_, width_, band_start_, split_helpers_, split_load_,
                          1.0 / kSweepRate, 1.0, assign);
      continue;
    }
    std::stable_sort(split_cells_.begin(), split_cells_.end(),
                     [&](int a, int b) { return a % width_ < b % width_; });
    split_in_slabs(split_cells_, width_, split_helpers_, split_load_, cells_per_step, assign);
  }
}

}  // namespace hullinspect::planners
