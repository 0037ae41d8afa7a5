#include "hullinspect/tsp/dfj_iterative_solver.hpp"

#include <CbcEventHandler.hpp>
#include <CbcModel.hpp>
#include <CoinPackedVector.hpp>
#include <OsiClpSolverInterface.hpp>

#include <chrono>
#include <numeric>
#include <vector>

#include "end_costs.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/tsp/heuristic_solver.hpp"

namespace hullinspect::tsp {

namespace {

/// Column of e_{i,j}, i > j, in the paper's numbering.
int column(int i, int j) {
  return i * (i - 1) / 2 + j;
}

/// The paper's nodes: 0 = UAV, 2l+1 / 2l+2 = first / second end of segment l, 2g+1 = artificial.
struct PaperGraph {
  int g = 0;
  int nodes = 0;
  std::vector<grid::Cell> at;
  const SegmentTsp* problem = nullptr;

  explicit PaperGraph(const SegmentTsp& p)
      : g(static_cast<int>(p.segments.size())),
        nodes(2 * g + 2),
        at(static_cast<std::size_t>(nodes)),
        problem(&p) {
    at[0] = p.start;
    for (int l = 0; l < g; ++l) {
      at[static_cast<std::size_t>(2 * l + 1)] = p.segments[static_cast<std::size_t>(l)].first;
      at[static_cast<std::size_t>(2 * l + 2)] = p.segments[static_cast<std::size_t>(l)].second;
    }
  }
  int artificial() const { return 2 * g + 1; }
  /// d_{i,j}: the problem's distance, 0 to the artificial node (eq. 11; its forced edge to 0
  /// costs 0 too).
  double cost(int i, int j) const {
    if (i == artificial() || j == artificial()) return 0.0;
    return node_distance(*problem, at[static_cast<std::size_t>(i)],
                         at[static_cast<std::size_t>(j)]);
  }
  /// Eqs. 9 and 10.
  bool forced(int i, int j) const {
    if (i < j) std::swap(i, j);
    if (i == artificial()) return j == 0;
    return j >= 1 && (j % 2) == 1 && i == j + 1;
  }
};

/// Eqs. 6, 7, 9, 10, 12: the program without any subtour constraint.
void build_program(const PaperGraph& graph, OsiClpSolverInterface& solver) {
  const int n = graph.nodes;
  const int columns = n * (n - 1) / 2;
  std::vector<CoinBigIndex> starts(static_cast<std::size_t>(columns) + 1);
  std::vector<int> rows(2 * static_cast<std::size_t>(columns));
  std::vector<double> objective(static_cast<std::size_t>(columns));
  std::vector<double> lower(static_cast<std::size_t>(columns));
  for (int i = 1; i < n; ++i) {
    for (int j = 0; j < i; ++j) {
      const auto c = static_cast<std::size_t>(column(i, j));
      starts[c] = static_cast<CoinBigIndex>(2 * c);
      rows[2 * c] = i;
      rows[2 * c + 1] = j;
      objective[c] = graph.cost(i, j);
      lower[c] = graph.forced(i, j) ? 1.0 : 0.0;
    }
  }
  starts[static_cast<std::size_t>(columns)] = 2 * columns;
  const std::vector<double> ones(2 * static_cast<std::size_t>(columns), 1.0);
  const std::vector<double> upper(static_cast<std::size_t>(columns), 1.0);
  const std::vector<double> degree(static_cast<std::size_t>(n), 2.0);
  solver.messageHandler()->setLogLevel(0);
  solver.getModelPtr()->setLogLevel(0);
  solver.setHintParam(OsiDoReducePrint, true, OsiHintTry);
  solver.loadProblem(columns, n, starts.data(), rows.data(), ones.data(), lower.data(),
                     upper.data(), objective.data(), degree.data(), degree.data());
  std::vector<int> all(static_cast<std::size_t>(columns));
  std::iota(all.begin(), all.end(), 0);
  solver.setInteger(all.data(), columns);
}

/// Labels the connected components of the chosen edges; returns how many there are.
int components(const PaperGraph& graph, const double* x, std::vector<int>& label) {
  const int n = graph.nodes;
  label.assign(static_cast<std::size_t>(n), -1);
  int count = 0;
  std::vector<int> stack;
  for (int root = 0; root < n; ++root) {
    if (label[static_cast<std::size_t>(root)] >= 0) continue;
    label[static_cast<std::size_t>(root)] = count;
    stack.assign(1, root);
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (int j = 0; j < n; ++j) {
        if (j == i || label[static_cast<std::size_t>(j)] >= 0) continue;
        if (x[column(std::max(i, j), std::min(i, j))] > 0.5) {
          label[static_cast<std::size_t>(j)] = count;
          stack.push_back(j);
        }
      }
    }
    ++count;
  }
  return count;
}

/// The visiting order of a single tour, dropping the artificial node (entry ends, see
/// end_costs.hpp).
std::vector<int> tour_entries(const PaperGraph& graph, const double* x) {
  const int n = graph.nodes;
  auto neighbour_except = [&](int i, int avoid) {
    for (int j = 0; j < n; ++j) {
      if (j != i && j != avoid && x[column(std::max(i, j), std::min(i, j))] > 0.5) return j;
    }
    throw LogicError("dfj-iterative: a node of the tour has fewer than two edges");
  };
  std::vector<int> entries;
  int at = neighbour_except(0, graph.artificial());
  while (at != graph.artificial()) {
    if (static_cast<int>(entries.size()) >= graph.g) {
      throw LogicError("dfj-iterative: the tour does not close at the artificial node");
    }
    const int l = (at - 1) / 2;
    const bool entered_second = at % 2 == 0;
    entries.push_back(2 * l + (entered_second ? 1 : 0));
    const int other_end = entered_second ? at - 1 : at + 1;
    at = neighbour_except(other_end, at);
  }
  if (static_cast<int>(entries.size()) != graph.g) {
    throw LogicError("dfj-iterative: the tour misses segments");
  }
  return entries;
}

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
      return detail::make_solution(problem, tour_entries(graph, x), true, started);
    }
    // Eq. 8 for every subtour of this answer.
    for (int c = 0; c < count; ++c) {
      CoinPackedVector row;
      int size = 0;
      for (int i = 0; i < graph.nodes; ++i) {
        if (label[static_cast<std::size_t>(i)] != c) continue;
        ++size;
        for (int j = 0; j < i; ++j) {
          if (label[static_cast<std::size_t>(j)] == c) row.insert(column(i, j), 1.0);
        }
      }
      program.addRow(row, -program.getInfinity(), size - 1.0);
    }
  }
  // Time limit reached: the heuristic's tour, without an optimality claim.
  if (!limited) fallback = HeuristicSolver().solve(problem);
  fallback.optimal = false;
  fallback.seconds = detail::seconds_since(started);
  return fallback;
}

}  // namespace hullinspect::tsp
