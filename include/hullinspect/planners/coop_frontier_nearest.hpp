#pragma once
// Exact Manhattan distance from one cell to the nearest member of a changing cell set, answered on
// demand: Coop-Frontier reads d_HP at its frontier cells only, a few hundred of the grid's cells,
// so one query per frontier read replaces a transform of the whole grid after every change.

#include <cstdint>
#include <vector>

namespace hullinspect::planners {

class NearestSourceIndex {
 public:
  /// An empty set on a grid of `width` × `height` cells (index = y · width + x).
  void reset(int width, int height);
  /// Adds (member = true) or removes the cell; the caller passes only real changes.
  void set(int index, bool member);
  /// min over members m of |x − m.x| + |y − m.y|; grid::kUnreachable when the set is empty. A
  /// cached answer is reused while its nearest member stays and no member was added since.
  int distance(int index) const;

 private:
  // The nearest member in column x to row y: |row distance| and its row, or a negative distance.
  int nearest_in_column(int x, int y, int& row) const;

  int width_ = 0;
  int height_ = 0;
  int words_ = 0;                       // 64-bit words per column
  std::vector<std::uint64_t> columns_;  // [x · words_ + w]: bit r of word w = row 64 w + r
  std::vector<int> column_count_;       // members per column
  int count_ = 0;
  long long additions_ = 0;  // members added so far: a cached answer older is void
  // Per cell, its last answer: one record, so that a reused answer costs one memory access (and
  // the nearest member's column word, kept as an index into columns_, needs no division).
  struct Cached {
    long long at = -1;  // additions_ when cached; −1 never
    int distance = 0;
    int word = -1;  // columns_ index of the nearest member's word; −1 none
    std::uint64_t bit = 0;
  };
  mutable std::vector<Cached> cached_;
};

}  // namespace hullinspect::planners
