// The open tour of many points (open_tour.hpp): nearest neighbour and local search restricted to
// each point's few nearest points, found through a grid of buckets, so that the work grows about
// linearly with the points instead of with their square.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "hullinspect/planners/open_tour.hpp"
#include "open_tour_moves.hpp"

namespace hullinspect::planners {

namespace {

constexpr int kNeighbours = 16;    // nearest points per point
constexpr int kPerQuadrant = 4;    // and nearest points per quadrant around it
constexpr int kQuadrantRings = 6;  // looked for up to this many rings of buckets further
constexpr int kNearness = 4096;    // nearness(): leg cost × this + Manhattan distance
constexpr int kListSize = kNeighbours + 4 * kPerQuadrant;

/// Points (node 0 the start, node i ≥ 1 the point i − 1) in square buckets of side `side`, each
/// bucket's nodes in increasing order.
class Buckets {
 public:
  Buckets(std::span<const grid::Cell> at, int side) : side_(side) {
    int x_hi = std::numeric_limits<int>::min();
    int y_hi = std::numeric_limits<int>::min();
    x_lo_ = std::numeric_limits<int>::max();
    y_lo_ = std::numeric_limits<int>::max();
    for (const grid::Cell c : at) {
      x_lo_ = std::min(x_lo_, c.x);
      y_lo_ = std::min(y_lo_, c.y);
      x_hi = std::max(x_hi, c.x);
      y_hi = std::max(y_hi, c.y);
    }
    columns_ = (x_hi - x_lo_) / side_ + 1;
    rows_ = (y_hi - y_lo_) / side_ + 1;
    start_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
    for (const grid::Cell c : at) ++start_[static_cast<std::size_t>(bucket(c)) + 1];
    for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
    nodes_.resize(at.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < at.size(); ++i)
      nodes_[static_cast<std::size_t>(fill[static_cast<std::size_t>(bucket(at[i]))]++)] =
          static_cast<int>(i);
  }

  int side() const { return side_; }
  int column(grid::Cell c) const { return std::clamp((c.x - x_lo_) / side_, 0, columns_ - 1); }
  int row(grid::Cell c) const { return std::clamp((c.y - y_lo_) / side_, 0, rows_ - 1); }
  /// Rings beyond which no bucket lies, from the bucket (column, row).
  int last_ring(int column, int row) const {
    return std::max({column, columns_ - 1 - column, row, rows_ - 1 - row});
  }
  /// Calls visit(node) for every node in the buckets at Chebyshev distance `ring` from
  /// (column, row).
  template <typename Visit>
  void ring(int column, int row, int ring, Visit&& visit) const {
    for (int r = row - ring; r <= row + ring; ++r) {
      if (r < 0 || r >= rows_) continue;
      const bool edge_row = r == row - ring || r == row + ring;
      const int step = edge_row ? 1 : std::max(1, 2 * ring);
      for (int q = column - ring; q <= column + ring; q += step) {
        if (q < 0 || q >= columns_) continue;
        const auto b = static_cast<std::size_t>(r * columns_ + q);
        for (int k = start_[b]; k < start_[b + 1]; ++k) visit(nodes_[static_cast<std::size_t>(k)]);
      }
    }
  }

 private:
  int bucket(grid::Cell c) const { return row(c) * columns_ + column(c); }

  int side_;
  int x_lo_;
  int y_lo_;
  int columns_ = 1;
  int rows_ = 1;
  std::vector<int> start_;  // bucket b's nodes are nodes_[start_[b], start_[b + 1])
  std::vector<int> nodes_;
};

/// The least leg cost to any point of a bucket `ring` rings away: such a point differs by at
/// least (ring − 1)·side + 1 on one axis.
int ring_bound(int ring, int side, int reach) {
  return ring == 0 ? 0 : std::max(0, (ring - 1) * side + 1 - reach);
}

/// Nearer first; equally near, the lower node first (the order never depends on the search's).
bool nearer(std::pair<int, int> a, std::pair<int, int> b) {
  return a < b;
}

/// The `Size` nearest candidates offered, nearest first.
template <int Size>
struct NearestOf {
  std::array<std::pair<int, int>, Size> best{};
  int found = 0;

  void offer(std::pair<int, int> candidate) {
    if (found == Size && !nearer(candidate, best.back())) return;
    int k = found == Size ? Size - 1 : found++;
    while (k > 0 && nearer(candidate, best[static_cast<std::size_t>(k - 1)])) {
      best[static_cast<std::size_t>(k)] = best[static_cast<std::size_t>(k - 1)];
      --k;
    }
    best[static_cast<std::size_t>(k)] = candidate;
  }
  /// No candidate at least `bound` away can enter.
  bool done(int bound) const { return found == Size && bound > best.back().first; }
};

class NeighbourSearch {
 public:
  NeighbourSearch(grid::Cell from, std::span<grid::Cell> points, const OpenTourCost& cost)
      : points_(points), cost_(cost), m_(static_cast<int>(points.size())), end_(m_ + 1) {
    at_.reserve(points.size() + 1);
    at_.push_back(from);
    at_.insert(at_.end(), points.begin(), points.end());
  }

  void run() {
    // About two nodes per bucket over the points' bounding box.
    long long width = 1;
    long long height = 1;
    {
      const auto [x0, x1] =
          std::minmax_element(at_.begin(), at_.end(), [](auto a, auto b) { return a.x < b.x; });
      const auto [y0, y1] =
          std::minmax_element(at_.begin(), at_.end(), [](auto a, auto b) { return a.y < b.y; });
      width = x1->x - x0->x + 1;
      height = y1->y - y0->y + 1;
    }
    const double per_node = static_cast<double>(width * height) / static_cast<double>(at_.size());
    const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(2.0 * per_node))));
    const Buckets buckets(at_, side);
    nearest_neighbour(buckets);
    neighbour_lists(buckets);
    local_search();
    for (int p = 1; p <= m_; ++p) points_[static_cast<std::size_t>(p - 1)] = at_[node(p)];
  }

 private:
  std::size_t node(int position) const {
    return static_cast<std::size_t>(order_[static_cast<std::size_t>(position)]);
  }
  int d(int a, int b) const {
    if (a == end_ || b == end_) return 0;  // the tour's end is free
    return cost_.leg(at_[static_cast<std::size_t>(a)], at_[static_cast<std::size_t>(b)]);
  }
  /// The leg's cost, ties broken by the Manhattan distance: points within a footprint all cost
  /// nothing, and the nearer of them make the better neighbours.
  int nearness(int a, int b) const {
    const grid::Cell p = at_[static_cast<std::size_t>(a)];
    const grid::Cell q = at_[static_cast<std::size_t>(b)];
    const int manhattan = std::abs(p.x - q.x) + std::abs(p.y - q.y);
    return cost_.leg(p, q) * kNearness + std::min(manhattan, kNearness - 1);
  }
  int pos(int a) const { return pos_[static_cast<std::size_t>(a)]; }
  int at_position(int p) const { return order_[static_cast<std::size_t>(p)]; }

  void nearest_neighbour(const Buckets& buckets) {
    std::vector<char> taken(at_.size(), 0);
    taken[0] = 1;
    order_.assign(1, 0);
    int here = 0;
    for (int step = 0; step < m_; ++step) {
      const grid::Cell c = at_[static_cast<std::size_t>(here)];
      const int column = buckets.column(c);
      const int row = buckets.row(c);
      std::pair<int, int> best{std::numeric_limits<int>::max(), 0};
      const int last = buckets.last_ring(column, row);
      for (int r = 0; r <= last; ++r) {
        if (best.first < std::numeric_limits<int>::max() &&
            ring_bound(r, buckets.side(), cost_.reach) * kNearness > best.first)
          break;
        buckets.ring(column, row, r, [&](int v) {
          if (taken[static_cast<std::size_t>(v)] != 0) return;
          const std::pair<int, int> candidate{nearness(here, v), v};
          if (nearer(candidate, best)) best = candidate;
        });
      }
      here = best.second;
      taken[static_cast<std::size_t>(here)] = 1;
      order_.push_back(here);
    }
    order_.push_back(end_);
    pos_.assign(order_.size(), 0);
    for (std::size_t p = 0; p < order_.size(); ++p)
      pos_[static_cast<std::size_t>(order_[p])] = static_cast<int>(p);
  }

  using Nearest = NearestOf<kNeighbours>;
  using QuadrantNearest = NearestOf<kPerQuadrant>;

  void neighbour_lists(const Buckets& buckets) {
    // The nearest points alone are all in the same corrosion patch (legs within a footprint cost
    // nothing), so each point also gets the nearest in each quadrant around it, which lead out of
    // the patch; those are looked for only a few rings of buckets further.
    neighbours_.assign(at_.size() * kListSize, -1);
    for (std::size_t a = 0; a < at_.size(); ++a) {
      Nearest nearest;
      std::array<QuadrantNearest, 4> quadrant;
      const grid::Cell here = at_[a];
      const int column = buckets.column(here);
      const int row = buckets.row(here);
      const int last = buckets.last_ring(column, row);
      int cap = last;
      for (int r = 0; r <= std::min(last, cap); ++r) {
        const int bound = ring_bound(r, buckets.side(), cost_.reach) * kNearness;
        const bool nearest_done = nearest.done(bound);
        if (nearest_done && cap == last) cap = r + kQuadrantRings;
        if (nearest_done && std::all_of(quadrant.begin(), quadrant.end(),
                                        [&](const QuadrantNearest& q) { return q.done(bound); }))
          break;
        buckets.ring(column, row, r, [&](int v) {
          if (static_cast<std::size_t>(v) == a) return;
          const grid::Cell c = at_[static_cast<std::size_t>(v)];
          const std::pair<int, int> candidate{nearness(static_cast<int>(a), v), v};
          nearest.offer(candidate);
          const int dx = c.x - here.x;
          const int dy = c.y - here.y;
          const int q = dx > 0 && dy >= 0 ? 0 : dx <= 0 && dy > 0 ? 1 : dx < 0 && dy <= 0 ? 2 : 3;
          quadrant[static_cast<std::size_t>(q)].offer(candidate);
        });
      }
      int* list = &neighbours_[a * kListSize];
      int size = 0;
      const auto add = [&](const auto& from) {
        for (int k = 0; k < from.found; ++k) {
          const int v = from.best[static_cast<std::size_t>(k)].second;
          if (std::find(list, list + size, v) == list + size) list[size++] = v;
        }
      };
      add(nearest);
      for (const QuadrantNearest& q : quadrant) add(q);
    }
  }

  std::span<const int> neighbours(int a) const {
    const auto first = neighbours_.begin() + static_cast<std::ptrdiff_t>(a) * kListSize;
    const auto past = std::find(first, first + kListSize, -1);
    return {first, past};
  }

  using Move = open_tour_detail::TourMove;

  void consider_reversal(Move& best, int i, int j) const {
    // Reversing [i, j] replaces the edges (i − 1, i) and (j, j + 1) by (i − 1, j) and (i, j + 1).
    if (i < 1 || j <= i || j > m_) return;
    const int before = at_position(i - 1);
    const int first = at_position(i);
    const int last = at_position(j);
    const int after = at_position(j + 1);
    const int gain = d(before, first) + d(last, after) - d(before, last) - d(first, after);
    if (gain > best.gain) best = {gain, true, i, j, 0, false};
  }

  void best_two_opt(int a, Move& best) const {
    const int p = pos(a);
    for (const int c : neighbours(a)) {
      // New edge (a, c) with a's successor and c's successor joined, or a's predecessor and c's.
      const int q = pos(c);
      if (q > p) {
        consider_reversal(best, p + 1, q);
        consider_reversal(best, p, q - 1);
      } else {
        consider_reversal(best, q + 1, p);
        consider_reversal(best, q, p - 1);
      }
    }
  }

  void consider_insertion(Move& best, int s, int e, int removed, int q) const {
    // Between positions q and q + 1, both outside the run [s, e].
    if (q < 0 || q > m_ || (q >= s - 1 && q <= e)) return;
    const int u = at_position(q);
    const int v = at_position(q + 1);
    const int first = at_position(s);
    const int last = at_position(e);
    const int base = d(u, v);
    const int forward = removed - (d(u, first) + d(last, v) - base);
    const int reversed = removed - (d(u, last) + d(first, v) - base);
    if (forward > best.gain) best = {forward, false, s, e, q, false};
    if (reversed > best.gain) best = {reversed, false, s, e, q, true};
  }

  void best_or_opt(int a, Move& best) const {
    const int p = pos(a);
    for (int len = 1; len <= 3; ++len) {
      for (const int s : {p, p - len + 1}) {
        const int e = s + len - 1;
        if (s < 1 || e > m_) continue;
        const int removed = d(at_position(s - 1), at_position(s)) +
                            d(at_position(e), at_position(e + 1)) -
                            d(at_position(s - 1), at_position(e + 1));
        if (removed <= 0) continue;
        for (const int end : {at_position(s), at_position(e)}) {
          for (const int c : neighbours(end)) {
            consider_insertion(best, s, e, removed, pos(c));
            consider_insertion(best, s, e, removed, pos(c) - 1);
          }
        }
        if (len == 1) break;  // both runs are the same
      }
    }
  }

  void push(int a) {
    if (a == end_ || queued_[static_cast<std::size_t>(a)] != 0) return;
    queued_[static_cast<std::size_t>(a)] = 1;
    queue_.push_back(a);
  }

  /// Applies `move`, queueing the ends of every edge it changed.
  void apply(const Move& move) {
    open_tour_detail::apply_tour_move(move, order_, pos_, [&](int p) { push(at_position(p)); });
  }

  /// Don't-look bits: a node is looked at again only when an edge at it changed. Every move
  /// shortens the tour by at least 1; the cap only bounds the time on pathological inputs.
  void local_search() {
    queued_.assign(at_.size() + 1, 0);
    queue_.clear();
    for (int p = 0; p <= m_; ++p) push(at_position(p));
    const long long max_moves = 50LL * (m_ + 1);
    long long moves = 0;
    for (std::size_t head = 0; head < queue_.size() && moves < max_moves; ++head) {
      const int a = queue_[head];
      queued_[static_cast<std::size_t>(a)] = 0;
      Move best;
      best_two_opt(a, best);
      best_or_opt(a, best);
      if (best.gain <= 0) continue;
      apply(best);
      push(a);
      ++moves;
      // The queue only grows; drop the part looked at when it is most of it.
      if (head > 4096 && head * 2 > queue_.size()) {
        queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head) + 1);
        head = static_cast<std::size_t>(-1);
      }
    }
  }

  std::span<grid::Cell> points_;
  OpenTourCost cost_;
  int m_;
  int end_;                     // node m + 1: the free end after the last point
  std::vector<grid::Cell> at_;  // node → its cell (not the end)
  std::vector<int> order_;      // position → node: 0 first, end_ last
  std::vector<int> pos_;        // node → position
  std::vector<int> neighbours_;
  std::vector<char> queued_;
  std::vector<int> queue_;
};

}  // namespace

void plan_open_tour_neighbours(grid::Cell from, std::span<grid::Cell> points,
                               const OpenTourCost& cost) {
  if (points.empty()) return;
  NeighbourSearch(from, points, cost).run();
}

}  // namespace hullinspect::planners
