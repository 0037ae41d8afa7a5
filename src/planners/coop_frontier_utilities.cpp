#include "hullinspect/planners/coop_frontier_utilities.hpp"

#include <algorithm>

#include "hullinspect/grid/distance.hpp"

namespace hullinspect::planners {

namespace {
/// A bound computed in floating point is raised by this much, so that rounding can never bring it
/// below a score it has to bound (a tie skipped would change the tie-break).
double raised(double bound) {
  return bound + 1e-9 * (1.0 + std::abs(bound));
}
}  // namespace

double FieldUtilities::utility(int position) const {
  const int i = indices_[static_cast<std::size_t>(position)];
  return base_ +
         frontier_utility(alpha_, prior_ != nullptr ? prior_->distance(i) : grid::kUnreachable,
                          detected_ != nullptr ? detected_->distance(i) : grid::kUnreachable);
}

double FieldUtilities::utility_bound(int d_hp) const {
  return base_ + frontier_utility(alpha_, d_hp, detected_ != nullptr ? 1 : grid::kUnreachable);
}

double FieldUtilities::score_ceiling(grid::Cell at, int m, double beta) const {
  const auto travel = [&](int d) { return beta / static_cast<double>(std::max(1, d)); };
  const double everywhere = utility_bound(floor_);
  int here = grid::kUnreachable;
  if (prior_ != nullptr && manhattan_ && floor_ < grid::kUnreachable) {
    here = prior_->distance(at.y * width_ + at.x);
  }
  // From distance k = here − floor on, the triangle bound is no better than the floor.
  const int k = here < grid::kUnreachable ? here - floor_ : 0;
  if (m >= k) return raised(everywhere + travel(m));
  // For m ≤ d < k: U_f + β/max(1, d) ≤ α/max(1, here − d) + β/max(1, d) + the rest, a convex
  // function of d on [max(m, 1), min(k, here − 1)] (both terms are), so its largest value there is
  // at an end; d = 0 (only for m = 0), d = here (where max(1, ·) stops the growth) and d ≥ k (the
  // floor's bound with a smaller travel term than at k) are taken separately.
  const auto at_distance = [&](int d) {
    return utility_bound(std::max(floor_, here - d)) + travel(d);
  };
  double bound = std::max(at_distance(m), at_distance(std::max(m, 1)));
  bound = std::max(bound, at_distance(std::max(m, std::min(k, here - 1))));
  bound = std::max(bound, at_distance(k));
  return raised(bound);
}

}  // namespace hullinspect::planners
