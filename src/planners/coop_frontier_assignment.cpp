#include "hullinspect/planners/coop_frontier_assignment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "hullinspect/grid/distance.hpp"

namespace hullinspect::planners {

namespace {
bool is_distance(int d) {
  return d >= 0 && d < grid::kUnreachable;
}
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

void FrontierAssigner::reserve(int frontiers, int robots) {
  reduced_.reserve(static_cast<std::size_t>(std::max(0, frontiers)));
  const auto r = static_cast<std::size_t>(std::max(0, robots));
  assigned_.reserve(r);
  picks_.reserve(r);
  best_.reserve(r);
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

FrontierAssigner::Pick FrontierAssigner::best_for(std::span<const grid::Cell> frontiers, int robot,
                                                  grid::Cell at) const {
  const auto table = travel_term_.size();
  grid::DistanceService* distances =
      robot_distances_.empty() ? distances_ : robot_distances_[static_cast<std::size_t>(robot)];
  const grid::Grid<int>* field =
      distances != nullptr && distances->searched() ? &distances->field(at) : nullptr;
  Pick best;
  for (std::size_t j = 0; j < frontiers.size(); ++j) {
    // With the flight space in parts, only frontiers the robot's own part can see.
    if (!robot_distances_.empty() &&
        distances->viewpoint(frontiers[j], robot_half_) == grid::kNoCell) {
      continue;
    }
    const auto d = static_cast<std::size_t>(field != nullptr ? (*field)[frontiers[j]]
                                                             : grid::manhattan(at, frontiers[j]));
    const double travel = d < table ? travel_term_[d] : beta_ / static_cast<double>(d);
    const double score = reduced_[j] + travel;
    if (best.frontier < 0 || score > best.score ||
        (score == best.score &&
         frontiers[j] < frontiers[static_cast<std::size_t>(best.frontier)])) {
      best = {robot, static_cast<int>(j), score};
    }
  }
  return best;
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
  // Each robot's best frontier under the current reduced utilities. A reduction only lowers U, so a
  // robot's best stays its best unless that very frontier was reduced: only then is it recomputed.
  // This gives the same pairs as scanning every (r, f) in every round.
  best_.resize(robots.size());
  for (std::size_t r = 0; r < robots.size(); ++r) {
    best_[r] = best_for(frontiers, static_cast<int>(r), robots[r]);
  }
  const auto limit = static_cast<long long>(reduction_.size());
  for (std::size_t round = 0; round < robots.size(); ++round) {
    // argmax over robots; the scan in id order keeps the lowest robot on equal scores, and each
    // robot's own best already has the lowest (y, x) among its equal scores.
    int winner = -1;
    for (std::size_t r = 0; r < robots.size(); ++r) {
      if (assigned_[r]) continue;
      const auto w = static_cast<std::size_t>(winner);
      if (winner < 0 || (best_[w].frontier < 0 && best_[r].frontier >= 0) ||
          (best_[r].frontier >= 0 && best_[r].score > best_[w].score)) {
        winner = static_cast<int>(r);
      }
    }
    const Pick pick = best_[static_cast<std::size_t>(winner)];
    assigned_[static_cast<std::size_t>(winner)] = 1;
    if (pick.frontier < 0) continue;  // nothing its part of the flight space can see
    chosen[static_cast<std::size_t>(winner)] = pick.frontier;
    picks_.push_back(pick);
    const grid::Cell f = frontiers[static_cast<std::size_t>(pick.frontier)];
    reduce_around(frontiers, f);
    for (std::size_t r = 0; r < robots.size(); ++r) {
      if (assigned_[r] || best_[r].frontier < 0) continue;
      const grid::Cell g = frontiers[static_cast<std::size_t>(best_[r].frontier)];
      const long long dx = g.x - f.x;
      const long long dy = g.y - f.y;
      if (dx * dx + dy * dy < limit) best_[r] = best_for(frontiers, static_cast<int>(r), robots[r]);
    }
  }
}

}  // namespace hullinspect::planners
