#pragma once
// Internal: maximum flow / minimum cut on a small undirected graph with real capacities, for the
// branch-and-cut's separation routines. Edmonds–Karp with an early stop: the routines only need
// to know whether a cut below some threshold exists, and which one.

#include <vector>

namespace hullinspect::tsp::detail {

class FlowGraph {
 public:
  /// Starts a graph on nodes 0 … n−1 with no edges.
  void reset(int n);
  /// Adds the undirected edge {u, v} with capacity c (both directions).
  void add_edge(int u, int v, double capacity);
  /// Freezes the edges; call after the last add_edge().
  void build();
  /// Flow from source to sink, stopping once it reaches `enough`. If the result is below `enough`,
  /// source_side() tells the source side of a minimum cut.
  double max_flow(int source, int sink, double enough);
  bool source_side(int v) const { return reached_[static_cast<std::size_t>(v)] >= 0; }
  int nodes() const { return n_; }

 private:
  int n_ = 0;
  std::vector<int> from_, to_;
  std::vector<double> capacity_;
  std::vector<int> start_, head_, reverse_;  // arcs in CSR order
  std::vector<double> arc_capacity_, residual_;
  std::vector<int> reached_, queue_;  // arc that reached each node (-1: not reached)
};

}  // namespace hullinspect::tsp::detail
