#pragma once
// A lower bound on d_HP over the frontier set F, kept without reading every frontier cell: it
// bounds the largest frontier utility U_f from above, which lets the assignment stop searching
// around a UAV once nothing farther away can score higher (coop_frontier_assignment.hpp).
//
// d_HP of a cell never decreases during a mission (the prior's cells only leave their set when
// seen), so a d_HP read earlier is still a lower bound later. Cells are kept in buckets by the
// last value read for them; the bound reads again only cells of the lowest bucket, moving each up
// until one is still that near. A cell is read again only when it is in the lowest bucket, so the
// work follows the changes, not |F| per query.

#include <algorithm>
#include <vector>

namespace hullinspect::planners {

class DistanceFloor {
 public:
  /// No cells, for a grid of `cells` cells; distances at or above `levels − 1` share the top
  /// bucket (its bound is levels − 1).
  void reset(int cells, int levels);
  /// A cell that joined F, not read yet: it sits in bucket 0 until the next lowest().
  void add(int index);

  /// The largest d such that every cell of F has d_HP ≥ d, capped at levels − 1 (levels − 1 when F
  /// is empty). `in_set(index)` says whether a cell added earlier is still in F; `distance(index)`
  /// is its d_HP now (any value ≥ levels − 1, grid::kUnreachable included, means far).
  template <class InSet, class Distance>
  int lowest(InSet in_set, Distance distance) {
    while (low_ <= top()) {
      while (head_[static_cast<std::size_t>(low_)] >= 0) {
        const int index = head_[static_cast<std::size_t>(low_)];
        unlink(index);
        if (!in_set(index)) continue;  // left F
        const int d = std::min(distance(index), top());
        link(index, std::max(d, low_));
        if (d <= low_) return low_;
      }
      if (low_ == top()) return low_;
      ++low_;
    }
    return 0;
  }

 private:
  int top() const { return static_cast<int>(head_.size()) - 1; }
  // Buckets are intrusive doubly linked lists over the cells, so that keeping them allocates
  // nothing once reset (the planner's step loop allocates nothing).
  void link(int index, int level);
  void unlink(int index);

  std::vector<int> head_;   // [d]: the first cell whose last read d_HP was d (capped), or −1
  std::vector<int> next_;   // per cell: the next cell of its bucket, or −1
  std::vector<int> prev_;   // per cell: the previous cell of its bucket, or −1
  std::vector<int> level_;  // per cell: its bucket, or −1 when not kept
  int low_ = 0;             // no kept cell sits in a bucket below this one
};

}  // namespace hullinspect::planners
