#pragma once
// The sortie layer (docs/model.md, "Batteries and sorties"): sits between a planner and the
// simulator like the deconfliction layer. Before every step it sends home the UAVs their planner
// sends home (Planner::returns), then, as the safety net, every UAV whose battery would not last
// another step's worth beyond its flight home and the reserve (ReturnRule::due); the simulator
// lands it, swaps its battery and flies it back to where it left off. The planner meanwhile sees
// the UAV away (UavState::away_left > 0), as for a plane change. It sees only the UAVs' states.

#include <span>

#include "hullinspect/sim/simulator.hpp"

namespace hullinspect::sim {

class SortieLayer {
 public:
  /// Sends home the UAVs `planned` that their planner sends home, then those whose battery has
  /// reached their flight home plus the reserve and the margin. Call before the planner decides
  /// the step. Throws LogicError for a planned UAV that cannot be sent home (failed, on the
  /// ground, already away, or unknown). Allocates only when a UAV is sent home.
  void before_step(Simulator& sim, std::span<const int> planned = {});

  /// UAVs sent home for a swap since construction: by their planner, and by the layer itself.
  long long planned_returns() const { return planned_; }
  long long returns() const { return returns_; }

 private:
  long long planned_ = 0;
  long long returns_ = 0;
};

}  // namespace hullinspect::sim
