#pragma once
// "heuristic": nearest-neighbour construction, 2-opt with segment flips and Or-opt to a local
// optimum, then iterated local search with double-bridge kicks. No optimality claim (except the
// trivial g ≤ 1). Deterministic for a given seed.

#include <cstdint>
#include <memory>
#include <vector>

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp {

namespace detail {
class LocalSearch;
class EndCosts;
}  // namespace detail

struct HeuristicOptions {
  /// Double-bridge kicks, each followed by a local search (0 = plain local search).
  int kicks = 50;
  /// Seed of the kicks' random stream.
  int seed = 1;
};

class HeuristicSolver final : public TspSolver {
 public:
  explicit HeuristicSolver(HeuristicOptions options = {});
  ~HeuristicSolver() override;
  TspSolution solve(const SegmentTsp& problem) override;
  /// Reads "kicks", "seed"; rejects unknown keys.
  static const Params<HeuristicOptions>& params();
  static HeuristicOptions read_options(const OptionMap& options);

 private:
  HeuristicOptions options_;
  std::unique_ptr<detail::EndCosts> costs_;
  std::unique_ptr<detail::LocalSearch> search_;
  std::vector<int> entries_;
};

}  // namespace hullinspect::tsp
