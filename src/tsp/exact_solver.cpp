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

const Params<ExactOptions>& ExactSolver::params() {
  static const Params<ExactOptions> params = [] {
    Params<ExactOptions> p("exact");
    p.number("time-limit", &ExactOptions::time_limit, 0.0, 1e9,
             "seconds before returning the best tour with optimal = false (0 = none)")
        .integer("dp-max-segments", &ExactOptions::dp_max_segments, 0,
                 detail::SegmentDp::kMaxSegments, "largest g solved by the dynamic program")
        .integer("kicks", &ExactOptions::kicks, 0, 1'000'000,
                 "local-search kicks for the first tour of branch-and-cut");
    return p;
  }();
  return params;
}

ExactOptions ExactSolver::read_options(const OptionMap& options) { return params().read(options); }

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
