#pragma once
// "exact" (the default TSP solver): proves optimality. Small instances go to a dynamic program over
// (visited segments, exit end); larger ones to a branch-and-cut (subtour and blossom cuts, strong
// branching, its own small dual simplex) that starts from the local search's tour; above
// `max_segments` (if set) the local search's tour is returned with a lower bound. See docs/tsp.md
// for the method and measurements.

#include <cstdint>
#include <memory>

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp {

namespace detail {
class SegmentDp;
class BranchAndCut;
class LocalSearch;
class EndCosts;
}  // namespace detail

struct ExactOptions {
  /// Seconds the branch-and-cut may run before it returns its best tour with optimal = false;
  /// 0 = no limit. The dynamic program (g ≤ dp_max_segments) always finishes.
  double time_limit = 0;
  /// Largest g solved by the dynamic program (0–16); larger g use branch-and-cut.
  int dp_max_segments = 8;
  /// Double-bridge kicks of the local search that gives the branch-and-cut its first tour.
  int kicks = 10;
  /// Largest g the branch-and-cut is tried on; above it the answer is the local search's tour
  /// (with `kicks` kicks) and a lower bound, optimal = false: bounded time whatever the instance
  /// (docs/tsp.md, "Bounded solves"). 0 = no limit.
  int max_segments = 120;
  /// Work the branch-and-cut may do before it returns its best tour and its root bound with
  /// optimal = false, in millions of units of Σ m² over its LP pivots (m rows): a deterministic
  /// bound (the same answer on every machine and load, unlike time_limit), about 2 ms of CPU per
  /// unit here (docs/tsp.md). 0 = no budget.
  double work_budget = 50;
};

class ExactSolver final : public TspSolver {
 public:
  explicit ExactSolver(ExactOptions options = {});
  ~ExactSolver() override;
  TspSolution solve(const SegmentTsp& problem) override;
  /// The declared options: "time-limit", "dp-max-segments", "kicks", "max-segments",
  /// "work-budget".
  static const Params<ExactOptions>& params();
  /// Reads the declared options; rejects unknown keys.
  static ExactOptions read_options(const OptionMap& options);

 private:
  ExactOptions options_;
  std::unique_ptr<detail::EndCosts> costs_;
  std::unique_ptr<detail::SegmentDp> dp_;
  std::unique_ptr<detail::LocalSearch> search_;
  std::unique_ptr<detail::BranchAndCut> branch_and_cut_;
  std::vector<int> entries_;
};

}  // namespace hullinspect::tsp
