#include "hullinspect/sim/mission_result.hpp"

namespace hullinspect::sim {

double MissionResult::c_percent(int t) const {
  if (corroded_cells == 0) return 100.0;
  return 100.0 * inspected_series[static_cast<std::size_t>(t)] / corroded_cells;
}

double MissionResult::m_percent(int t) const {
  if (hull_cells == 0) return 100.0;
  return 100.0 * known_series[static_cast<std::size_t>(t)] / hull_cells;
}

UavCounters MissionResult::totals() const {
  UavCounters total;
  for (const auto& u : uavs) {
    total.moves += u.moves;
    total.hovers += u.hovers;
    total.plane_changes += u.plane_changes;
    total.steps_z1 += u.steps_z1;
    total.steps_z2 += u.steps_z2;
    total.steps_transit += u.steps_transit;
    total.flight_steps += u.flight_steps;
    total.swaps += u.swaps;
  }
  return total;
}

int MissionResult::sorties() const {
  int n = 0;
  for (const auto& u : uavs) n += static_cast<int>(u.sorties.size());
  return n;
}

std::optional<int> MissionResult::min_battery() const {
  std::optional<int> least;
  for (const auto& u : uavs) {
    if (u.min_battery >= 0 && (!least || u.min_battery < *least)) least = u.min_battery;
  }
  return least;
}

}  // namespace hullinspect::sim
