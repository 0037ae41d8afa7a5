#include "hullinspect/planners/coop_frontier_assignment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "hullinspect/grid/distance.hpp"

namespace hullinspect::planners {

namespace {
bool is_distance(int d) { return d >= 0 && d < grid::kUnreachable; }
}  // namespace

double frontier_utility(double alpha, int d_hp, int d_c) {
  double u = 0;
  if (is_distance(d_hp)) u += alpha / std::max(1, d_hp);
  if (is_distance(d_c)) u += (1.0 - alpha) / std::max(1, d_c);
  return u;
}

double utility_reduction(double d, int s2) {
  const double radius = 2.0 * s2;
  return d < radius ? d / radius : 1.0;
}

void FrontierAssigner::configure(double beta, int s2, int max_distance) {
  beta_ = beta;
  s2_ = s2;
  travel_term_.resize(static_cast<std::size_t>(std::max(0, max_distance)) + 1);
  for (std::size_t d = 0; d < travel_term_.size(); ++d) {
    travel_term_[d] = beta / static_cast<double>(std::max<std::size_t>(1, d));
  }
  // P depends on the Euclidean distance between two cells only through its square, an integer.
  const int radius = 2 * s2;
  reduction_.resize(static_cast<std::size_t>(radius) * static_cast<std::size_t>(radius));
  for (std::size_t q = 0; q < reduction_.size(); ++q) {
    reduction_[q] = utility_reduction(std::sqrt(static_cast<double>(q)), s2);
  }
}

void FrontierAssigner::reduce_around(std::span<const grid::Cell> frontiers, grid::Cell assigned) {
  const auto limit = static_cast<long long>(reduction_.size());
  for (std::size_t j = 0; j < frontiers.size(); ++j) {
    const long long dx = frontiers[j].x - assigned.x;
    const long long dy = frontiers[j].y - assigned.y;
    const long long q = dx * dx + dy * dy;
    if (q < limit) reduced_[j] *= reduction_[static_cast<std::size_t>(q)];
  }
}

void FrontierAssigner::assign(std::span<const grid::Cell> frontiers,
                              std::span<const double> utility, std::span<const grid::Cell> held,
                              std::span<const grid::Cell> robots, std::span<int> chosen) {
  picks_.clear();
  std::fill(chosen.begin(), chosen.end(), -1);
  reduced_.assign(utility.begin(), utility.end());
  if (frontiers.empty()) return;
  for (const grid::Cell h : held) reduce_around(frontiers, h);
  assigned_.assign(robots.size(), 0);

  const auto table = travel_term_.size();
  for (std::size_t round = 0; round < robots.size(); ++round) {
    Pick best;
    for (std::size_t r = 0; r < robots.size(); ++r) {
      if (assigned_[r]) continue;
      const grid::Cell at = robots[r];
      for (std::size_t j = 0; j < frontiers.size(); ++j) {
        const auto d = static_cast<std::size_t>(grid::manhattan(at, frontiers[j]));
        const double travel = d < table ? travel_term_[d] : beta_ / static_cast<double>(d);
        const double score = reduced_[j] + travel;
        // Robots are scanned in id order, so an equal score only wins on a lower (y, x) frontier
        // of the same robot.
        if (best.robot < 0 || score > best.score ||
            (score == best.score && static_cast<int>(r) == best.robot &&
             frontiers[j] < frontiers[static_cast<std::size_t>(best.frontier)])) {
          best = {static_cast<int>(r), static_cast<int>(j), score};
        }
      }
    }
    assigned_[static_cast<std::size_t>(best.robot)] = 1;
    chosen[static_cast<std::size_t>(best.robot)] = best.frontier;
    picks_.push_back(best);
    reduce_around(frontiers, frontiers[static_cast<std::size_t>(best.frontier)]);
  }
}

}  // namespace hullinspect::planners
