// Repairing an open tour (open_tour.hpp) after its start moved and some of its points left it:
// the exhaustive search's moves, looked for only where the tour changed, so that keeping a tour
// short as the UAV flies it costs about linear work per change instead of a new plan.

#include <algorithm>
#include <vector>

#include "hullinspect/planners/open_tour.hpp"
#include "open_tour_moves.hpp"

namespace hullinspect::planners {

namespace {

class TourRepair {
 public:
  TourRepair(grid::Cell from, std::span<grid::Cell> points, const OpenTourCost& cost)
      : points_(points), cost_(cost), m_(static_cast<int>(points.size())) {
    at_.reserve(points.size() + 1);
    at_.push_back(from);
    at_.insert(at_.end(), points.begin(), points.end());
    order_.resize(at_.size());
    pos_.resize(at_.size());
    for (int p = 0; p <= m_; ++p) {
      order_[static_cast<std::size_t>(p)] = p;
      pos_[static_cast<std::size_t>(p)] = p;
    }
    queued_.assign(at_.size(), 0);
  }

  void run(std::span<const std::size_t> touched) {
    for (const std::size_t node : touched) {
      if (node <= static_cast<std::size_t>(m_)) push(static_cast<int>(node));
    }
    // Every move shortens the tour by at least 1; the cap only bounds the time on
    // pathological inputs.
    const long long max_moves = 50LL * (m_ + 1);
    long long moves = 0;
    for (std::size_t head = 0; head < queue_.size() && moves < max_moves; ++head) {
      const int a = queue_[head];
      queued_[static_cast<std::size_t>(a)] = 0;
      Move best;
      best_two_opt(pos(a), best);
      best_or_opt(pos(a), best);
      if (best.gain <= 0) continue;
      apply(best);
      push(a);
      ++moves;
    }
    for (int p = 1; p <= m_; ++p) points_[static_cast<std::size_t>(p - 1)] = at_[node(p)];
  }

 private:
  using Move = open_tour_detail::TourMove;

  std::size_t node(int position) const {
    return static_cast<std::size_t>(order_[static_cast<std::size_t>(position)]);
  }
  int pos(int a) const { return pos_[static_cast<std::size_t>(a)]; }
  /// The leg from position p to position q; none after the last position (the end is free).
  int d(int p, int q) const {
    if (p > m_ || q > m_) return 0;
    return cost_.leg(at_[node(p)], at_[node(q)]);
  }

  void consider_reversal(Move& best, int i, int j) const {
    // Reversing [i, j] replaces the edges (i − 1, i) and (j, j + 1) by (i − 1, j) and (i, j + 1).
    if (i < 1 || j <= i || j > m_) return;
    const int gain = d(i - 1, i) + d(j, j + 1) - d(i - 1, j) - d(i, j + 1);
    if (gain > best.gain) best = {gain, true, i, j, 0, false};
  }

  /// Every reversal that removes an edge at position p.
  void best_two_opt(int p, Move& best) const {
    for (int other = 0; other <= m_; ++other) {
      consider_reversal(best, p + 1, other);  // removes (p, p + 1)
      consider_reversal(best, p, other);      // removes (p − 1, p)
      consider_reversal(best, other, p);      // removes (p, p + 1) at the run's end
      consider_reversal(best, other, p - 1);  // removes (p − 1, p) at the run's end
    }
  }

  /// Every move of a run of 1–3 positions that starts or ends at p to between two other
  /// positions, or after the last, either way round.
  void best_or_opt(int p, Move& best) const {
    for (int len = 1; len <= 3; ++len) {
      for (const int s : {p, p - len + 1}) {
        const int e = s + len - 1;
        if (s < 1 || e > m_) continue;
        const int removed = d(s - 1, s) + d(e, e + 1) - d(s - 1, e + 1);
        if (removed > 0) {
          for (int q = 0; q <= m_; ++q) {
            if (q >= s - 1 && q <= e) continue;  // next to or inside the run: no move
            const int base = d(q, q + 1);
            const int forward = removed - (d(q, s) + d(e, q + 1) - base);
            const int reversed = removed - (d(q, e) + d(s, q + 1) - base);
            if (forward > best.gain) best = {forward, false, s, e, q, false};
            if (reversed > best.gain) best = {reversed, false, s, e, q, true};
          }
        }
        if (len == 1) break;  // both runs are the same
      }
    }
  }

  void push(int a) {
    if (queued_[static_cast<std::size_t>(a)] != 0) return;
    queued_[static_cast<std::size_t>(a)] = 1;
    queue_.push_back(a);
  }

  void push_at(int position) {
    if (position >= 0 && position <= m_) push(static_cast<int>(node(position)));
  }

  /// Applies `move`, queueing the ends of every edge it changed.
  void apply(const Move& move) {
    open_tour_detail::apply_tour_move(move, order_, pos_, [&](int p) { push_at(p); });
  }

  std::span<grid::Cell> points_;
  OpenTourCost cost_;
  int m_;
  std::vector<grid::Cell> at_;  // node → its cell: 0 the start, i ≥ 1 points[i − 1]
  std::vector<int> order_;      // position → node
  std::vector<int> pos_;        // node → position
  std::vector<char> queued_;
  std::vector<int> queue_;
};

}  // namespace

void repair_open_tour(grid::Cell from, std::span<grid::Cell> points,
                      std::span<const std::size_t> touched, const OpenTourCost& cost) {
  if (points.size() < 2) return;
  TourRepair(from, points, cost).run(touched);
}

}  // namespace hullinspect::planners
