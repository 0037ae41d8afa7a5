#pragma once
// The lawnmower's route with no-fly zones (docs/model.md): the same strips, their flight rows split
// where they cross no-fly positions (the gaps are flown around along shortest paths), then point
// visits for the region cells the sweep missed, and — for cells no z = 1 footprint reaches — a
// second leg flown at z = 2 after one climb.

#include <cstdint>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::planners {

/// The columns [first, last] of UAV `uav`'s region in the strip of rows [y_begin, y_end); first >
/// last when the region has no cell there. Both routes (with and without no-fly zones) sweep these.
struct StripColumns {
  int first = 0;
  int last = -1;
  bool empty() const { return last < first; }
};
StripColumns strip_columns(const grid::Grid<std::int16_t>& owner, int uav, int y_begin, int y_end);

struct LawnmowerRoute {
  std::vector<grid::Cell> z1;  ///< waypoints flown at z = 1
  std::vector<grid::Cell> z2;  ///< waypoints flown at z = 2 afterwards (empty: never climbs)
};

/// UAV `uav`'s route over its region of `owner` from `from`; `reach` holds world::kReachZ1/Z2 bits.
LawnmowerRoute lawnmower_route_around_no_fly(const grid::Grid<std::int16_t>& owner, int uav, int s1,
                                             int s2, grid::Cell from,
                                             grid::DistanceService& distances,
                                             const grid::Grid<std::uint8_t>& reach);

}  // namespace hullinspect::planners
