#pragma once
// Distance fields behind d_HP and d_C (model.md §5.4): the Manhattan distance from every cell to the
// nearest member of a cell set that changes during the mission.

#include <cstdint>

#include "hullinspect/grid/distance.hpp"
#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

/// Exact Manhattan (4-neighbour, obstacle-free) distance from every cell to the nearest cell with
/// sources != 0, by one forward and one backward raster pass: O(cells), no allocation once `out`
/// has the right size. With no source every cell gets grid::kUnreachable.
void manhattan_distance_transform(const grid::Grid<std::uint8_t>& sources, grid::Grid<int>& out);

/// A set of cells and the distance field to it. Membership changes are O(1) and only mark the field
/// stale; the field is recomputed (one O(cells) transform) the first time it is read afterwards, so
/// any number of changes between two reads costs one transform.
class SourceDistanceField {
 public:
  /// An empty set on a grid of `width` × `height` cells.
  void reset(int width, int height);
  /// Adds (member = true) or removes the cell.
  void set(int index, bool member);
  bool member(int index) const { return member_[index] != 0; }
  int count() const { return count_; }
  bool empty() const { return count_ == 0; }
  /// Recomputes the field if the set changed since the last call.
  void refresh();
  /// Distance from `index` to the nearest member (grid::kUnreachable when the set is empty). Call
  /// refresh() first after changes.
  int distance(int index) const { return distance_[index]; }
  bool stale() const { return stale_; }
  /// How many transforms were run (for tests and statistics).
  long long transforms() const { return transforms_; }

 private:
  grid::Grid<std::uint8_t> member_;
  grid::Grid<int> distance_;
  int count_ = 0;
  bool stale_ = true;
  long long transforms_ = 0;
};

}  // namespace hullinspect::planners
