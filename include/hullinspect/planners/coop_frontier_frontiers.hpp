#pragma once
// The frontier set F of model.md §5.4, kept up to date cell by cell as the map M fills in.

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/coop_frontier_cell_set.hpp"

namespace hullinspect::planners {

/// F = the hull cells with M = 0 that have a 4-neighbour with M ≠ 0. Non-hull cells (M = −1) count
/// as known; positions outside the grid are not neighbours. Cells only ever go from M = 0 to M ≠ 0,
/// so F changes only around the cells that just became known: each update is O(1).
class FrontierSet {
 public:
  /// Builds F from a whole map: O(cells), once per mission.
  void reset(const grid::Grid<std::int8_t>& map);
  /// Call when cell `index` has just turned from M = 0 to M ≠ 0 in `map` (once per such cell): it
  /// leaves F and its unknown hull neighbours join.
  void on_known(int index, const grid::Grid<std::int8_t>& map);

  bool contains(int index) const { return set_.contains(index); }
  int size() const { return set_.size(); }
  bool empty() const { return set_.empty(); }
  std::span<const int> indices() const { return set_.indices(); }
  std::span<const grid::Cell> cells() const { return set_.cells(); }
  /// F as a set with positions (for searches around a cell).
  const IndexedCellSet& members() const { return set_; }
  /// Cells that joined F since the last take_joined() (or reset(), which lists every member):
  /// moved into `out`, which is cleared first.
  void take_joined(std::vector<int>& out);

  /// Whether `index` belongs in F according to `map` (the definition, for resets and tests).
  static bool is_frontier(const grid::Grid<std::int8_t>& map, int index);

 private:
  void insert(int index);

  IndexedCellSet set_;
  std::vector<int> joined_;
};

}  // namespace hullinspect::planners
