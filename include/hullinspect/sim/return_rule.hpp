#pragma once
// When the sortie layer sends a UAV home (docs/model.md, "Batteries and sorties"): its flight
// home, the reserve and the margin. One rule, read by the layer and by the planners that plan
// their own returns (PlannerView::returns), so that a planner's estimate of when the layer would
// act is the layer's own.

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/sim/types.hpp"
#include "hullinspect/world/battery.hpp"
#include "hullinspect/world/launch_sites.hpp"

namespace hullinspect::sim {

class ReturnRule {
 public:
  /// Unlimited flight (the paper's model): no UAV is ever sent home.
  ReturnRule() = default;
  /// The rule of a mission with launch sites `legs` and battery `battery`; `margin` is
  /// world::sortie_margin_steps. `legs` must outlive the rule.
  ReturnRule(const world::LaunchLegs& legs, const world::BatterySteps& battery, int margin)
      : legs_(&legs), battery_(battery), margin_(margin) {}

  /// True when batteries are limited and the UAVs have launch sites to swap them at.
  bool limited() const { return battery_.limited && legs_ != nullptr && !legs_->empty(); }
  /// The UAVs' battery in steps: endurance, reserve, swap.
  const world::BatterySteps& battery() const { return battery_; }
  /// Steps of flight UAV `uav` needs from `pos` on plane `z` (finishing a plane change of
  /// `transit_left` steps) until it has landed at its site and been carried off the grid.
  int flight_home(int uav, grid::Cell pos, int z, int transit_left = 0) const {
    return legs_->homeward_steps(uav, pos, z, transit_left);
  }
  /// The battery UAV `uav` must have left at `pos` on plane `z` for the layer to let it fly one
  /// more step: flight_home + the reserve + the margin. Only when limited().
  int battery_needed(int uav, grid::Cell pos, int z, int transit_left = 0) const {
    return flight_home(uav, pos, z, transit_left) + battery_.reserve + margin_;
  }
  /// Whether the layer sends `u` (UAV `uav`) home before this step: working, airborne, on the hull
  /// and below battery_needed where it is.
  bool due(int uav, const UavState& u) const {
    if (!limited() || u.failed || !u.airborne || u.away_left > 0) return false;
    return u.battery_left < battery_needed(uav, u.pos, u.z, u.transit_left);
  }

 private:
  const world::LaunchLegs* legs_ = nullptr;
  world::BatterySteps battery_;
  int margin_ = 0;
};

}  // namespace hullinspect::sim
