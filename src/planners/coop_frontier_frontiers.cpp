#include "hullinspect/planners/coop_frontier_frontiers.hpp"

#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners {

bool FrontierSet::is_frontier(const grid::Grid<std::int8_t>& map, int index) {
  if (map[index] != sim::kUnknown) return false;
  const grid::Cell c = map.cell(index);
  for (int d = 0; d < 4; ++d) {
    const int x = c.x + grid::kNeighbourDx[d];
    const int y = c.y + grid::kNeighbourDy[d];
    if (map.contains(x, y) && map(x, y) != sim::kUnknown) return true;
  }
  return false;
}

void FrontierSet::reset(const grid::Grid<std::int8_t>& map) {
  set_.reset(map.width(), map.height());
  joined_.clear();
  joined_.reserve(static_cast<std::size_t>(map.size()));  // the step loop allocates nothing
  for (int i = 0; i < map.size(); ++i) {
    if (is_frontier(map, i)) insert(i);
  }
}

void FrontierSet::on_known(int index, const grid::Grid<std::int8_t>& map) {
  set_.erase(index);
  const grid::Cell c = map.cell(index);
  for (int d = 0; d < 4; ++d) {
    const int x = c.x + grid::kNeighbourDx[d];
    const int y = c.y + grid::kNeighbourDy[d];
    // An unknown neighbour is a hull cell (non-hull cells are −1) and now touches a known cell.
    if (map.contains(x, y) && map(x, y) == sim::kUnknown) insert(map.index(x, y));
  }
}

void FrontierSet::insert(int index) {
  if (set_.contains(index)) return;
  set_.insert(index);
  joined_.push_back(index);
}

void FrontierSet::take_joined(std::vector<int>& out) {
  // A copy, not a swap: both buffers keep the capacity they were given.
  out.assign(joined_.begin(), joined_.end());
  joined_.clear();
}

}  // namespace hullinspect::planners
