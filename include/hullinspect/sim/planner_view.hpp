#pragma once
// What a planner may see at time t: everything the UAVs know, and nothing of the ground truth C.

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/sim/return_rule.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::sim {

/// The readings of every UAV from the sensing that ended the last step (or the one at t = 0).
class SensingLog {
 public:
  std::span<const Reading> readings(int uav) const {
    const auto b = static_cast<std::size_t>(begin_[static_cast<std::size_t>(uav)]);
    const auto e = static_cast<std::size_t>(begin_[static_cast<std::size_t>(uav) + 1]);
    return std::span<const Reading>(readings_).subspan(b, e - b);
  }
  int uav_count() const { return static_cast<int>(begin_.size()) - 1; }

 private:
  friend class Simulator;
  std::vector<Reading> readings_;  // capacity n·s2², never reallocated during a mission
  std::vector<int> begin_;         // n + 1 offsets into readings_
};

struct PlannerView {
  int time = 0;
  std::span<const UavState> uavs;
  const grid::Grid<std::int8_t>& map;    ///< M (eq. 2), shared knowledge of the fleet
  const grid::Grid<std::uint8_t>& seen;  ///< kSeenAtZ2 | kSeenAtZ1 per cell
  const SensingLog& sensed;              ///< this step's readings, per UAV
  /// When the sortie layer sends a UAV home (each UAV's battery left is UavState::battery_left):
  /// read by planners that plan their own returns (Planner::returns). Not limited() in the
  /// paper's model.
  ReturnRule returns{};
};

}  // namespace hullinspect::sim
