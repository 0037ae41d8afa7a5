#include "hullinspect/core/errors.hpp"
#include "hullinspect/tsp/cbc_cut_solver.hpp"
#include "hullinspect/tsp/dfj_iterative_solver.hpp"
#include "hullinspect/tsp/exact_solver.hpp"
#include "hullinspect/tsp/heuristic_solver.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp {

namespace {

void add_builtins(TspSolverRegistry& r) {
  r.add_builtin(make_entry<TspSolver, ExactOptions>(
      "exact", "proves optimality: dynamic program for small g, branch-and-cut above",
      ExactSolver::params(),
      [](const ExactOptions& o) { return std::make_unique<ExactSolver>(o); }));
  r.add_builtin(make_entry<TspSolver, DfjIterativeOptions>(
      "dfj-iterative",
      "the paper's reference: DFJ integer program on CBC, subtour constraints added iteratively",
      DfjIterativeSolver::params(),
      [](const DfjIterativeOptions& o) { return std::make_unique<DfjIterativeSolver>(o); }));
  r.add_builtin(make_entry<TspSolver, CbcCutOptions>(
      "cbc-cut",
      "the same integer program solved once by CBC's branch-and-cut, subtour constraints as lazy "
      "cuts, seeded with the heuristic's tour",
      CbcCutSolver::params(),
      [](const CbcCutOptions& o) { return std::make_unique<CbcCutSolver>(o); }));
  r.add_builtin(make_entry<TspSolver, HeuristicOptions>(
      "heuristic",
      "nearest neighbour + 2-opt/Or-opt with segment flips + double-bridge kicks; no proof",
      HeuristicSolver::params(),
      [](const HeuristicOptions& o) { return std::make_unique<HeuristicSolver>(o); }));
}

}  // namespace

TspSolverRegistry& tsp_solvers() {
  static TspSolverRegistry registry("TSP solver", "tsp-solver", &add_builtins);
  return registry;
}

std::vector<TspSolverInfo> tsp_solver_registry() {
  return tsp_solvers().entries();
}

std::unique_ptr<TspSolver> make_tsp_solver(std::string_view name, const OptionMap& options) {
  return tsp_solvers().make(name, options);
}

OptionMap resolve_tsp_solver_options(std::string_view name, const OptionMap& options) {
  return tsp_solvers().resolve(name, options);
}

}  // namespace hullinspect::tsp
