#pragma once
// The frontier utilities the Coop-Frontier planner hands to its assignment: U_f of eq. 13 plus γ,
// read from the distance fields behind d_HP and d_C, and the bound that lets the assignment's
// ring search stop early (coop_frontier_assignment.hpp).

#include <span>

#include "hullinspect/planners/coop_frontier_assignment.hpp"
#include "hullinspect/planners/coop_frontier_fields.hpp"

namespace hullinspect::planners {

/// The bound: d_HP ≥ `floor` on every frontier, and with Manhattan distances also
/// d_HP(f) ≥ d_HP(at) − d at Manhattan distance d from `at` (the triangle inequality); d_C ≥ 1.
class FieldUtilities final : public FrontierUtilities {
 public:
  /// `indices`: F's flat indices by position; `prior` (null: α = 0) and `detected` (null: α = 1)
  /// the fields of d_HP and d_C; `floor` ≤ d_HP of every frontier (grid::kUnreachable: the prior
  /// set is empty); `manhattan`: d_HP is the Manhattan distance.
  FieldUtilities(double alpha, double base_utility, std::span<const int> indices, int width,
                 const SourceDistanceField* prior, const SourceDistanceField* detected, int floor,
                 bool manhattan)
      : alpha_(alpha),
        base_(base_utility),
        indices_(indices),
        width_(width),
        prior_(prior),
        detected_(detected),
        floor_(floor),
        manhattan_(manhattan) {}

  double utility(int position) const override;
  double score_ceiling(grid::Cell at, int m, double beta) const override;

 private:
  /// The bound on U_f for a frontier whose d_HP is at least d_hp.
  double utility_bound(int d_hp) const;

  double alpha_;
  double base_;
  std::span<const int> indices_;
  int width_;
  const SourceDistanceField* prior_;
  const SourceDistanceField* detected_;
  int floor_;
  bool manhattan_;
};

}  // namespace hullinspect::planners
