#pragma once
// A set of grid cells with O(1) insert, erase and membership and a dense list to iterate, for the
// Coop-Frontier planner's frontier set and its list of corrosion cells still to inspect.

#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"

namespace hullinspect::planners {

class IndexedCellSet {
 public:
  /// Empties the set for a grid of `width` × `height` cells and reserves room for every cell, so
  /// inserts never allocate afterwards.
  void reset(int width, int height);

  bool contains(int index) const { return slot_[static_cast<std::size_t>(index)] >= 0; }
  /// The member's position in indices() and cells(), or −1 when `index` is not a member.
  int position(int index) const { return slot_[static_cast<std::size_t>(index)]; }
  /// The grid the set was reset for.
  int width() const { return width_; }
  int height() const { return height_; }
  /// Adds the cell; no-op when present.
  void insert(int index);
  /// Removes the cell (the last one takes its slot); no-op when absent.
  void erase(int index);

  int size() const { return static_cast<int>(indices_.size()); }
  bool empty() const { return indices_.empty(); }
  /// Members as flat indices and as cells, in the same (unspecified but deterministic) order.
  std::span<const int> indices() const { return indices_; }
  std::span<const grid::Cell> cells() const { return cells_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<int> slot_;  // per cell: position in indices_, or -1
  std::vector<int> indices_;
  std::vector<grid::Cell> cells_;
};

}  // namespace hullinspect::planners
