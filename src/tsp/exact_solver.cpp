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
  o.max_segments = reader.get_int("max_segments", o.max_segments, 0, 1'000'000);
  o.work_budget = reader.get_double("work_budget", o.work_budget, 0.0, 1e9);
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
  const long long simple_bound = detail::simple_lower_bound(*costs_);
  auto unproven = [&](long long bound, bool fallback) {
    TspSolution s = detail::make_solution(problem, entries_, bound >= length, started);
    s.lower_bound = std::min(bound, s.length);
    s.fallback = fallback;
    return s;
  };
  if (simple_bound >= length) return unproven(simple_bound, false);
  if (options_.max_segments > 0 && g > options_.max_segments) return unproven(simple_bound, false);
  auto deadline = std::chrono::steady_clock::time_point::max();
  if (options_.time_limit > 0) {
    deadline = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(options_.time_limit));
  }
  const auto stats =
      branch_and_cut_->solve(*costs_, entries_, length, deadline, options_.work_budget * 1e6);
  if (stats.optimal) return detail::make_solution(problem, entries_, true, started);
  // Stopped by the time limit or the work budget, or (a defect, counted as a fallback) by numerical
  // trouble: the best tour found, with the better of the two bounds.
  return unproven(std::max(simple_bound, stats.root_bound), stats.gave_up);
}

}  // namespace hullinspect::tsp
