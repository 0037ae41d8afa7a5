#include "hullinspect/planners/sweep_returns.hpp"

#include <algorithm>

namespace hullinspect::planners {

double unused_battery_weight(const SortieRoute& route, const sim::ReturnRule& rule) {
  const world::BatterySteps& b = rule.battery();
  const int round_trip = 2 * rule.flight_home(route.uav, route.pos, route.z);
  const int work = b.endurance -
                   (rule.battery_needed(route.uav, route.pos, route.z) -
                    rule.flight_home(route.uav, route.pos, route.z)) -
                   round_trip;
  return static_cast<double>(round_trip + b.swap) / std::max(1, work);
}

bool near_sortie_end(const SortieRoute& route, const sim::ReturnRule& rule) {
  if (!rule.limited() || route.battery_left < 0) return false;
  const int need_now = rule.battery_needed(route.uav, route.pos, route.z);
  return route.battery_left - need_now <= rule.battery().endurance / 3;
}

bool end_sortie_now(const SortieRoute& route, const sim::ReturnRule& rule,
                    grid::DistanceService& flights) {
  if (!near_sortie_end(route, rule)) return false;
  const int need_now = rule.battery_needed(route.uav, route.pos, route.z);
  if (route.battery_left < need_now) return true;  // the layer's point: now
  const double weight = unused_battery_weight(route, rule);
  const auto cost = [&](grid::Cell c, int battery) {
    const int need = rule.battery_needed(route.uav, c, route.z);
    return 2.0 * rule.flight_home(route.uav, c, route.z) + weight * (battery - need);
  };
  const double now = cost(route.pos, route.battery_left);
  grid::Cell at = route.pos;
  int battery = route.battery_left;
  for (const grid::Cell w : route.waypoints) {
    while (at != w) {
      const grid::Cell next = flights.next_step(at, w);
      if (next == at) break;  // no flight there: the follower stops as well
      battery -= std::max(1, flights.flight(at, next));
      at = next;
      // Past the layer's point: no point before it was cheaper than now.
      if (battery < rule.battery_needed(route.uav, at, route.z)) return true;
      if (cost(at, battery) <= now) return false;  // as cheap a point lies ahead
    }
  }
  return false;  // the battery lasts to the route's end
}

}  // namespace hullinspect::planners
