#pragma once
// Internal to the open tour's sources (src/planners/open_tour_*.cpp): a 2-opt or Or-opt move on a
// tour held as positions of nodes, and its application, which the neighbour-list search and the
// repair share.

#include <algorithm>
#include <initializer_list>
#include <vector>

namespace hullinspect::planners::open_tour_detail {

/// A move: reverse positions [i, j] (2-opt), or move the run at positions [i, j] to after
/// position q, reversed or not (Or-opt); `gain` is how much shorter it makes the tour.
struct TourMove {
  int gain = 0;
  bool two_opt = true;
  int i = 0;
  int j = 0;
  int q = 0;
  bool reversed = false;
};

/// Applies `move` to `order` (position → node) and `pos` (node → position), first calling
/// touch(position) for the ends of every edge it changes (a position may be one past the last).
template <typename Touch>
void apply_tour_move(const TourMove& move, std::vector<int>& order, std::vector<int>& pos,
                     Touch&& touch) {
  const auto it = order.begin();
  const auto set_positions = [&](int lo, int hi) {
    for (int p = lo; p <= hi; ++p)
      pos[static_cast<std::size_t>(order[static_cast<std::size_t>(p)])] = p;
  };
  if (move.two_opt) {
    for (const int p : {move.i - 1, move.i, move.j, move.j + 1}) touch(p);
    std::reverse(it + move.i, it + move.j + 1);
    set_positions(move.i, move.j);
    return;
  }
  for (const int p : {move.i - 1, move.i, move.j, move.j + 1, move.q, move.q + 1}) touch(p);
  const int len = move.j - move.i + 1;
  if (move.q < move.i) {
    std::rotate(it + move.q + 1, it + move.i, it + move.j + 1);
    if (move.reversed) std::reverse(it + move.q + 1, it + move.q + 1 + len);
    set_positions(move.q + 1, move.j);
  } else {
    std::rotate(it + move.i, it + move.j + 1, it + move.q + 1);
    if (move.reversed) std::reverse(it + move.q + 1 - len, it + move.q + 1);
    set_positions(move.i, move.q);
  }
}

}  // namespace hullinspect::planners::open_tour_detail
