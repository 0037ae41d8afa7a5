#include "dfj_program.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "end_costs.hpp"
#include "hullinspect/core/errors.hpp"

namespace hullinspect::tsp::detail {

PaperGraph::PaperGraph(const SegmentTsp& p)
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

double PaperGraph::cost(int i, int j) const {
  if (i == artificial() || j == artificial()) return 0.0;
  return node_distance(*problem, at[static_cast<std::size_t>(i)], at[static_cast<std::size_t>(j)]);
}

bool PaperGraph::forced(int i, int j) const {
  if (i < j) std::swap(i, j);
  if (i == artificial()) return j == 0;
  return j >= 1 && (j % 2) == 1 && i == j + 1;
}

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

int components(const PaperGraph& graph, const double* x, std::vector<int>& label,
               double threshold) {
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
        if (x[column(std::max(i, j), std::min(i, j))] > threshold) {
          label[static_cast<std::size_t>(j)] = count;
          stack.push_back(j);
        }
      }
    }
    ++count;
  }
  return count;
}

std::vector<int> tour_entries(const PaperGraph& graph, const double* x, const char* solver) {
  const int n = graph.nodes;
  auto neighbour_except = [&](int i, int avoid) {
    for (int j = 0; j < n; ++j) {
      if (j != i && j != avoid && x[column(std::max(i, j), std::min(i, j))] > 0.5) return j;
    }
    throw LogicError(std::string(solver) + ": a node of the tour has fewer than two edges");
  };
  std::vector<int> entries;
  int at = neighbour_except(0, graph.artificial());
  while (at != graph.artificial()) {
    if (static_cast<int>(entries.size()) >= graph.g) {
      throw LogicError(std::string(solver) + ": the tour does not close at the artificial node");
    }
    const int l = (at - 1) / 2;
    const bool entered_second = at % 2 == 0;
    entries.push_back(2 * l + (entered_second ? 1 : 0));
    const int other_end = entered_second ? at - 1 : at + 1;
    at = neighbour_except(other_end, at);
  }
  if (static_cast<int>(entries.size()) != graph.g) {
    throw LogicError(std::string(solver) + ": the tour misses segments");
  }
  return entries;
}

int subtour_columns(const PaperGraph& graph, const std::vector<int>& label, int component,
                    std::vector<int>& columns) {
  columns.clear();
  int size = 0;
  for (int i = 0; i < graph.nodes; ++i) {
    if (label[static_cast<std::size_t>(i)] != component) continue;
    ++size;
    for (int j = 0; j < i; ++j) {
      if (label[static_cast<std::size_t>(j)] == component) columns.push_back(column(i, j));
    }
  }
  return size;
}

void add_subtour_rows(const PaperGraph& graph, const std::vector<int>& label, int count,
                      OsiClpSolverInterface& program) {
  std::vector<int> columns;
  for (int c = 0; c < count; ++c) {
    const int size = subtour_columns(graph, label, c, columns);
    const std::vector<double> ones(columns.size(), 1.0);
    program.addRow(static_cast<int>(columns.size()), columns.data(), ones.data(),
                   -program.getInfinity(), size - 1.0);
  }
}

std::vector<double> tour_columns(const PaperGraph& graph, const std::vector<int>& entries) {
  std::vector<double> x(static_cast<std::size_t>(graph.columns()), 0.0);
  auto use = [&](int i, int j) {
    x[static_cast<std::size_t>(column(std::max(i, j), std::min(i, j)))] = 1.0;
  };
  use(graph.artificial(), 0);
  int at = 0;
  for (const int entry : entries) {
    const int l = entry >> 1;
    const bool second = (entry & 1) != 0;
    const int in = second ? 2 * l + 2 : 2 * l + 1;
    const int out = second ? 2 * l + 1 : 2 * l + 2;
    use(at, in);
    use(in, out);
    at = out;
  }
  use(at, graph.artificial());
  return x;
}

}  // namespace hullinspect::tsp::detail
