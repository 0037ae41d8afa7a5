#pragma once
// Sweep-Inspect's tours of the prior's cells at z = 1 (docs/sweep-inspect.md, "The prior"): the
// planning estimate of a tour's steps, and the split of cells between two UAVs' tours so that the
// later of the two ends earliest (the re-split of neighbours' tours, and a UAV done early taking
// part of another's).

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

/// Estimates over cells given as indices of a grid `width` wide, with a z = 1 footprint of
/// Chebyshev half-width `half`. Holds its scratch, so one instance serves a planner's calls.
class PriorTourSplitter {
 public:
  PriorTourSplitter() = default;
  PriorTourSplitter(int width, int half, std::size_t capacity);

  /// Steps of a nearest-first tour from `from` (Manhattan, the project's x-then-y flights) that
  /// flies to the nearest position whose footprint holds a cell left, and in which the
  /// footprint sees every cell within `half` of each leg: a planning estimate, far cheaper than
  /// the tour planned for flight, so that many candidate splits can be compared.
  int tour_steps(grid::Cell from, std::span<const int> cells);

  /// Which of two UAVs may inspect a cell: -1 only the first, 1 only the second, 0 both or
  /// neither.
  using OnlyOne = std::function<int(int cell)>;

  /// A split of cells: the first `first` of them the first UAV's tour, the rest the second's;
  /// `later` the larger of the two tours' estimates.
  struct Split {
    std::size_t first = 0;
    int later = 0;
  };

  /// Reorders `cells` — those only the first UAV (at `pa`) may inspect first, then by how much
  /// nearer they are to it than to the second (at `pb`), those only the second may inspect
  /// last — and cuts them where the later of the two tours ends earliest: the first cut at
  /// which the first tour's estimate is at least the second's, or the cut before it when that
  /// ends no later.
  Split split(grid::Cell pa, grid::Cell pb, std::vector<int>& cells, const OnlyOne& only);

 private:
  grid::Cell cell(int index) const { return {index % width_, index / width_}; }
  int width_ = 1;
  int half_ = 0;
  std::vector<grid::Cell> left_;  // cells not yet seen by the estimated tour, in their order
};

}  // namespace hullinspect::planners
