#pragma once
// The deconfliction layer (docs/model.md, "Separation"): sits between a planner and the simulator
// and changes the planner's actions, when needed, so that no two UAVs come closer than the
// separation D. It sees only the UAV states and the actions, never the truth or the planner.

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::sim {

class Deconfliction {
 public:
  /// `no_fly` (may be null) is the mission's no-fly mask of a width × height grid; side-steps never
  /// enter it. `flights` (may be null) are the mission's neighbour flights, whose seam a move may
  /// cross. D >= 1.
  Deconfliction(int separation, int uavs, int width, int height,
                const grid::Grid<std::uint8_t>* no_fly, const grid::EdgeSteps* flights = nullptr);

  /// Rewrites `actions` (one per UAV, as the planner gave them) so that, if the UAVs are pairwise
  /// at least D apart now, they still are after the step and no two exchange cells. Allocates
  /// nothing.
  void adjust(std::span<const UavState> uavs, std::span<Action> actions);

  /// Moves the layer replaced by a hover or a side-step, since construction.
  long long held() const { return held_; }
  long long side_steps() const { return side_steps_; }

 private:
  bool allowed(int k, grid::Cell c) const;
  bool in_way(int k, int& blocker) const;
  Action evade(int k, int blocker);
  void settle(int k, grid::Cell c);

  int d_;
  int width_;
  int height_;
  const grid::Grid<std::uint8_t>* no_fly_;
  const grid::EdgeSteps* flights_;
  int patience_;  // steps a UAV waits before it takes precedence

  std::span<const UavState> uavs_;
  std::vector<grid::Cell> desire_;     // the cell the planner's action leads to
  std::vector<grid::Cell> next_;       // the cell decided for the step (valid once settled)
  std::vector<std::uint8_t> settled_;  // 1: next_ is decided
  std::vector<int> rank_;              // position in this step's order (lower goes first)
  std::vector<int> order_;
  std::vector<int> waited_;  // consecutive steps held back
  std::vector<int> side_;    // the sticky side (+1/−1) of a side-step, 0 none
  long long held_ = 0;
  long long side_steps_ = 0;
};

}  // namespace hullinspect::sim
