#pragma once
// Internal to the CBC-based solvers (dfj-iterative, cbc-cut): the paper's integer program for the
// segment TSP (Section IV-A, eqs. 6–12) over the complete undirected graph on nodes 0 (UAV),
// 2l+1 / 2l+2 (first / second end of segment l) and 2g+1 (artificial; distance 0 to every segment
// end, its edge to 0 forced), with the segment edges forced and degree 2 everywhere — everything
// but the subtour constraints (8), which each solver adds its own way.

#include <OsiClpSolverInterface.hpp>

#include <vector>

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp::detail {

/// Column of e_{i,j}, i > j, in the paper's numbering.
inline int column(int i, int j) {
  return i * (i - 1) / 2 + j;
}

struct PaperGraph {
  int g = 0;
  int nodes = 0;
  std::vector<grid::Cell> at;
  const SegmentTsp* problem = nullptr;

  explicit PaperGraph(const SegmentTsp& p);
  int artificial() const { return 2 * g + 1; }
  int columns() const { return nodes * (nodes - 1) / 2; }
  /// d_{i,j}: the problem's distance, 0 to the artificial node (eq. 11; its forced edge to 0
  /// costs 0 too).
  double cost(int i, int j) const;
  /// Eqs. 9 and 10.
  bool forced(int i, int j) const;
};

/// Eqs. 6, 7, 9, 10, 12: the program without any subtour constraint, all columns integer.
void build_program(const PaperGraph& graph, OsiClpSolverInterface& solver);

/// Labels the connected components of the edges with x > threshold; returns how many there are.
int components(const PaperGraph& graph, const double* x, std::vector<int>& label,
               double threshold = 0.5);

/// Eq. 8 for component `component` S of `label`: the columns of the edges inside S into
/// `columns` (cleared first); returns |S|, so the constraint is Σ x(columns) ≤ |S| − 1.
int subtour_columns(const PaperGraph& graph, const std::vector<int>& label, int component,
                    std::vector<int>& columns);

/// Adds eq. 8 of every component of `label` (there are `count`) as a row of `program`.
void add_subtour_rows(const PaperGraph& graph, const std::vector<int>& label, int count,
                      OsiClpSolverInterface& program);

/// The visiting order (entry ends, see end_costs.hpp) of a single tour x, dropping the artificial
/// node; a LogicError naming `solver` when x is not one tour through every segment.
std::vector<int> tour_entries(const PaperGraph& graph, const double* x, const char* solver);

/// The 0/1 column values of the tour that visits `entries` in order (the inverse of
/// tour_entries).
std::vector<double> tour_columns(const PaperGraph& graph, const std::vector<int>& entries);

}  // namespace hullinspect::tsp::detail
