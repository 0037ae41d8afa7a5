#include "hullinspect/tsp/exact_solver.hpp"

#include <algorithm>
#include <chrono>

#include "branch_and_cut.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/tsp/dfj_iterative_solver.hpp"
#include "end_costs.hpp"
#include "local_search.hpp"
#include "segment_dp.hpp"

namespace hullinspect::tsp {

namespace {
constexpr std::uint64_t kSearchSeed = 1;
}

ExactSolver::ExactSolver(ExactOptions options)
    : options_(options),
      costs_(std::make_unique<detail::EndCosts>()),
      dp_(std::make_unique<detail::SegmentDp>()),
      search_(std::make_unique<detail::LocalSearch>()),
      branch_and_cut_(std::make_unique<detail::BranchAndCut>()) {}

ExactSolver::~ExactSolver() = default;

ExactOptions ExactSolver::read_options(const OptionMap& options) {
  OptionReader reader(options, "exact");
  ExactOptions o;
  o.time_limit = reader.get_double("time_limit", o.time_limit, 0.0, 1e9);
  o.dp_max_segments =
      reader.get_int("dp_max_segments", o.dp_max_segments, 0, detail::SegmentDp::kMaxSegments);
  o.kicks = reader.get_int("kicks", o.kicks, 0, 1'000'000);
  reader.reject_unknown();
  return o;
}

TspSolution ExactSolver::solve(const SegmentTsp& problem) {
  const auto started = std::chrono::steady_clock::now();
  const int g = static_cast<int>(problem.segments.size());
  if (g == 0) return detail::make_solution(problem, {}, true, started);
  costs_->assign(problem);
  if (g <= std::max(options_.dp_max_segments, 1)) {
    dp_->solve(*costs_, entries_);
    return detail::make_solution(problem, entries_, true, started);
  }
  long long length = search_->run(*costs_, options_.kicks, kSearchSeed, entries_);
  auto deadline = std::chrono::steady_clock::time_point::max();
  if (options_.time_limit > 0) {
    deadline = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(options_.time_limit));
  }
  try {
    const auto stats = branch_and_cut_->solve(*costs_, entries_, length, deadline);
    return detail::make_solution(problem, entries_, stats.optimal, started);
  } catch (const LogicError&) {
    // Rarely the branch-and-cut reaches an integral LP point that its separation does not cut off
    // ("no fractional edge to branch on"; an open defect, see docs/tsp.md). The CBC-based DFJ
    // reference still proves optimality, only more slowly, so missions never stop on it.
    ++reference_fallbacks_;
    DfjIterativeOptions reference_options;
    if (options_.time_limit > 0) {
      reference_options.time_limit =
          std::max(1e-3, options_.time_limit - detail::seconds_since(started));
    }
    TspSolution solution = DfjIterativeSolver(reference_options).solve(problem);
    solution.seconds = detail::seconds_since(started);
    return solution;
  }
}

}  // namespace hullinspect::tsp
