#pragma once
// The deconfliction layer (docs/model.md, "Separation"): sits between a planner and the simulator
// and changes the planner's actions, when needed, so that no two airborne UAVs come closer than
// the separation D. It also sequences the take-offs and landings at the launch sites: it holds a
// UAV away at its site (on the ground, or hovering on its leg) until its next step is clear. It
// sees only the UAV states, their legs and the actions, never the truth or the planner.

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::sim {

class Deconfliction {
 public:
  /// `no_fly` (may be null) is the mission's no-fly mask of a width × height grid; side-steps never
  /// enter it. `flights` (may be null) are the mission's neighbour flights, whose seam a move may
  /// cross. D >= 1.
  Deconfliction(int separation, int uavs, int width, int height,
                const grid::Grid<std::uint8_t>* no_fly, const grid::EdgeSteps* flights = nullptr);

  /// Rewrites `actions` (one per UAV, as the planner gave them) and decides the orders of the UAVs
  /// away at their sites (away_orders()) so that, if the airborne UAVs are pairwise at least D
  /// apart now, they still are after the step and no two exchange cells. Then call
  /// sim.step(actions, away_orders()). Allocates nothing.
  void adjust(const Simulator& sim, std::span<Action> actions);
  /// The orders for Simulator::step (Simulator::kGo, kHold, kTurnBack), one per UAV.
  std::span<const std::uint8_t> away_orders() const { return orders_; }

  /// Moves the layer replaced by a hover or a side-step, since construction (holds of UAVs away
  /// at their sites included).
  long long held() const { return held_; }
  long long side_steps() const { return side_steps_; }
  /// UAVs flying out that turned back to their site to let a UAV flying home pass.
  long long turn_backs() const { return turn_backs_; }

 private:
  enum class Kind : std::uint8_t { kFixed, kAway, kWorking };
  int key(int k) const;
  bool allowed(int k, grid::Cell c, bool airborne, int* blocker = nullptr) const;
  bool in_way(int k, int& blocker) const;
  bool site_busy(int k) const;
  bool flying_home(int j) const;
  Action evade(int k, int blocker);
  void settle(int k, grid::Cell c, bool airborne);
  void decide_away(int k);
  void decide_working(int k, std::span<Action> actions);
  void end_of_lead_step(int k);

  int d_;
  int width_;
  int height_;
  const grid::Grid<std::uint8_t>* no_fly_;
  const grid::EdgeSteps* flights_;
  int patience_;  // steps a UAV waits before it takes precedence

  std::span<const UavState> uavs_;
  std::vector<AwayMove> away_;  // per UAV away at its site: its next step
  std::vector<Kind> kind_;
  std::vector<grid::Cell> desire_;        // the cell the planner's action (or the leg) leads to
  std::vector<std::uint8_t> desire_air_;  // 1: airborne there
  std::vector<grid::Cell> next_;          // the cell decided for the step (valid once settled)
  std::vector<std::uint8_t> next_air_;    // 1: airborne there
  std::vector<std::uint8_t> settled_;     // 1: next_ is decided
  std::vector<int> rank_;                 // position in this step's order (lower goes first)
  std::vector<int> order_;
  std::vector<int> waited_;  // consecutive steps held back
  // Precedence: a UAV held back for `patience_` steps leads, the older lead first, until it has
  // been clear of the others for `lead_steps_` steps (end_of_lead_step), so that it passes before
  // the UAV it waited for can take precedence in turn.
  int lead_steps_;
  std::vector<int> lead_;              // steps of precedence left
  std::vector<long long> lead_since_;  // the step its precedence began
  long long step_ = 0;
  std::vector<int> side_;  // the sticky side (+1/−1) of a side-step, 0 none
  std::vector<std::uint8_t> orders_;
  long long held_ = 0;
  long long side_steps_ = 0;
  long long turn_backs_ = 0;
};

}  // namespace hullinspect::sim
