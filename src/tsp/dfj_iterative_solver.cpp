#include "hullinspect/tsp/dfj_iterative_solver.hpp"

#include <CbcEventHandler.hpp>
#include <CbcModel.hpp>
#include <OsiClpSolverInterface.hpp>

#include <chrono>
#include <numeric>
#include <vector>

#include "dfj_program.hpp"
#include "end_costs.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/tsp/heuristic_solver.hpp"

namespace hullinspect::tsp {

using detail::build_program;
using detail::components;
using detail::PaperGraph;

namespace {

/// Stops CBC at the next node once the wall-clock deadline has passed: CBC's own
/// setMaximumSeconds is checked less often, which let a solve run to 2.7× its limit.
class DeadlineHandler final : public CbcEventHandler {
 public:
  explicit DeadlineHandler(std::chrono::steady_clock::time_point deadline) : deadline_(deadline) {}
  CbcAction event(CbcEvent) override {
    return std::chrono::steady_clock::now() >= deadline_ ? stop : noAction;
  }
  CbcEventHandler* clone() const override { return new DeadlineHandler(*this); }

 private:
  std::chrono::steady_clock::time_point deadline_;
};

}  // namespace

const Params<DfjIterativeOptions>& DfjIterativeSolver::params() {
  static const Params<DfjIterativeOptions> params = [] {
    Params<DfjIterativeOptions> p("dfj-iterative");
    p.number("time-limit", &DfjIterativeOptions::time_limit, 0.0, 1e9,
             "seconds before returning the heuristic's tour with optimal = false (0 = none)");
    return p;
  }();
  return params;
}

DfjIterativeOptions DfjIterativeSolver::read_options(const OptionMap& options) {
  return params().read(options);
}

TspSolution DfjIterativeSolver::solve(const SegmentTsp& problem) {
  const auto started = std::chrono::steady_clock::now();
  if (problem.segments.empty()) return detail::make_solution(problem, {}, true, started);
  const bool limited = options_.time_limit > 0;
  // With a time limit the answer on giving up is the heuristic's tour; it is computed first (a few
  // milliseconds) so that giving up costs nothing after the deadline.
  TspSolution fallback;
  if (limited) fallback = HeuristicSolver().solve(problem);
  const auto deadline =
      started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(limited ? options_.time_limit : 0.0));
  const PaperGraph graph(problem);
  OsiClpSolverInterface program;
  build_program(graph, program);
  std::vector<int> label;
  while (true) {
    double remaining = 0;
    if (limited) {
      remaining = options_.time_limit - detail::seconds_since(started);
      if (remaining <= 0) break;
    }
    CbcModel model(program);
    model.setLogLevel(0);
    model.messageHandler()->setLogLevel(0);
    model.solver()->messageHandler()->setLogLevel(0);
    if (limited) {
      model.setUseElapsedTime(true);  // wall-clock, like the limit of the other solvers
      model.setMaximumSeconds(remaining);
      // The LP solves (the root one is most of the time on large g) stop on their own clock.
      if (auto* clp = dynamic_cast<OsiClpSolverInterface*>(model.solver())) {
        clp->getModelPtr()->setMaximumWallSeconds(remaining);
      }
      DeadlineHandler handler(deadline);
      model.passInEventHandler(&handler);
    }
    model.branchAndBound();
    if (!model.isProvenOptimal() || model.bestSolution() == nullptr) break;
    if (limited && std::chrono::steady_clock::now() >= deadline) break;
    const double* x = model.bestSolution();
    const int count = components(graph, x, label);
    if (count == 1) {
      return detail::make_solution(problem, detail::tour_entries(graph, x, "dfj-iterative"), true,
                                   started);
    }
    // Eq. 8 for every subtour of this answer.
    detail::add_subtour_rows(graph, label, count, program);
  }
  // Time limit reached: the heuristic's tour, without an optimality claim.
  if (!limited) fallback = HeuristicSolver().solve(problem);
  fallback.optimal = false;
  fallback.seconds = detail::seconds_since(started);
  return fallback;
}

}  // namespace hullinspect::tsp
