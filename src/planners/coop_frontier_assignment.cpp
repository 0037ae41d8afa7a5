#include "hullinspect/planners/coop_frontier_assignment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

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
  const auto f = static_cast<std::size_t>(std::max(0, frontiers));
  reduced_.reserve(f);
  stamp_.reserve(f);
  applied_.reserve(f);
  const auto r = static_cast<std::size_t>(std::max(0, robots));
  assigned_.reserve(r);
  picks_.reserve(r);
  best_.reserve(r);
}

double FrontierAssigner::reduction(grid::Cell a, grid::Cell b) const {
  const long long dx = a.x - b.x;
  const long long dy = a.y - b.y;
  const long long q = dx * dx + dy * dy;
  return q < static_cast<long long>(reduction_.size()) ? reduction_[static_cast<std::size_t>(q)]
                                                       : 1.0;
}

double FrontierAssigner::reduced(int position) {
  const auto j = static_cast<std::size_t>(position);
  const grid::Cell f = frontiers_[j];
  if (stamp_[j] != epoch_) {
    stamp_[j] = epoch_;
    double u = utilities_->utility(position);
    for (const grid::Cell h : held_) {
      if (const double p = reduction(f, h); p != 1.0) u *= p;
    }
    reduced_[j] = u;
    applied_[j] = 0;
  }
  for (; applied_[j] < picks_.size(); ++applied_[j]) {
    const grid::Cell g = frontiers_[static_cast<std::size_t>(picks_[applied_[j]].frontier)];
    if (const double p = reduction(f, g); p != 1.0) reduced_[j] *= p;
  }
  return reduced_[j];
}

void FrontierAssigner::consider(Pick& best, int robot, int j, std::size_t d) {
  const double travel = d < travel_term_.size() ? travel_term_[d] : beta_ / static_cast<double>(d);
  const double score = reduced(j) + travel;
  if (best.frontier < 0 || score > best.score ||
      (score == best.score && frontiers_[static_cast<std::size_t>(j)] <
                                  frontiers_[static_cast<std::size_t>(best.frontier)])) {
    best = {robot, j, score};
  }
}

FrontierAssigner::Pick FrontierAssigner::scan(int robot, grid::Cell at,
                                              grid::DistanceService* distances,
                                              const grid::Grid<int>* field) {
  Pick best;
  for (std::size_t j = 0; j < frontiers_.size(); ++j) {
    // With the flight space in parts, only frontiers the robot's own part can see.
    if (!robot_distances_.empty() &&
        distances->viewpoint(frontiers_[j], robot_half_) == grid::kNoCell) {
      continue;
    }
    const auto d = static_cast<std::size_t>(field != nullptr ? (*field)[frontiers_[j]]
                                                             : grid::manhattan(at, frontiers_[j]));
    consider(best, robot, static_cast<int>(j), d);
  }
  return best;
}

FrontierAssigner::Pick FrontierAssigner::rings(int robot, grid::Cell at,
                                               const grid::Grid<int>* field) {
  const int w = set_->width();
  const int h = set_->height();
  // Past this many cells looked at, a scan of F is cheaper than the rings still to come.
  const long long budget = static_cast<long long>(frontiers_.size()) / 2 + 32;
  long long looked = 0;
  Pick best;
  const auto look = [&](int x, int y, int m) {
    if (x < 0 || x >= w) return;
    const int j = set_->position(y * w + x);
    if (j < 0) return;
    consider(best, robot, j, static_cast<std::size_t>(field != nullptr ? (*field)(x, y) : m));
  };
  for (int m = 0; m <= w + h; ++m) {
    // Every frontier from ring m on scores at most the utilities' ceiling.
    if (best.frontier >= 0 && utilities_->score_ceiling(at, m, beta_) < best.score) break;
    looked += std::max(1, 4 * m);
    if (looked > budget) return scan(robot, at, nullptr, field);
    for (int dy = -m; dy <= m; ++dy) {
      const int y = at.y + dy;
      if (y < 0 || y >= h) continue;
      const int dx = m - std::abs(dy);
      look(at.x - dx, y, m);
      if (dx > 0) look(at.x + dx, y, m);
    }
  }
  return best;
}

FrontierAssigner::Pick FrontierAssigner::best_for(int robot, grid::Cell at) {
  grid::DistanceService* distances =
      robot_distances_.empty() ? distances_ : robot_distances_[static_cast<std::size_t>(robot)];
  const grid::Grid<int>* field =
      distances != nullptr && distances->searched() ? &distances->field(at) : nullptr;
  // The rings' bound takes a flight to be no shorter than the Manhattan distance, which a linked
  // seam breaks: such a hull is scanned.
  const bool seam = distances != nullptr && !distances->flight_table().seam.empty();
  if (set_ != nullptr && robot_distances_.empty() && !seam) return rings(robot, at, field);
  return scan(robot, at, distances, field);
}

namespace {
/// Utilities given as one value per frontier position.
class SpanUtilities final : public FrontierUtilities {
 public:
  explicit SpanUtilities(std::span<const double> values) : values_(values) {}
  double utility(int position) const override {
    return values_[static_cast<std::size_t>(position)];
  }
  double score_ceiling(grid::Cell, int, double) const override {
    return std::numeric_limits<double>::infinity();  // never read: a span is scanned
  }

 private:
  std::span<const double> values_;
};
}  // namespace

void FrontierAssigner::assign(std::span<const grid::Cell> frontiers,
                              std::span<const double> utility, std::span<const grid::Cell> held,
                              std::span<const grid::Cell> robots, std::span<int> chosen) {
  const SpanUtilities utilities(utility);
  frontiers_ = frontiers;
  set_ = nullptr;
  utilities_ = &utilities;
  held_ = held;
  run(robots, chosen);
  for (std::size_t j = 0; j < frontiers.size(); ++j) reduced(static_cast<int>(j));
  utilities_ = nullptr;
}

void FrontierAssigner::assign(const IndexedCellSet& frontiers, const FrontierUtilities& utilities,
                              std::span<const grid::Cell> held, std::span<const grid::Cell> robots,
                              std::span<int> chosen) {
  frontiers_ = frontiers.cells();
  set_ = &frontiers;
  utilities_ = &utilities;
  held_ = held;
  run(robots, chosen);
  utilities_ = nullptr;
}

void FrontierAssigner::run(std::span<const grid::Cell> robots, std::span<int> chosen) {
  picks_.clear();
  std::fill(chosen.begin(), chosen.end(), -1);
  if (frontiers_.empty()) return;
  // A new epoch voids every reduced value of the last call (all are voided again on wrap-around).
  if (++epoch_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    epoch_ = 1;
  }
  if (reduced_.size() < frontiers_.size()) {
    reduced_.resize(frontiers_.size());
    stamp_.resize(frontiers_.size(), 0u);
    applied_.resize(frontiers_.size());
  }
  assigned_.assign(robots.size(), 0);
  // Each robot's best frontier under the current reduced utilities. A reduction only lowers U, so a
  // robot's best stays its best unless that very frontier was reduced: only then is it recomputed.
  // This gives the same pairs as scanning every (r, f) in every round.
  best_.resize(robots.size());
  for (std::size_t r = 0; r < robots.size(); ++r) {
    best_[r] = best_for(static_cast<int>(r), robots[r]);
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
    const grid::Cell f = frontiers_[static_cast<std::size_t>(pick.frontier)];
    for (std::size_t r = 0; r < robots.size(); ++r) {
      if (assigned_[r] || best_[r].frontier < 0) continue;
      const grid::Cell g = frontiers_[static_cast<std::size_t>(best_[r].frontier)];
      const long long dx = g.x - f.x;
      const long long dy = g.y - f.y;
      if (dx * dx + dy * dy < limit) best_[r] = best_for(static_cast<int>(r), robots[r]);
    }
  }
}

}  // namespace hullinspect::planners
