// Sweep-Inspect's own battery returns (docs/sweep-inspect.md, "Planned returns"): a UAV flying
// its sweep, or flying back to it after an inspection, ends its sortie at the cheapest point of
// the route ahead (sweep_returns.hpp). UAVs in other modes (prior tours, inspections, help) are
// left to the sortie layer, which stays the safety net for all.

#include "hullinspect/planners/sweep_inspect_planner.hpp"
#include "hullinspect/planners/sweep_returns.hpp"

namespace hullinspect::planners {

void SweepInspectPlanner::returns(const sim::PlannerView& view, std::vector<int>& uavs) {
  if (!options_.planned_returns || !view.returns.limited()) return;
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    const sim::UavState& u = view.uavs[k];
    const Uav& p = uavs_[k];
    if (u.failed || !u.airborne || u.in_transit() || u.battery_left < 0) continue;
    if (p.mode != Mode::kSweep && p.mode != Mode::kReturn) continue;
    // Most steps are far from a sortie's end: the route is built only near it.
    if (!near_sortie_end({static_cast<int>(k), u.pos, u.z, u.battery_left, {}}, view.returns)) {
      continue;
    }
    return_route_.clear();
    if (p.mode == Mode::kReturn) return_route_.push_back(p.resume);
    const auto ahead = p.sweep.remaining();
    return_route_.insert(return_route_.end(), ahead.begin(), ahead.end());
    const SortieRoute route{static_cast<int>(k), u.pos, u.z, u.battery_left, return_route_};
    if (end_sortie_now(route, view.returns, *uav_distances_[k]))
      uavs.push_back(static_cast<int>(k));
  }
}

}  // namespace hullinspect::planners
