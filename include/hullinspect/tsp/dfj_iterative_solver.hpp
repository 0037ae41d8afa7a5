#pragma once
// "dfj-iterative": the paper's reference method (Section IV-A, eqs. 6–12) on CBC. The integer
// program over the complete undirected graph on nodes 0 (UAV), 2l+1 / 2l+2 (ends of segment l) and
// 2g+1 (artificial; distance 0 to every segment end, edge (2g+1, 0) forced) with the segment edges
// forced and degree 2 everywhere is solved without subtour constraints (8); the constraint of every
// subtour in the answer is added and the program solved again, until the answer is one tour.
// Slow by design: it is kept to check and to measure the other solvers against.

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp {

struct DfjIterativeOptions {
  /// Seconds before giving up with optimal = false and the heuristic's tour; 0 = no limit.
  double time_limit = 0;
};

class DfjIterativeSolver final : public TspSolver {
 public:
  explicit DfjIterativeSolver(DfjIterativeOptions options = {}) : options_(options) {}
  TspSolution solve(const SegmentTsp& problem) override;
  /// Reads "time_limit"; rejects unknown keys.
  static const Params<DfjIterativeOptions>& params();
  static DfjIterativeOptions read_options(const OptionMap& options);

 private:
  DfjIterativeOptions options_;
};

}  // namespace hullinspect::tsp
