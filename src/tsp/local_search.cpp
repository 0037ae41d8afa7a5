#include "local_search.hpp"

#include <algorithm>

#include "hullinspect/world/random.hpp"

namespace hullinspect::tsp::detail {

long long LocalSearch::run(const EndCosts& costs, int kicks, std::uint64_t seed,
                           std::vector<int>& best) {
  nearest_neighbour(costs, best);
  descend(costs, best);
  long long best_length = costs.length(best);
  const int g = costs.segments();
  if (g < 3) return best_length;  // too few visits for a double bridge to change anything
  world::RandomStream random(seed, world::Stream::kPlanner);
  const auto positions = static_cast<std::uint64_t>(g) + 1;
  for (int kick = 0; kick < kicks; ++kick) {
    // Double bridge on the open path: A B C D → A C B D with B and C non-empty.
    std::size_t cut[3];
    do {
      for (auto& c : cut) c = static_cast<std::size_t>(random.below(positions));
      std::sort(cut, cut + 3);
    } while (cut[0] == cut[1] || cut[1] == cut[2]);
    current_ = best;
    std::rotate(current_.begin() + static_cast<std::ptrdiff_t>(cut[0]),
                current_.begin() + static_cast<std::ptrdiff_t>(cut[1]),
                current_.begin() + static_cast<std::ptrdiff_t>(cut[2]));
    descend(costs, current_);
    const long long length = costs.length(current_);
    if (length < best_length) {
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

long long LocalSearch::descend(const EndCosts& costs, std::vector<int>& tour) {
  long long total = 0;
  while (true) {
    const long long change = two_opt_pass(costs, tour) + or_opt_pass(costs, tour);
    if (change == 0) return total;
    total += change;
  }
}

long long LocalSearch::two_opt_pass(const EndCosts& costs, std::vector<int>& tour) {
  const std::size_t n = tour.size();
  long long total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) {
      // Reverse visits i..j: the run is entered by tour[j]'s other end and left by tour[i].
      const int before_exit = i == 0 ? costs.start() : tour[i - 1] ^ 1;
      long long change = costs(before_exit, tour[j] ^ 1) - costs(before_exit, tour[i]);
      if (j + 1 < n) change += costs(tour[i], tour[j + 1]) - costs(tour[j] ^ 1, tour[j + 1]);
      if (change < 0) {
        std::reverse(tour.begin() + static_cast<std::ptrdiff_t>(i),
                     tour.begin() + static_cast<std::ptrdiff_t>(j + 1));
        for (std::size_t k = i; k <= j; ++k) tour[k] ^= 1;
        total += change;
      }
    }
  }
  return total;
}

long long LocalSearch::or_opt_pass(const EndCosts& costs, std::vector<int>& tour) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(tour.size());
  long long total = 0;
  for (std::ptrdiff_t length = 1; length <= 3; ++length) {
    for (std::ptrdiff_t i = 0; i + length <= n; ++i) {
      const std::ptrdiff_t last = i + length - 1;
      const int before = i == 0 ? costs.start() : tour[static_cast<std::size_t>(i - 1)] ^ 1;
      const int first_entry = tour[static_cast<std::size_t>(i)];
      const int last_exit = tour[static_cast<std::size_t>(last)] ^ 1;
      const bool has_after = last + 1 < n;
      const int after = has_after ? tour[static_cast<std::size_t>(last + 1)] : -1;
      long long removal = -costs(before, first_entry);
      if (has_after) removal += costs(before, after) - costs(last_exit, after);
      // Insert after visit k (k = -1: right after the UAV), in either direction.
      for (std::ptrdiff_t k = -1; k < n; ++k) {
        if (k >= i - 1 && k <= last) continue;
        const int from = k < 0 ? costs.start() : tour[static_cast<std::size_t>(k)] ^ 1;
        const bool has_to = k + 1 < n;
        const int to = has_to ? tour[static_cast<std::size_t>(k + 1)] : -1;
        const long long gap = has_to ? costs(from, to) : 0;
        const long long forward =
            costs(from, first_entry) + (has_to ? costs(last_exit, to) : 0) - gap;
        const long long backward =
            costs(from, last_exit) + (has_to ? costs(first_entry, to) : 0) - gap;
        const bool reverse = backward < forward;
        const long long change = removal + (reverse ? backward : forward);
        if (change >= 0) continue;
        auto begin = tour.begin();
        std::ptrdiff_t at = 0;  // where the run starts after the move
        if (k < i) {
          std::rotate(begin + k + 1, begin + i, begin + last + 1);
          at = k + 1;
        } else {
          std::rotate(begin + i, begin + last + 1, begin + k + 1);
          at = k + 1 - length;
        }
        if (reverse) {
          std::reverse(begin + at, begin + at + length);
          for (std::ptrdiff_t m = at; m < at + length; ++m) tour[static_cast<std::size_t>(m)] ^= 1;
        }
        total += change;
        break;  // the run moved; continue scanning from the next start position
      }
    }
  }
  return total;
}

}  // namespace hullinspect::tsp::detail
