#include "local_search.hpp"

#include <algorithm>

#include "hullinspect/world/random.hpp"

namespace hullinspect::tsp::detail {

long long LocalSearch::run(const EndCosts& costs, int kicks, std::uint64_t seed,
                           std::vector<int>& best) {
  nearest_neighbour(costs, best);
  activate_all(best);
  descend(costs, best);
  long long best_length = costs.length(best);
  const int g = costs.segments();
  if (g < 3) return best_length;  // too few visits for a double bridge to change anything
  world::RandomStream random(seed, world::Stream::kPlanner);
  const auto positions = static_cast<std::uint64_t>(g) + 1;
  for (int kick = 0; kick < kicks; ++kick) {
    // Double bridge on the open path: A B C D → A C B D with B and C non-empty.
    int cut[3];
    do {
      for (auto& c : cut) c = static_cast<int>(random.below(positions));
      std::sort(cut, cut + 3);
    } while (cut[0] == cut[1] || cut[1] == cut[2]);
    current_ = best;
    std::rotate(current_.begin() + cut[0], current_.begin() + cut[1], current_.begin() + cut[2]);
    active_.assign(static_cast<std::size_t>(g), 0);
    queue_.clear();
    const int middle = cut[0] + (cut[2] - cut[1]);  // where B now starts
    for (int p : {cut[0] - 1, cut[0], middle - 1, middle, cut[2] - 1, cut[2]}) {
      activate_position(current_, p);
    }
    descend(costs, current_);
    const long long length = costs.length(current_);
    if (length <= best_length) {  // equal too: drift across the many ties of Manhattan costs
      best_length = length;
      best.swap(current_);
    }
  }
  return best_length;
}

void LocalSearch::nearest_neighbour(const EndCosts& costs, std::vector<int>& tour) {
  const int n = costs.ends();
  used_.assign(static_cast<std::size_t>(costs.segments()), 0);
  tour.clear();
  int at = costs.start();
  for (int step = 0; step < costs.segments(); ++step) {
    int pick = -1;
    for (int e = 0; e < n; ++e) {
      if (used_[static_cast<std::size_t>(e >> 1)] != 0) continue;
      if (pick < 0 || costs(at, e) < costs(at, pick)) pick = e;
    }
    used_[static_cast<std::size_t>(pick >> 1)] = 1;
    tour.push_back(pick);
    at = pick ^ 1;
  }
}

void LocalSearch::activate_position(const std::vector<int>& tour, int position) {
  if (position < 0 || position >= static_cast<int>(tour.size())) return;
  const auto segment = static_cast<std::size_t>(tour[static_cast<std::size_t>(position)] >> 1);
  if (active_[segment] != 0) return;
  active_[segment] = 1;
  queue_.push_back(static_cast<int>(segment));
}

void LocalSearch::activate_all(const std::vector<int>& tour) {
  active_.assign(tour.size(), 0);
  queue_.clear();
  for (int p = static_cast<int>(tour.size()) - 1; p >= 0; --p) activate_position(tour, p);
}

void LocalSearch::descend(const EndCosts& costs, std::vector<int>& tour) {
  while (!queue_.empty()) {
    const int segment = queue_.back();
    queue_.pop_back();
    active_[static_cast<std::size_t>(segment)] = 0;
    int position = 0;
    while (tour[static_cast<std::size_t>(position)] >> 1 != segment) ++position;
    if (improve_at(costs, tour, position)) {
      active_[static_cast<std::size_t>(segment)] = 1;
      queue_.push_back(segment);
    }
  }
}

bool LocalSearch::improve_at(const EndCosts& costs, std::vector<int>& tour, int i) {
  if (two_opt_at(costs, tour, i)) return true;
  const int n = static_cast<int>(tour.size());
  for (int length = 1; length <= 3; ++length) {
    if (i + length <= n && or_opt_block(costs, tour, i, i + length - 1)) return true;
    if (length > 1 && i - length + 1 >= 0 && or_opt_block(costs, tour, i - length + 1, i))
      return true;
  }
  return false;
}

void LocalSearch::reverse(std::vector<int>& tour, int from, int to) {
  std::reverse(tour.begin() + from, tour.begin() + to + 1);
  for (int k = from; k <= to; ++k) tour[static_cast<std::size_t>(k)] ^= 1;
  for (int p : {from - 1, from, to, to + 1}) activate_position(tour, p);
}

bool LocalSearch::two_opt_at(const EndCosts& costs, std::vector<int>& tour, int i) {
  // Reverse visits a..b (each flipped): the run is entered by tour[b]'s other end and left by
  // tour[a]. Position i as the first (a = i) or the last (b = i) visit of the run.
  const int n = static_cast<int>(tour.size());
  auto change = [&](int a, int b) {
    const int before = a == 0 ? costs.start() : tour[static_cast<std::size_t>(a - 1)] ^ 1;
    const int first = tour[static_cast<std::size_t>(a)];
    const int last_exit = tour[static_cast<std::size_t>(b)] ^ 1;
    long long delta = costs(before, last_exit) - costs(before, first);
    if (b + 1 < n) {
      const int after = tour[static_cast<std::size_t>(b + 1)];
      delta += costs(first, after) - costs(last_exit, after);
    }
    return delta;
  };
  for (int b = i; b < n; ++b) {
    if (change(i, b) < 0) {
      reverse(tour, i, b);
      return true;
    }
  }
  for (int a = 0; a < i; ++a) {
    if (change(a, i) < 0) {
      reverse(tour, a, i);
      return true;
    }
  }
  return false;
}

bool LocalSearch::or_opt_block(const EndCosts& costs, std::vector<int>& tour, int i, int last) {
  const int n = static_cast<int>(tour.size());
  const int length = last - i + 1;
  const int before = i == 0 ? costs.start() : tour[static_cast<std::size_t>(i - 1)] ^ 1;
  const int first_entry = tour[static_cast<std::size_t>(i)];
  const int last_exit = tour[static_cast<std::size_t>(last)] ^ 1;
  const bool has_after = last + 1 < n;
  const int after = has_after ? tour[static_cast<std::size_t>(last + 1)] : -1;
  long long removal = -costs(before, first_entry);
  if (has_after) removal += costs(before, after) - costs(last_exit, after);
  // Insert after visit k (k = -1: right after the UAV), in either direction.
  for (int k = -1; k < n; ++k) {
    if (k >= i - 1 && k <= last) continue;
    const int from = k < 0 ? costs.start() : tour[static_cast<std::size_t>(k)] ^ 1;
    const bool has_to = k + 1 < n;
    const int to = has_to ? tour[static_cast<std::size_t>(k + 1)] : -1;
    const long long gap = has_to ? costs(from, to) : 0;
    const long long forward = costs(from, first_entry) + (has_to ? costs(last_exit, to) : 0) - gap;
    const long long backward = costs(from, last_exit) + (has_to ? costs(first_entry, to) : 0) - gap;
    const bool flip = backward < forward;
    if (removal + (flip ? backward : forward) >= 0) continue;
    auto begin = tour.begin();
    int at = 0;  // where the run starts after the move
    if (k < i) {
      std::rotate(begin + k + 1, begin + i, begin + last + 1);
      at = k + 1;
    } else {
      std::rotate(begin + i, begin + last + 1, begin + k + 1);
      at = k + 1 - length;
    }
    if (flip) {
      std::reverse(begin + at, begin + at + length);
      for (int m = at; m < at + length; ++m) tour[static_cast<std::size_t>(m)] ^= 1;
    }
    // Re-examine both joins of the run and the join it left.
    const int old_join = k < i ? last + 1 : i;
    for (int p : {at - 1, at, at + length - 1, at + length, old_join - 1, old_join}) {
      activate_position(tour, p);
    }
    return true;
  }
  return false;
}

}  // namespace hullinspect::tsp::detail
