#pragma once
// "cbc-cut": the paper's integer program (dfj-iterative's, Section IV-A) solved by CBC's
// branch-and-cut, with the subtour constraints (8) as lazy cuts: a cut generator adds the
// constraint of every connected component of the LP solution's support that is not the whole
// graph, at every node and at every integer solution CBC finds. CBC starts from the heuristic's
// tour as its incumbent. CBC can still accept an integer point with subtours without asking the
// generator; then those subtours' constraints become rows and CBC runs again (reruns()). Kept as
// the bake-off's contender (docs/results.md) against "exact" (our own dual simplex and
// branch-and-cut): docs/results.md.

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp {

struct CbcCutOptions {
  /// Seconds before giving up with optimal = false and the incumbent tour; 0 = no limit.
  double time_limit = 0;
};

class CbcCutSolver final : public TspSolver {
 public:
  explicit CbcCutSolver(CbcCutOptions options = {}) : options_(options) {}
  TspSolution solve(const SegmentTsp& problem) override;
  /// Reads "time-limit"; rejects unknown keys.
  static const Params<CbcCutOptions>& params();
  static CbcCutOptions read_options(const OptionMap& options);
  /// Times CBC returned an integer point with subtours (its constraints were then added as rows
  /// and CBC run again); for the bake-off's record.
  long long reruns() const { return reruns_; }

 private:
  CbcCutOptions options_;
  long long reruns_ = 0;
};

}  // namespace hullinspect::tsp
