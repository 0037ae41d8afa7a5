#pragma once
// Internal: exact branch-and-cut for the segment TSP on CLP, used by the "exact" solver for larger
// g.
//
// The LP is the paper's model with the forced edges substituted out: nodes are the 2g segment ends,
// the UAV S and the artificial node A; a variable per free edge (every pair of nodes except a
// segment's own two ends and S–A; A's edges cost 0). Every node has exactly one free edge
// (degree 2 minus its forced edge). Subtour elimination x(E(T)) ≤ |T| − 1 is needed only for sets
// T of whole segments (the S–A pair counts as one), so separation works on the graph contracted to
// g + 1 super-nodes: connected components first, then exact max-flow min-cuts between the S–A
// super-node and every segment. Cuts are added inside one LP that is warm-started throughout a
// depth-first branch-and-bound (x = 1 child first); nodes are pruned when ⌈LP bound⌉ cannot beat
// the incumbent (lengths are integers), and root reduced costs fix edges that cannot improve it.

#include <chrono>
#include <memory>
#include <set>
#include <vector>

#include "end_costs.hpp"

class OsiClpSolverInterface;

namespace hullinspect::tsp::detail {

struct BranchAndCutStats {
  bool optimal = false;      ///< search finished: the incumbent is optimal
  long long root_bound = 0;  ///< ⌈root LP bound⌉ (path length, segments included)
  int nodes = 0;
  int lp_solves = 0;
  int cuts = 0;
};

class BranchAndCut {
 public:
  BranchAndCut();
  ~BranchAndCut();
  BranchAndCut(const BranchAndCut&) = delete;
  BranchAndCut& operator=(const BranchAndCut&) = delete;

  /// `best`/`best_length`: a valid tour (entry ends) and its length on entry, the best tour found
  /// on return. Stops early (optimal = false) once `deadline` has passed. Requires g ≥ 2.
  BranchAndCutStats solve(const EndCosts& costs, std::vector<int>& best, long long& best_length,
                          std::chrono::steady_clock::time_point deadline);

 private:
  enum class NodeState { kPruned, kFractional, kIntegral };

  void build_lp();
  NodeState solve_node();
  void branch(int depth);
  void fix_by_reduced_cost();
  int separate();
  bool add_cut(std::vector<int>& supers);
  double max_flow(int source, int sink, double enough);
  void take_integral_tour();
  int super_of(int node) const { return node < 2 * g_ ? node >> 1 : g_; }

  const EndCosts* costs_ = nullptr;
  int g_ = 0;
  int nodes_ = 0;   // 2g + 2 LP nodes: ends, then S = 2g, A = 2g + 1
  int supers_ = 0;  // g + 1 super-nodes: segments, then {S, A} = g
  std::vector<int> edge_u_, edge_v_;
  std::vector<int> column_of_;  // nodes_ × nodes_ → column, -1 for none
  std::unique_ptr<OsiClpSolverInterface> lp_;
  std::set<std::vector<int>> known_cuts_;  // by sorted super-nodes of the side without {S, A}
  std::vector<int>* best_ = nullptr;
  long long* best_length_ = nullptr;
  std::chrono::steady_clock::time_point deadline_;
  bool stopped_ = false;  // deadline passed
  bool trouble_ = false;  // an LP ended neither optimal nor infeasible: no optimality claim
  BranchAndCutStats stats_;
  // Separation scratch, reused.
  std::vector<double> weight_, residual_;
  std::vector<int> label_, queue_, parent_, side_;
  std::vector<int> row_index_;
  std::vector<double> row_value_;
};

}  // namespace hullinspect::tsp::detail
