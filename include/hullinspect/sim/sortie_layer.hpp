#pragma once
// The sortie layer (docs/model.md, "Batteries and sorties"): sits between a planner and the
// simulator like the deconfliction layer. Before every step it sends home every UAV whose battery
// would not last another step's worth beyond its flight home and the reserve; the simulator lands
// it, swaps its battery and flies it back to where it left off. The planner meanwhile sees the UAV
// away (UavState::away_left > 0), as for a plane change. It sees only the UAVs' states.

#include "hullinspect/sim/simulator.hpp"

namespace hullinspect::sim {

class SortieLayer {
 public:
  /// For the mission of `sim` (whose battery is limited and which has launch sites).
  explicit SortieLayer(const Simulator& sim);

  /// Sends home the UAVs whose battery has reached their flight home plus the reserve and the
  /// margin. Call before the planner decides the step. Allocates only when a UAV is sent home.
  void before_step(Simulator& sim);

  /// UAVs sent home for a swap since construction.
  long long returns() const { return returns_; }

 private:
  int reserve_;
  int margin_;
  long long returns_ = 0;
};

}  // namespace hullinspect::sim
