#include <fmt/format.h>

#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/tsp/dfj_iterative_solver.hpp"
#include "hullinspect/tsp/exact_solver.hpp"
#include "hullinspect/tsp/heuristic_solver.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp {

namespace {

std::unique_ptr<TspSolver> make_exact(const OptionMap& options) {
  return std::make_unique<ExactSolver>(ExactSolver::read_options(options));
}
std::unique_ptr<TspSolver> make_dfj_iterative(const OptionMap& options) {
  return std::make_unique<DfjIterativeSolver>(DfjIterativeSolver::read_options(options));
}
std::unique_ptr<TspSolver> make_heuristic(const OptionMap& options) {
  return std::make_unique<HeuristicSolver>(HeuristicSolver::read_options(options));
}

std::string text(double value) {
  return fmt::format("{}", value);
}

const std::vector<TspSolverInfo>& registry() {
  static const ExactOptions exact;
  static const DfjIterativeOptions dfj;
  static const HeuristicOptions heuristic;
  static const std::vector<TspSolverInfo> entries = {
      {"exact",
       "proves optimality: dynamic program for small g, branch-and-cut above",
       {{"time_limit", text(exact.time_limit),
         "seconds before returning the best tour with optimal = false (0 = none)"},
        {"dp_max_segments", text(exact.dp_max_segments),
         "largest g solved by the dynamic program (0-16)"},
        {"kicks", text(exact.kicks), "local-search kicks for the first tour of branch-and-cut"},
        {"max_segments", text(exact.max_segments),
         "above this g: the local search's tour and a lower bound, no proof (0 = no limit)"},
        {"work_budget", text(exact.work_budget),
         "LP work (10^6 units of rows^2 per pivot, ~2 ms each) before returning the best tour "
         "and a bound, no proof (0 = none)"}},
       &make_exact},
      {"dfj-iterative",
       "the paper's reference: DFJ integer program on CBC, subtour constraints added iteratively",
       {{"time_limit", text(dfj.time_limit),
         "seconds before returning the heuristic's tour with optimal = false (0 = none)"}},
       &make_dfj_iterative},
      {"heuristic",
       "nearest neighbour + 2-opt/Or-opt with segment flips + double-bridge kicks; no proof",
       {{"kicks", text(heuristic.kicks), "double-bridge kicks, each followed by local search"},
        {"seed", text(heuristic.seed), "seed of the kicks"}},
       &make_heuristic},
  };
  return entries;
}

}  // namespace

std::span<const TspSolverInfo> tsp_solver_registry() {
  return registry();
}

std::unique_ptr<TspSolver> make_tsp_solver(std::string_view name, const OptionMap& options) {
  std::string names;
  for (const auto& info : registry()) {
    if (info.name == name) return info.make(options);
    names += (names.empty() ? "" : ", ") + info.name;
  }
  throw ParameterError("tsp_solver", fmt::format("unknown TSP solver '{}' (known: {})", name,
                                                 names.empty() ? "none" : names));
}

}  // namespace hullinspect::tsp
