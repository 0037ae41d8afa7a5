#include "hullinspect/tsp/heuristic_solver.hpp"

#include <algorithm>
#include <chrono>

#include "end_costs.hpp"
#include "local_search.hpp"

namespace hullinspect::tsp {

HeuristicSolver::HeuristicSolver(HeuristicOptions options)
    : options_(options),
      costs_(std::make_unique<detail::EndCosts>()),
      search_(std::make_unique<detail::LocalSearch>()) {}

HeuristicSolver::~HeuristicSolver() = default;

const Params<HeuristicOptions>& HeuristicSolver::params() {
  static const Params<HeuristicOptions> params = [] {
    Params<HeuristicOptions> p("heuristic");
    p.integer("kicks", &HeuristicOptions::kicks, 0, 1'000'000,
              "double-bridge kicks, each followed by local search")
        .integer("seed", &HeuristicOptions::seed, 0, 2'147'483'647, "seed of the kicks");
    return p;
  }();
  return params;
}

HeuristicOptions HeuristicSolver::read_options(const OptionMap& options) {
  return params().read(options);
}

TspSolution HeuristicSolver::solve(const SegmentTsp& problem) {
  const auto started = std::chrono::steady_clock::now();
  const int g = static_cast<int>(problem.segments.size());
  if (g == 0) return detail::make_solution(problem, {}, true, started);
  costs_->assign(problem);
  search_->run(*costs_, options_.kicks, static_cast<std::uint64_t>(options_.seed), entries_);
  // With one segment the local search tries both directions, so the answer is optimal.
  TspSolution solution = detail::make_solution(*costs_, entries_, g == 1, started);
  if (!solution.optimal) {
    solution.lower_bound = std::min(solution.length, detail::simple_lower_bound(*costs_));
  }
  return solution;
}

}  // namespace hullinspect::tsp
