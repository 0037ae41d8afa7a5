#include "hullinspect/tsp/exact_solver.hpp"

#include <algorithm>
#include <chrono>

#include "branch_and_cut.hpp"
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
  const auto stats = branch_and_cut_->solve(*costs_, entries_, length, deadline);
  return detail::make_solution(problem, entries_, stats.optimal, started);
}

}  // namespace hullinspect::tsp
