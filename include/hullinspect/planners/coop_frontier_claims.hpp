#pragma once
// Which UAV claimed which detected corrosion cell, and the INSPECT target rule of the Coop-Frontier
// planner (model.md §5.4).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

class InspectionClaims {
 public:
  /// No claims, for `uavs` UAVs on a grid of `width` × `height` cells; reserves all storage.
  void reset(int uavs, int width, int height);

  /// UAV `uav` claims cell `index` unless another UAV holds it. Returns whether it now holds it.
  bool claim(int uav, int index);
  /// Drops every claim of `uav` (a failed UAV's cells become free for the others).
  void release_all(int uav);
  /// The UAV holding the cell, or −1.
  int owner(int index) const { return owner_[static_cast<std::size_t>(index)]; }
  /// Cells claimed by `uav` (some may have been inspected since; see inspect_target()).
  std::span<const int> claims(int uav) const { return claims_[static_cast<std::size_t>(uav)]; }

  /// The INSPECT target of `uav` at `pos`: the nearest cell (Manhattan; ties lowest (y, x)) among
  /// its claimed cells with M = 2 and every M = 2 cell within Manhattan distance `radius` of `pos`.
  /// Claimed cells that are no longer 2 are dropped from the claim list on the way. nullopt when
  /// the set is empty. With `distance_from_pos` (the distance service's field from `pos`, no-fly
  /// zones) that distance replaces Manhattan in both rules.
  std::optional<grid::Cell> inspect_target(int uav, grid::Cell pos,
                                           const grid::Grid<std::int8_t>& map, int radius,
                                           const grid::Grid<int>* distance_from_pos = nullptr);

 private:
  std::vector<int> owner_;
  std::vector<std::vector<int>> claims_;
};

}  // namespace hullinspect::planners
