#pragma once
// Distance fields behind d_HP and d_C (model.md §5.4): the distance (docs/model.md) from every cell
// to the nearest member of a cell set that changes during the mission.

#include <cstdint>

#include "hullinspect/grid/distance.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/coop_frontier_nearest.hpp"
#include "hullinspect/planners/coop_frontier_shrinking_field.hpp"

namespace hullinspect::planners {

/// The obstacle-free transform now lives in the distance service's module.
using grid::manhattan_distance_transform;

/// A set of cells and the distance field to it. As a field: membership changes are O(1) and only
/// mark it stale; it is brought up to date the first time it is read afterwards, so any number of
/// changes between two reads costs one update. With Manhattan distances, an update after removals
/// only recomputes a window around the removed members (remove_members()); after an addition, or
/// with shortest flights, it is one O(cells) transform or search. On a grid of more than
/// `on_demand_cells` cells without no-fly positions (Manhattan distances), each read is answered on
/// its own by a NearestSourceIndex instead: Coop-Frontier reads only its frontier cells, and on
/// very large grids the windows of the updates may cover most of the grid (up to the default
/// hull at 8× its area, 55 250 cells, the field with its window updates is the cheaper of the
/// two: docs/results.md "Planning time against hull size").
class SourceDistanceField {
 public:
  /// An empty set on a grid of `width` × `height` cells; distances from `distances` (shortest
  /// allowed paths) or, when null, Manhattan.
  void reset(int width, int height, grid::DistanceService* distances = nullptr,
             int on_demand_cells = kOnDemandCells);
  /// Grids above this many cells are read on demand (without no-fly positions).
  static constexpr int kOnDemandCells = 100'000;
  /// Adds (member = true) or removes the cell.
  void set(int index, bool member);
  bool member(int index) const { return member_[index] != 0; }
  int count() const { return count_; }
  bool empty() const { return count_ == 0; }
  /// Recomputes the field if the set changed since the last call (not when read on demand).
  void refresh();
  /// Distance from `index` to the nearest member (grid::kUnreachable when the set is empty). Call
  /// refresh() first after changes.
  int distance(int index) const { return on_demand_ ? nearest_.distance(index) : distance_[index]; }
  bool stale() const { return stale_; }
  /// How many whole-field searches were run (for tests and statistics).
  long long transforms() const { return transforms_; }
  /// How many updates recomputed only a window around removed members.
  long long partial_updates() const { return partial_updates_; }

 private:
  grid::DistanceService* distances_ = nullptr;
  bool on_demand_ = false;    // nearest_ answers each read
  bool incremental_ = false;  // Manhattan distances held as a field: removals update it in place
  NearestSourceIndex nearest_;
  grid::Grid<std::uint8_t> member_;
  grid::Grid<int> distance_;
  // Removals since the field was last exact; an addition (or a first field) needs a transform.
  std::vector<int> removed_;
  bool needs_transform_ = true;
  int count_ = 0;
  bool stale_ = true;
  long long transforms_ = 0;
  long long partial_updates_ = 0;
};

}  // namespace hullinspect::planners
