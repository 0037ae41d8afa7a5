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

const Params<ExactOptions>& ExactSolver::params() {
  static const Params<ExactOptions> params = [] {
    Params<ExactOptions> p("exact");
    p.number("time-limit", &ExactOptions::time_limit, 0.0, 1e9,
             "seconds before returning the best tour with optimal = false (0 = none)")
        .integer("dp-max-segments", &ExactOptions::dp_max_segments, 0,
                 detail::SegmentDp::kMaxSegments, "largest g solved by the dynamic program")
        .integer("kicks", &ExactOptions::kicks, 0, 1'000'000,
                 "local-search kicks for the first tour of branch-and-cut")
        .integer("max-segments", &ExactOptions::max_segments, 0, 1'000'000,
                 "above this g: the local search's tour and a lower bound, no proof (0 = no limit)")
        .number("work-budget", &ExactOptions::work_budget, 0.0, 1e9,
                "LP work (10^6 units of rows^2 per pivot, ~2 ms each) before returning the best "
                "tour and a bound, no proof (0 = none)");
    return p;
  }();
  return params;
}

ExactOptions ExactSolver::read_options(const OptionMap& options) {
  return params().read(options);
}

TspSolution ExactSolver::solve(const SegmentTsp& problem) {
  const auto started = std::chrono::steady_clock::now();
  const int g = static_cast<int>(problem.segments.size());
  if (g == 0) return detail::make_solution(problem, {}, true, started);
  costs_->assign(problem);
  if (g <= std::max(options_.dp_max_segments, 1)) {
    dp_->solve(*costs_, entries_);
    return detail::make_solution(*costs_, entries_, true, started);
  }
  long long length = search_->run(*costs_, options_.kicks, kSearchSeed, entries_);
  const long long simple_bound = detail::simple_lower_bound(*costs_);
  auto unproven = [&](long long bound, bool fallback) {
    TspSolution s = detail::make_solution(*costs_, entries_, bound >= length, started);
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
  if (stats.optimal) return detail::make_solution(*costs_, entries_, true, started);
  // Stopped by the time limit or the work budget, or (a defect, counted as a fallback) by numerical
  // trouble: the best tour found, with the better of the two bounds.
  return unproven(std::max(simple_bound, stats.root_bound), stats.gave_up);
}

}  // namespace hullinspect::tsp
