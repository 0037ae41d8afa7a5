#include "hullinspect/tsp/cbc_cut_solver.hpp"

#include <CbcModel.hpp>
// CbcCutGenerator.hpp uses CbcModel.hpp's declarations without including them.
#include <CbcCutGenerator.hpp>
#include <CglCutGenerator.hpp>
#include <OsiClpSolverInterface.hpp>
#include <OsiCuts.hpp>
#include <OsiRowCut.hpp>

#include <chrono>
#include <vector>

#include "dfj_program.hpp"
#include "end_costs.hpp"
#include "hullinspect/tsp/heuristic_solver.hpp"

namespace hullinspect::tsp {

namespace {

using detail::PaperGraph;

/// Separates eq. 8 on the support graph of x: a connected component S of the edges with x > 0
/// that is not the whole graph has x(E(S)) = |S| by the degree equations, one more than (8)
/// allows. At an integer solution the components are the subtours, so every integer point CBC
/// accepts is one tour.
class SubtourCuts final : public CglCutGenerator {
 public:
  explicit SubtourCuts(const PaperGraph& graph) : graph_(&graph) {}
  void generateCuts(const OsiSolverInterface& solver, OsiCuts& cuts,
                    const CglTreeInfo /*info*/) override {
    const int count = detail::components(*graph_, solver.getColSolution(), label_, 1e-6);
    if (count == 1) return;
    std::vector<double> ones;
    for (int c = 0; c < count; ++c) {
      const int size = detail::subtour_columns(*graph_, label_, c, index_);
      ones.assign(index_.size(), 1.0);
      OsiRowCut cut;
      cut.setRow(static_cast<int>(index_.size()), index_.data(), ones.data());
      cut.setLb(-solver.getInfinity());
      cut.setUb(size - 1.0);
      cut.setGloballyValid(true);
      cuts.insert(cut);
    }
  }
  CglCutGenerator* clone() const override { return new SubtourCuts(*this); }

 private:
  const PaperGraph* graph_;
  std::vector<int> label_;
  std::vector<int> index_;
};

}  // namespace

const Params<CbcCutOptions>& CbcCutSolver::params() {
  static const Params<CbcCutOptions> params = [] {
    Params<CbcCutOptions> p("cbc-cut");
    p.number("time-limit", &CbcCutOptions::time_limit, 0.0, 1e9,
             "seconds before returning the incumbent tour with optimal = false (0 = none)");
    return p;
  }();
  return params;
}

CbcCutOptions CbcCutSolver::read_options(const OptionMap& options) {
  return params().read(options);
}

TspSolution CbcCutSolver::solve(const SegmentTsp& problem) {
  const auto started = std::chrono::steady_clock::now();
  if (problem.segments.empty()) return detail::make_solution(problem, {}, true, started);
  // The heuristic's tour is CBC's first incumbent (docs/tsp.md: "seeded with the heuristic's tour"), and
  // the answer if the time limit stops CBC first.
  TspSolution incumbent = HeuristicSolver().solve(problem);
  std::vector<int> entries;
  for (const Visit v : incumbent.order) entries.push_back(detail::entry_end(v));
  const PaperGraph graph(problem);
  OsiClpSolverInterface program;
  detail::build_program(graph, program);
  const std::vector<double> start = detail::tour_columns(graph, entries);
  double start_cost = 0;
  const double* objective = program.getObjCoefficients();
  for (std::size_t c = 0; c < start.size(); ++c) start_cost += objective[c] * start[c];

  auto unproven = [&] {
    incumbent.optimal = false;
    incumbent.seconds = detail::seconds_since(started);
    return incumbent;
  };
  SubtourCuts subtours(graph);
  std::vector<int> label;
  while (true) {
    const double remaining = options_.time_limit - detail::seconds_since(started);
    if (options_.time_limit > 0 && remaining <= 0) return unproven();
    CbcModel model(program);
    model.setLogLevel(0);
    model.messageHandler()->setLogLevel(0);
    model.solver()->messageHandler()->setLogLevel(0);
    // At every node (howOften 1, also in the subtree) and at every solution CBC finds.
    model.addCutGenerator(&subtours, 1, "subtour", true, true, false, 1);
    model.cutGenerator(model.numberCutGenerators() - 1)->setMustCallAgain(true);
    // Strong branching takes an integer point of a trial branch without calling the generators.
    model.setNumberStrong(0);
    model.setNumberBeforeTrust(0);
    model.setBestSolution(start.data(), static_cast<int>(start.size()), start_cost, false);
    if (options_.time_limit > 0) {
      model.setUseElapsedTime(true);
      model.setMaximumSeconds(remaining);
    }
    model.branchAndBound();
    const double* x = model.bestSolution();
    if (x == nullptr || !model.isProvenOptimal()) return unproven();
    const int count = detail::components(graph, x, label);
    if (count == 1) {
      return detail::make_solution(problem, detail::tour_entries(graph, x, "cbc-cut"), true,
                                   started);
    }
    // CBC can still accept an integer point with subtours without asking the generator (seen on
    // g = 3: the root's heuristics): its constraints become rows of the program and CBC runs
    // again. The answer is optimal for a relaxation of the TSP and one tour, so optimal.
    detail::add_subtour_rows(graph, label, count, program);
    ++reruns_;
  }
}

}  // namespace hullinspect::tsp
