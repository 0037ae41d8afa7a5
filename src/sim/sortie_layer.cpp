#include "hullinspect/sim/sortie_layer.hpp"

namespace hullinspect::sim {

SortieLayer::SortieLayer(const Simulator& sim)
    : reserve_(sim.battery().reserve), margin_(world::sortie_margin_steps(sim.params())) {}

void SortieLayer::before_step(Simulator& sim) {
  if (!sim.battery().limited || sim.launch_legs().empty()) return;
  const auto uavs = sim.uavs();
  for (std::size_t k = 0; k < uavs.size(); ++k) {
    const UavState& u = uavs[k];
    if (u.failed || !u.airborne || u.away_left > 0) continue;
    // Waiting one more step costs one step of battery and lengthens the flight home by at most
    // the margin, so a UAV sent home now, and not later, always lands with the reserve left.
    const int home =
        sim.launch_legs().homeward_steps(static_cast<int>(k), u.pos, u.z, u.transit_left);
    if (u.battery_left >= home + reserve_ + margin_) continue;
    sim.return_for_swap(static_cast<int>(k));
    ++returns_;
  }
}

}  // namespace hullinspect::sim
