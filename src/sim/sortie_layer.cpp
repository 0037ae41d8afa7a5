#include "hullinspect/sim/sortie_layer.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::sim {

void SortieLayer::before_step(Simulator& sim, std::span<const int> planned) {
  const ReturnRule rule = sim.return_rule();
  if (!rule.limited()) {
    if (!planned.empty()) {
      throw LogicError("a planner sent a UAV home without a limited battery and a launch site");
    }
    return;
  }
  for (const int k : planned) {
    const auto uavs = sim.uavs();
    if (k < 0 || k >= static_cast<int>(uavs.size()) || uavs[static_cast<std::size_t>(k)].failed ||
        !uavs[static_cast<std::size_t>(k)].airborne ||
        uavs[static_cast<std::size_t>(k)].away_left > 0) {
      throw LogicError(fmt::format(
          "a planner sent UAV {} home at t = {}: only a working UAV airborne on the hull can be", k,
          sim.time()));
    }
    sim.return_for_swap(k);
    ++planned_;
  }
  const auto uavs = sim.uavs();
  for (std::size_t k = 0; k < uavs.size(); ++k) {
    // Waiting one more step costs one step of battery and lengthens the flight home by at most
    // the margin, so a UAV sent home now, and not later, always lands with the reserve left.
    if (!rule.due(static_cast<int>(k), uavs[k])) continue;
    sim.return_for_swap(static_cast<int>(k));
    ++returns_;
  }
}

}  // namespace hullinspect::sim
