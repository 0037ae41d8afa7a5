#pragma once
// Internal: exact branch-and-cut for the segment TSP on its own small LP solver (dual_simplex.hpp),
// used by the "exact" solver for larger g.
//
// The LP is the paper's model with the forced edges substituted out: nodes are the 2g segment ends,
// the UAV S and the artificial node A; a variable per free edge (every pair of nodes except a
// segment's own two ends and S–A; A's edges cost 0). Every node has exactly one free edge (degree 2
// minus its forced edge), so the free edges form a perfect matching. Two families of cuts:
//  - subtour elimination x(E(T)) ≤ |T| − 1, needed only for sets T of whole segments (the S–A pair
//    counts as one), separated exactly on the graph contracted to g + 1 super-nodes: connected
//    components, then max-flow min-cuts between the S–A super-node and every segment;
//  - blossoms x(E(H)) + x(F) ≤ |H| + (|F| − 1) / 2 (H a node set, F an odd set of edges leaving H,
//    forced edges included), separated by the Padberg–Rao odd-cut method on the fractional edges
//    (Gomory–Hu tree by Gusfield's algorithm). They remove the half-integral odd cycles that make
//    the plain subtour LP weak on these instances.
// Separation escalates from cheap to expensive and stops at the first kind that finds cuts; at most
// max(10, g/2) blossoms per round, the most violated first; a node stops cutting after a round
// limit or when the bound stalls (tailing off) and is branched on; cuts that are not binding are
// dropped once there are more cuts than nodes (the LP's cost grows with the square of its rows).
// Column generation at the root: the LP starts from the local search's tour edges, every edge at S
// and A and each end's nearest ends, and is priced against all edges until no reduced cost is
// negative. Then edges whose reduced cost shows they cannot beat the incumbent are dropped for good
// and the others enter the LP, so the tree needs no pricing. Depth-first branch-and-bound on one
// warm-started LP, branching on an edge chosen by strong branching; a node is pruned when its LP
// bound (a Lagrangian bound from the duals, valid whatever the LP's numerical state) cannot beat
// the incumbent by 1 (lengths are integers). Deterministic: no randomness, no clocks except the
// deadline.

#include <chrono>
#include <memory>
#include <set>
#include <vector>

#include "dual_simplex.hpp"
#include "end_costs.hpp"
#include "max_flow.hpp"

namespace hullinspect::tsp::detail {

struct BranchAndCutStats {
  bool optimal = false;      ///< search finished: the incumbent is optimal
  bool gave_up = false;      ///< stopped by numerical trouble (not the deadline): no claim
  long long root_bound = 0;  ///< ⌈root LP bound⌉ (path length, segments included)
  int nodes = 0;
  int lp_solves = 0;
  int cuts = 0;
  int columns = 0;  ///< LP columns after the root (of 2g² + 2g free edges)
};

class BranchAndCut {
 public:
  BranchAndCut();
  ~BranchAndCut();
  BranchAndCut(const BranchAndCut&) = delete;
  BranchAndCut& operator=(const BranchAndCut&) = delete;

  /// `best`/`best_length`: a valid tour (entry ends) and its length on entry, the best tour found
  /// on return. Stops early (optimal = false) once `deadline` has passed. Requires g ≥ 2.
  /// Also stops once its LPs' work (DualSimplex::total_work) reaches `work_budget` (0 = no
  /// budget): a deterministic bound, unlike the deadline.
  BranchAndCutStats solve(const EndCosts& costs, std::vector<int>& best, long long& best_length,
                          std::chrono::steady_clock::time_point deadline, double work_budget = 0);

 private:
  enum class NodeState { kPruned, kFractional, kIntegral };
  /// A cut row Σ coefficient(e) x_e ≤ rhs over free edges, with coefficient 0 or 1.
  struct Cut {
    bool subtour = false;      // subtour: `inside` by super-node; blossom: the handle, by node
    std::vector<char> inside;  // coefficient 1 for edges with both ends inside
    std::vector<int> teeth;    // blossom: free edges of F, sorted (coefficient 1)
    double rhs = 0;
    std::vector<int> key;  // in known_cuts_
  };

  void enumerate_edges();
  void build_lp();
  bool solve_root();
  NodeState solve_node();
  bool resolve();
  bool out_of_work() const;
  void branch();
  int choose_branch_column(bool& up_first);
  void finish_root_columns();
  int price(double room);
  void add_columns(const std::vector<int>& edges);
  int separate();
  int separate_subtours(bool min_cuts);
  int separate_blossoms(bool min_cuts);
  bool try_blossom(const std::vector<char>& handle);
  void add_cut(Cut cut);
  bool integral_solution();
  bool tailing_off(int max_rounds);
  void purge_cuts();
  void take_integral_tour();
  int super_of(int node) const { return node < 2 * g_ ? node >> 1 : g_; }
  /// The forced partner of a node: the other end of its segment, or S ↔ A.
  int partner_of(int node) const { return node ^ 1; }
  int edge_between(int u, int v) const {
    return edge_of_pair_[static_cast<std::size_t>(u) * static_cast<std::size_t>(nodes_) +
                         static_cast<std::size_t>(v)];
  }
  bool contains(const Cut& cut, int edge) const;
  double bound();

  const EndCosts* costs_ = nullptr;
  int g_ = 0;
  int nodes_ = 0;   // 2g + 2 LP nodes: ends, then S = 2g, A = 2g + 1
  int supers_ = 0;  // g + 1 super-nodes: segments, then {S, A} = g
  // Every free edge; LP columns are a subset.
  std::vector<int> edge_u_, edge_v_;
  std::vector<double> edge_cost_;
  std::vector<int> edge_of_pair_;    // nodes_ × nodes_ → edge, -1 for forced pairs and u = v
  std::vector<int> column_of_edge_;  // edge → LP column, -1 if not in the LP
  std::vector<int> edge_of_column_;
  std::vector<Cut> cuts_;  // LP row nodes_ + i is cuts_[i]
  DualSimplex lp_;
  DualSimplex::Status status_ = DualSimplex::Status::kOptimal;
  DualSimplex::Snapshot snapshot_;
  std::set<std::vector<int>> known_cuts_;  // subtours by super-node set, blossoms by (H, F)
  std::vector<int>* best_ = nullptr;
  long long* best_length_ = nullptr;
  std::chrono::steady_clock::time_point deadline_;
  double work_budget_ = 0;
  bool stopped_ = false;  // deadline passed or work budget spent
  bool trouble_ = false;  // an LP ended neither optimal nor infeasible: no optimality claim
  BranchAndCutStats stats_;
  // Scratch, reused.
  FlowGraph flow_;
  std::vector<double> weight_, value_at_;
  std::vector<int> label_, queue_, members_, local_, tree_parent_, candidates_, new_edges_;
  std::vector<double> tree_value_;
  std::vector<int> row_index_;
  std::vector<double> values_, bound_history_;
  struct Pending {
    double violation;
    Cut cut;
  };
  std::vector<Pending> pending_;
  std::vector<char> side_, handle_;
  std::vector<int> big_, teeth_;
  std::vector<std::vector<int>> fractional_;
};

}  // namespace hullinspect::tsp::detail
