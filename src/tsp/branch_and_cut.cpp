#include "branch_and_cut.hpp"

#include <algorithm>
#include <cmath>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::tsp::detail {

namespace {
constexpr double kIntegral = 1e-6;   // |x − round(x)| below this counts as integral
constexpr double kSupport = 1e-9;    // edges below this are absent from the support graph
constexpr double kViolation = 1e-6;  // a cut must be violated by more than this
constexpr double kBoundSlack = 1e-6;
constexpr double kPricing = 1e-9;       // columns whose reduced cost is below −kPricing enter
constexpr int kNearest = 6;             // initial columns: each end's nearest ends
constexpr int kStrongCandidates = 8;    // strong branching: edges tried per node
constexpr int kStrongIterations = 25;   // strong branching: dual pivots per child
constexpr int kRootRounds = 200;        // cutting rounds at the root, at most
constexpr int kNodeRounds = 20;         // cutting rounds at other nodes, at most
constexpr std::size_t kTailRounds = 5;  // tailing off: bound progress over this many rounds …
constexpr double kTailProgress = 0.05;  // … below this ends the cutting at a node
constexpr int kBlossomsPerRound = 10;   // at least; g / 2 if larger
constexpr long kPivotLimit = 200'000;   // per LP solve; reaching it is numerical trouble
}  // namespace

BranchAndCut::BranchAndCut() = default;
BranchAndCut::~BranchAndCut() = default;

BranchAndCutStats BranchAndCut::solve(const EndCosts& costs, std::vector<int>& best,
                                      long long& best_length,
                                      std::chrono::steady_clock::time_point deadline,
                                      double work_budget) {
  if (costs.segments() < 2) throw LogicError("branch-and-cut called with g < 2");
  costs_ = &costs;
  g_ = costs.segments();
  nodes_ = 2 * g_ + 2;
  supers_ = g_ + 1;
  best_ = &best;
  best_length_ = &best_length;
  deadline_ = deadline;
  work_budget_ = work_budget;
  stopped_ = false;
  trouble_ = false;
  stats_ = {};
  cuts_.clear();
  known_cuts_.clear();
  enumerate_edges();
  build_lp();
  // The root's column fixing and cut purge change the LP: it is solved again (and cut again if
  // needed) as the first node of the tree before anything reads its values.
  if (solve_root() && solve_node() == NodeState::kFractional) branch();
  stats_.optimal = !stopped_ && !trouble_;
  stats_.gave_up = trouble_ && !stopped_;
  costs_ = nullptr;
  best_ = nullptr;
  best_length_ = nullptr;
  return stats_;
}

void BranchAndCut::enumerate_edges() {
  const int artificial = 2 * g_ + 1;
  edge_u_.clear();
  edge_v_.clear();
  edge_cost_.clear();
  edge_of_pair_.assign(static_cast<std::size_t>(nodes_) * static_cast<std::size_t>(nodes_), -1);
  for (int u = 0; u < nodes_; ++u) {
    for (int v = u + 1; v < nodes_; ++v) {
      if (super_of(u) == super_of(v)) continue;  // forced edges are not variables
      const int e = static_cast<int>(edge_u_.size());
      edge_of_pair_[static_cast<std::size_t>(u * nodes_ + v)] = e;
      edge_of_pair_[static_cast<std::size_t>(v * nodes_ + u)] = e;
      edge_u_.push_back(u);
      edge_v_.push_back(v);
      edge_cost_.push_back(v == artificial ? 0.0 : static_cast<double>((*costs_)(u, v)));
    }
  }
  column_of_edge_.assign(edge_u_.size(), -1);
  edge_of_column_.clear();
}

void BranchAndCut::build_lp() {
  const int start = 2 * g_;
  const int artificial = 2 * g_ + 1;
  const int ends = 2 * g_;
  std::vector<char> chosen(edge_u_.size(), 0);
  // The incumbent's edges keep the first LP feasible; every S and A edge; each end's nearest ends.
  int at = start;
  for (int entry : *best_) {
    chosen[static_cast<std::size_t>(edge_between(at, entry))] = 1;
    at = entry ^ 1;
  }
  chosen[static_cast<std::size_t>(edge_between(at, artificial))] = 1;
  for (int u = 0; u < ends; ++u) {
    chosen[static_cast<std::size_t>(edge_between(start, u))] = 1;
    chosen[static_cast<std::size_t>(edge_between(artificial, u))] = 1;
    candidates_.clear();
    for (int v = 0; v < ends; ++v) {
      if (super_of(v) != super_of(u)) candidates_.push_back(v);
    }
    const auto keep = std::min<std::size_t>(kNearest, candidates_.size());
    std::partial_sort(candidates_.begin(), candidates_.begin() + static_cast<std::ptrdiff_t>(keep),
                      candidates_.end(), [&](int a, int b) {
                        const int ca = (*costs_)(u, a);
                        const int cb = (*costs_)(u, b);
                        return ca != cb ? ca < cb : a < b;
                      });
    for (std::size_t k = 0; k < keep; ++k) {
      chosen[static_cast<std::size_t>(edge_between(u, candidates_[k]))] = 1;
    }
  }

  const std::vector<double> degree(static_cast<std::size_t>(nodes_), 1.0);
  lp_.reset(degree);
  new_edges_.clear();
  for (std::size_t e = 0; e < chosen.size(); ++e) {
    if (chosen[e] != 0) new_edges_.push_back(static_cast<int>(e));
  }
  add_columns(new_edges_);
  resolve();
}

bool BranchAndCut::out_of_work() const {
  if (work_budget_ > 0 && lp_.total_work() >= work_budget_) return true;
  return std::chrono::steady_clock::now() >= deadline_;
}

bool BranchAndCut::resolve() {
  long limit = kPivotLimit;
  if (work_budget_ > 0) {
    // The pivots the remaining budget allows at the current size (the last one may overshoot it
    // by the rows a new cut adds).
    const double m = std::max(1, lp_.rows());
    const double left = std::max(0.0, work_budget_ - lp_.total_work());
    limit = std::min<long>(limit, 1 + static_cast<long>(left / (m * m)));
  }
  status_ = lp_.solve(limit, deadline_);
  ++stats_.lp_solves;
  if (status_ == DualSimplex::Status::kPivotLimit && out_of_work()) {
    stopped_ = true;  // out of time or work budget, not numerical trouble
  }
  return status_ == DualSimplex::Status::kOptimal;
}

double BranchAndCut::bound() {
  return lp_.dual_bound() + static_cast<double>(costs_->segment_total());
}

bool BranchAndCut::solve_root() {
  ++stats_.nodes;
  bound_history_.clear();
  bool solved = true;  // build_lp() solved the first LP
  while (true) {
    if (out_of_work()) {
      stopped_ = true;
      return false;
    }
    if (!solved) resolve();
    solved = false;
    // The restricted root LP always holds the incumbent tour, so it cannot be infeasible.
    if (status_ != DualSimplex::Status::kOptimal) {
      trouble_ = true;
      return false;
    }
    if (integral_solution()) {
      if (separate_subtours(false) > 0) continue;
    } else if (!tailing_off(kRootRounds) && separate() > 0) {
      continue;
    }
    if (price(0.0) > 0) continue;
    break;
  }
  stats_.root_bound = static_cast<long long>(std::ceil(bound() - kBoundSlack));
  if (bound() > static_cast<double>(*best_length_) - 1.0 + kBoundSlack) return false;
  if (integral_solution()) {
    take_integral_tour();
    return false;
  }
  finish_root_columns();
  purge_cuts();
  return true;
}

bool BranchAndCut::integral_solution() {
  // Integral and inside the column's bounds: a value of 2 or −1 is integral but no tour.
  const auto x = lp_.values();
  for (int j = 0; j < lp_.columns(); ++j) {
    const double v = x[static_cast<std::size_t>(j)];
    if (std::abs(v - std::round(v)) > kIntegral) return false;
    if (v < lp_.lower(j) - kIntegral || v > lp_.upper(j) + kIntegral) return false;
  }
  return true;
}

bool BranchAndCut::tailing_off(int max_rounds) {
  // Cutting stops at a node after max_rounds rounds, or when the last kTailRounds rounds raised
  // the bound by less than kTailProgress in total; the node is then branched on.
  bound_history_.push_back(bound());
  const std::size_t rounds = bound_history_.size();
  if (static_cast<int>(rounds) > max_rounds) return true;
  return rounds > kTailRounds &&
         bound_history_.back() - bound_history_[rounds - 1 - kTailRounds] < kTailProgress;
}

void BranchAndCut::finish_root_columns() {
  // With the full LP optimal, a tour using edge e costs at least bound + reduced cost(e). Edges
  // for which that cannot beat the incumbent by 1 are useless for the rest of the search: absent
  // ones stay out, present ones are fixed. All other absent edges enter now.
  const double room = static_cast<double>(*best_length_) - 1.0 - bound() + kBoundSlack;
  const auto x = lp_.values();
  const int columns = lp_.columns();
  for (int j = 0; j < columns; ++j) {
    const double reduced = lp_.reduced_cost(j);
    if (x[j] < kIntegral && reduced > room) {
      lp_.set_bounds(j, 0.0, 0.0);
      lp_.retire(j);
    }
    if (x[j] > 1.0 - kIntegral && -reduced > room) {
      lp_.set_bounds(j, 1.0, 1.0);
      lp_.retire(j);
    }
  }
  price(room);
  stats_.columns = lp_.columns();
}

int BranchAndCut::price(double room) {
  // Reduced cost of every absent edge: its cost minus the duals of the rows it would be in.
  // room = 0: the usual pricing (negative reduced costs enter); room > 0: everything up to room.
  const auto dual = lp_.duals();
  candidates_.clear();  // cuts with a non-zero dual
  for (std::size_t i = 0; i < cuts_.size(); ++i) {
    if (std::abs(dual[static_cast<std::size_t>(nodes_) + i]) > 1e-12) {
      candidates_.push_back(static_cast<int>(i));
    }
  }
  new_edges_.clear();
  for (std::size_t e = 0; e < edge_u_.size(); ++e) {
    if (column_of_edge_[e] >= 0) continue;
    double reduced = edge_cost_[e] - dual[edge_u_[e]] - dual[edge_v_[e]];
    for (int i : candidates_) {
      if (contains(cuts_[static_cast<std::size_t>(i)], static_cast<int>(e))) {
        reduced -= dual[static_cast<std::size_t>(nodes_ + i)];
      }
    }
    if (room > 0 ? reduced <= room : reduced < -kPricing) new_edges_.push_back(static_cast<int>(e));
  }
  add_columns(new_edges_);
  return static_cast<int>(new_edges_.size());
}

bool BranchAndCut::contains(const Cut& cut, int edge) const {
  const int u = edge_u_[static_cast<std::size_t>(edge)];
  const int v = edge_v_[static_cast<std::size_t>(edge)];
  if (cut.subtour) {
    return cut.inside[static_cast<std::size_t>(super_of(u))] != 0 &&
           cut.inside[static_cast<std::size_t>(super_of(v))] != 0;
  }
  if (cut.inside[static_cast<std::size_t>(u)] != 0 &&
      cut.inside[static_cast<std::size_t>(v)] != 0) {
    return true;
  }
  return std::binary_search(cut.teeth.begin(), cut.teeth.end(), edge);
}

void BranchAndCut::add_columns(const std::vector<int>& edges) {
  for (int e : edges) {
    row_index_.clear();
    row_index_.push_back(edge_u_[static_cast<std::size_t>(e)]);
    row_index_.push_back(edge_v_[static_cast<std::size_t>(e)]);
    for (std::size_t i = 0; i < cuts_.size(); ++i) {
      if (contains(cuts_[i], e)) row_index_.push_back(nodes_ + static_cast<int>(i));
    }
    column_of_edge_[static_cast<std::size_t>(e)] =
        lp_.add_column(row_index_, edge_cost_[static_cast<std::size_t>(e)], 0.0, 1.0);
    edge_of_column_.push_back(e);
  }
}

int BranchAndCut::choose_branch_column(bool& up_first) {
  // Strong branching: among the most fractional edges, the one whose two children (LP re-solved
  // from this node's basis, at most kStrongIterations dual pivots, no new cuts) raise the bound
  // most (product rule). Ties keep the more fractional, then the lower column.
  const auto x = lp_.values();
  values_.assign(x.begin(), x.end());
  const int columns = lp_.columns();
  candidates_.clear();
  for (int j = 0; j < columns; ++j) {
    if (std::abs(values_[static_cast<std::size_t>(j)] -
                 std::round(values_[static_cast<std::size_t>(j)])) > kIntegral) {
      candidates_.push_back(j);
    }
  }
  if (candidates_.empty()) return -1;
  auto fractionality = [&](int j) {
    const double v = values_[static_cast<std::size_t>(j)];
    return std::min(v, 1.0 - v);
  };
  std::stable_sort(candidates_.begin(), candidates_.end(),
                   [&](int a, int b) { return fractionality(a) > fractionality(b); });
  if (candidates_.size() > static_cast<std::size_t>(kStrongCandidates)) {
    candidates_.resize(static_cast<std::size_t>(kStrongCandidates));
  }
  up_first = true;
  if (candidates_.size() == 1) return candidates_[0];
  const double here = lp_.objective();
  const double cutoff = static_cast<double>(*best_length_) - 1.0 -
                        static_cast<double>(costs_->segment_total()) + kBoundSlack;
  auto child_bound = [&](DualSimplex::Status status) {
    ++stats_.lp_solves;
    if (status == DualSimplex::Status::kInfeasible) return cutoff + 1.0;
    if (status == DualSimplex::Status::kFailed) return here;
    return std::max(lp_.objective(), here);
  };
  int pick = candidates_[0];
  double best_score = -1;
  lp_.save(snapshot_);
  for (int j : candidates_) {
    if (out_of_work()) break;  // the pick so far; the search stops at the next node anyway
    lp_.set_bounds(j, 0.0, 0.0);
    const double down = child_bound(lp_.solve(kStrongIterations, deadline_));
    lp_.restore(snapshot_);
    lp_.set_bounds(j, 1.0, 1.0);
    const double up = child_bound(lp_.solve(kStrongIterations, deadline_));
    lp_.restore(snapshot_);
    const double score = std::max(down - here, 1e-6) * std::max(up - here, 1e-6);
    if (score > best_score) {
      best_score = score;
      pick = j;
      up_first = up <= down;
    }
  }
  return pick;
}

void BranchAndCut::branch() {
  // The LP of this node is solved and fractional: branch on an edge, the child with the lower
  // strong-branching bound first.
  bool up_first = true;
  const int pick = choose_branch_column(up_first);
  if (pick < 0) {
    // Only reachable if the LP's values are not an optimal basic solution of this node (the
    // defect that once made "exact" hand instances to the reference): no optimality claim.
    trouble_ = true;
    return;
  }
  const double lower = lp_.lower(pick);
  const double upper = lp_.upper(pick);
  for (int k = 0; k < 2; ++k) {
    const bool up = (k == 0) == up_first;
    lp_.set_bounds(pick, up ? 1.0 : lower, up ? upper : 0.0);
    ++stats_.nodes;
    if (solve_node() == NodeState::kFractional) branch();
    lp_.set_bounds(pick, lower, upper);
    if (stopped_) return;
  }
}

BranchAndCut::NodeState BranchAndCut::solve_node() {
  bound_history_.clear();
  while (true) {
    if (out_of_work()) {
      stopped_ = true;
      return NodeState::kPruned;
    }
    if (!resolve()) {
      if (status_ != DualSimplex::Status::kInfeasible) trouble_ = true;
      return NodeState::kPruned;
    }
    if (bound() > static_cast<double>(*best_length_) - 1.0 + kBoundSlack) return NodeState::kPruned;
    purge_cuts();
    if (integral_solution()) {
      // An integral solution is a tour unless it has subtours, which are its components.
      if (separate_subtours(false) > 0) continue;
      take_integral_tour();
      return NodeState::kIntegral;
    }
    if (tailing_off(kNodeRounds)) return NodeState::kFractional;
    if (separate() > 0) continue;
    return NodeState::kFractional;
  }
}

int BranchAndCut::separate() {
  // From cheap to expensive, stopping at the first kind that finds cuts: subtours that are
  // components, blossoms whose handle is a component of the fractional edges, subtours by
  // minimum cuts, blossoms by odd minimum cuts.
  if (const int found = separate_subtours(false); found > 0) return found;
  if (const int found = separate_blossoms(false); found > 0) return found;
  if (const int found = separate_subtours(true); found > 0) return found;
  return separate_blossoms(true);
}

int BranchAndCut::separate_subtours(bool min_cuts) {
  const auto x = lp_.values();
  const auto s = static_cast<std::size_t>(supers_);
  weight_.assign(s * s, 0.0);
  for (int j = 0; j < lp_.columns(); ++j) {
    if (x[j] <= kSupport) continue;
    const auto e = static_cast<std::size_t>(edge_of_column_[static_cast<std::size_t>(j)]);
    const auto a = static_cast<std::size_t>(super_of(edge_u_[e]));
    const auto b = static_cast<std::size_t>(super_of(edge_v_[e]));
    weight_[a * s + b] += x[j];
    weight_[b * s + a] += x[j];
  }
  // Connected components of the support graph: each one is a violated subtour.
  label_.assign(s, -1);
  int components = 0;
  for (std::size_t root = 0; root < s; ++root) {
    if (label_[root] >= 0) continue;
    queue_.assign(1, static_cast<int>(root));
    label_[root] = components;
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const auto a = static_cast<std::size_t>(queue_[head]);
      for (std::size_t b = 0; b < s; ++b) {
        if (label_[b] < 0 && weight_[a * s + b] > kSupport) {
          label_[b] = components;
          queue_.push_back(static_cast<int>(b));
        }
      }
    }
    ++components;
  }
  const std::size_t before = cuts_.size();
  Cut cut;
  cut.subtour = true;
  if (components > 1) {
    for (int c = 0; c < components; ++c) {
      cut.inside.assign(s, 0);
      for (std::size_t a = 0; a < s; ++a) cut.inside[a] = label_[a] == c ? 1 : 0;
      add_cut(cut);
    }
    return static_cast<int>(cuts_.size() - before);
  }
  if (!min_cuts) return 0;
  // Connected: minimum cuts between {S, A} and each segment.
  flow_.reset(supers_);
  for (std::size_t a = 0; a < s; ++a) {
    for (std::size_t b = a + 1; b < s; ++b) {
      if (weight_[a * s + b] > kSupport) {
        flow_.add_edge(static_cast<int>(a), static_cast<int>(b), weight_[a * s + b]);
      }
    }
  }
  flow_.build();
  side_.assign(s, 0);  // on the sink side of a cut found this round: skipped as a sink
  for (int t = 0; t < g_; ++t) {
    if (side_[static_cast<std::size_t>(t)] != 0) continue;
    if (flow_.max_flow(g_, t, 2.0 - kViolation) >= 2.0 - kViolation) continue;
    cut.inside.assign(s, 0);
    for (std::size_t a = 0; a < s; ++a) {
      if (!flow_.source_side(static_cast<int>(a))) cut.inside[a] = side_[a] = 1;
    }
    add_cut(cut);
  }
  return static_cast<int>(cuts_.size() - before);
}

int BranchAndCut::separate_blossoms(bool min_cuts) {
  // Padberg–Rao: with w_e = min(x_e, 1 − x_e) and T the nodes with an odd number of edges above
  // one half (the forced edge always counts), a set H with |H ∩ T| odd and w(δ(H)) < 1 gives a
  // violated blossom with F = the edges of δ(H) above one half. Only fractional edges have w > 0,
  // so the search runs on each component of the fractional edges, through a Gomory–Hu tree
  // (Gusfield's algorithm); a component with |C ∩ T| odd is itself such a set.
  const auto x = lp_.values();
  const auto n = static_cast<std::size_t>(nodes_);
  std::vector<int>& big = big_;  // edges above one half at each node, the forced one included
  big.assign(n, 1);
  std::vector<std::vector<int>>& fractional = fractional_;
  fractional.resize(n);
  for (auto& list : fractional) list.clear();
  for (int j = 0; j < lp_.columns(); ++j) {
    const auto e = static_cast<std::size_t>(edge_of_column_[static_cast<std::size_t>(j)]);
    if (x[j] > 0.5 + kIntegral) {
      ++big[static_cast<std::size_t>(edge_u_[e])];
      ++big[static_cast<std::size_t>(edge_v_[e])];
    }
    if (x[j] > kIntegral && x[j] < 1.0 - kIntegral) {
      fractional[static_cast<std::size_t>(edge_u_[e])].push_back(j);
      fractional[static_cast<std::size_t>(edge_v_[e])].push_back(j);
    }
  }
  const std::size_t before = cuts_.size();
  pending_.clear();
  label_.assign(n, -1);
  local_.assign(n, -1);
  std::vector<char>& handle = handle_;
  handle.assign(n, 0);
  for (std::size_t root = 0; root < n; ++root) {
    if (label_[root] >= 0 || fractional[root].empty()) continue;
    members_.assign(1, static_cast<int>(root));
    label_[root] = static_cast<int>(root);
    for (std::size_t head = 0; head < members_.size(); ++head) {
      const auto v = static_cast<std::size_t>(members_[head]);
      for (int j : fractional[v]) {
        const auto e = static_cast<std::size_t>(edge_of_column_[static_cast<std::size_t>(j)]);
        const int w = edge_u_[e] == static_cast<int>(v) ? edge_v_[e] : edge_u_[e];
        if (label_[static_cast<std::size_t>(w)] < 0) {
          label_[static_cast<std::size_t>(w)] = static_cast<int>(root);
          members_.push_back(w);
        }
      }
    }
    int odd = 0;
    for (int v : members_) odd += big[static_cast<std::size_t>(v)] % 2;
    if (odd % 2 == 1) {
      for (int v : members_) handle[static_cast<std::size_t>(v)] = 1;
      try_blossom(handle);
      for (int v : members_) handle[static_cast<std::size_t>(v)] = 0;
      continue;
    }
    // Gusfield: n − 1 minimum cuts, each a tree edge of a Gomory–Hu tree; check each cut.
    const int size = static_cast<int>(members_.size());
    if (!min_cuts || size < 4) continue;
    for (int i = 0; i < size; ++i)
      local_[static_cast<std::size_t>(members_[static_cast<std::size_t>(i)])] = i;
    flow_.reset(size);
    for (int v : members_) {
      for (int j : fractional[static_cast<std::size_t>(v)]) {
        const auto e = static_cast<std::size_t>(edge_of_column_[static_cast<std::size_t>(j)]);
        if (edge_u_[e] != v) continue;  // each edge once, from its lower end
        flow_.add_edge(local_[static_cast<std::size_t>(edge_u_[e])],
                       local_[static_cast<std::size_t>(edge_v_[e])], std::min(x[j], 1.0 - x[j]));
      }
    }
    flow_.build();
    tree_parent_.assign(static_cast<std::size_t>(size), 0);
    for (int i = 1; i < size; ++i) {
      if (i % 16 == 0 && out_of_work()) break;  // n − 1 max-flows: long on large components
      const int p = tree_parent_[static_cast<std::size_t>(i)];
      const double value = flow_.max_flow(i, p, 2.0);  // w-degrees are ≤ 1: this is exact
      for (int k = i + 1; k < size; ++k) {
        if (tree_parent_[static_cast<std::size_t>(k)] == p && flow_.source_side(k)) {
          tree_parent_[static_cast<std::size_t>(k)] = i;
        }
      }
      if (value >= 1.0 - kViolation) continue;
      int in_t = 0;
      for (int k = 0; k < size; ++k) {
        const bool in = flow_.source_side(k);
        const int v = members_[static_cast<std::size_t>(k)];
        handle[static_cast<std::size_t>(v)] = in ? 1 : 0;
        if (in) in_t += big[static_cast<std::size_t>(v)] % 2;
      }
      if (in_t % 2 == 1) try_blossom(handle);
      for (int v : members_) handle[static_cast<std::size_t>(v)] = 0;
    }
  }
  // The most violated first, at most kBlossomsPerRound of them (the LP's cost grows with its rows).
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const Pending& a, const Pending& b) { return a.violation > b.violation; });
  const int limit = std::max(kBlossomsPerRound, g_ / 2);
  for (auto& p : pending_) {
    if (static_cast<int>(cuts_.size() - before) >= limit) break;
    add_cut(std::move(p.cut));
  }
  return static_cast<int>(cuts_.size() - before);
}

bool BranchAndCut::try_blossom(const std::vector<char>& handle) {
  // F: the edges leaving H above one half; if |F| is even, toggle the leaving edge closest to one
  // half. Violated if x(E(H)) + x(F) > |H| + (|F| − 1) / 2. Forced edges (x = 1) go to the rhs.
  const auto x = lp_.values();
  auto in = [&](int v) { return handle[static_cast<std::size_t>(v)] != 0; };
  double lhs = 0;
  double rhs = 0;
  int handle_size = 0;
  int forced_inside = 0;
  std::vector<int>& teeth_free = teeth_;  // free edges in F
  teeth_free.clear();
  int forced_teeth = 0;
  int teeth = 0;
  // The leaving edge closest to one half, for the parity fix: (free edge or -1 - forced node).
  int flip = 0;
  double flip_loss = 2.0;
  for (int v = 0; v < nodes_; ++v) {
    if (!in(v)) continue;
    ++handle_size;
    const int p = partner_of(v);
    if (in(p)) {
      if (v < p) ++forced_inside;
    } else {
      ++forced_teeth;
      ++teeth;
      if (0.5 < flip_loss) {  // dropping a forced tooth loses 1 − 1/2
        flip_loss = 0.5;
        flip = -1 - v;
      }
    }
  }
  for (int j = 0; j < lp_.columns(); ++j) {
    if (x[j] <= kSupport) continue;
    const auto e = static_cast<std::size_t>(edge_of_column_[static_cast<std::size_t>(j)]);
    const bool iu = in(edge_u_[e]);
    const bool iv = in(edge_v_[e]);
    if (iu && iv) {
      lhs += x[j];
    } else if (iu != iv) {
      const double loss = std::abs(x[j] - 0.5);
      if (x[j] > 0.5 + kIntegral) {
        teeth_free.push_back(static_cast<int>(e));
        ++teeth;
      }
      if (loss < flip_loss) {
        flip_loss = loss;
        flip = static_cast<int>(e);
      }
    }
  }
  if (teeth % 2 == 0) {
    if (flip_loss > 0.5 - kViolation) return false;  // nothing to gain
    if (flip < 0) {
      --forced_teeth;  // drop a forced tooth
      --teeth;
    } else if (std::find(teeth_free.begin(), teeth_free.end(), flip) != teeth_free.end()) {
      teeth_free.erase(std::find(teeth_free.begin(), teeth_free.end(), flip));
      --teeth;
    } else {
      teeth_free.push_back(flip);
      ++teeth;
    }
  }
  if (teeth < 1) return false;
  for (int e : teeth_free) {
    const int column = column_of_edge_[static_cast<std::size_t>(e)];
    lhs += x[column];
  }
  // Free-variable form: subtract the forced edges inside H and in F (each x = 1) from both sides.
  rhs = handle_size + (teeth - 1) / 2.0 - forced_inside - forced_teeth;
  if (lhs <= rhs + kViolation) return false;
  Cut cut;
  cut.subtour = false;
  cut.inside = handle;
  std::sort(teeth_free.begin(), teeth_free.end());
  cut.teeth = teeth_free;
  cut.rhs = rhs;
  pending_.push_back({lhs - rhs, std::move(cut)});
  return true;
}

void BranchAndCut::add_cut(Cut cut) {
  std::vector<int> key;
  if (cut.subtour) {
    // A subtour set and its complement give the same row (given the degree rows): key on the side
    // without {S, A}, write the row on the smaller side.
    const auto size = cut.inside.size();
    std::size_t count = 0;
    for (char m : cut.inside) count += m != 0 ? 1 : 0;
    if (count == 0 || count == size) return;
    const bool flip_key = cut.inside[static_cast<std::size_t>(g_)] != 0;
    key.push_back(0);
    for (std::size_t a = 0; a < size; ++a) {
      if ((cut.inside[a] != 0) != flip_key) key.push_back(static_cast<int>(a));
    }
    if (!known_cuts_.insert(key).second) return;
    if (2 * count > size) {
      for (char& m : cut.inside) m = m != 0 ? 0 : 1;
      count = size - count;
    }
    cut.rhs = static_cast<double>(count) - 1.0;
  } else {
    key.push_back(1);
    for (std::size_t v = 0; v < cut.inside.size(); ++v) {
      if (cut.inside[v] != 0) key.push_back(static_cast<int>(v));
    }
    key.push_back(-1);
    key.insert(key.end(), cut.teeth.begin(), cut.teeth.end());
    if (!known_cuts_.insert(key).second) return;
  }
  row_index_.clear();
  for (int j = 0; j < lp_.columns(); ++j) {
    if (contains(cut, edge_of_column_[static_cast<std::size_t>(j)])) row_index_.push_back(j);
  }
  lp_.add_row(row_index_, cut.rhs);
  cut.key = std::move(key);
  cuts_.push_back(std::move(cut));
  ++stats_.cuts;
}

void BranchAndCut::purge_cuts() {
  // Keeps the LP small (its cost grows with the square of the rows): once there are more cuts
  // than nodes, drop those that are not binding. Separation finds them again if needed.
  if (static_cast<int>(cuts_.size()) <= nodes_) return;
  row_index_.clear();
  for (std::size_t i = 0; i < cuts_.size(); ++i) {
    if (lp_.slack_row(nodes_ + static_cast<int>(i)))
      row_index_.push_back(nodes_ + static_cast<int>(i));
  }
  if (row_index_.empty()) return;
  lp_.remove_rows(row_index_);
  std::size_t keep = 0;
  std::size_t next_removed = 0;
  for (std::size_t i = 0; i < cuts_.size(); ++i) {
    if (next_removed < row_index_.size() &&
        row_index_[next_removed] == nodes_ + static_cast<int>(i)) {
      known_cuts_.erase(cuts_[i].key);
      ++next_removed;
      continue;
    }
    if (keep != i) cuts_[keep] = std::move(cuts_[i]);
    ++keep;
  }
  cuts_.resize(keep);
}

void BranchAndCut::take_integral_tour() {
  const auto x = lp_.values();
  std::vector<int> partner(static_cast<std::size_t>(nodes_), -1);
  for (int j = 0; j < lp_.columns(); ++j) {
    if (x[j] > 0.5) {
      const auto e = static_cast<std::size_t>(edge_of_column_[static_cast<std::size_t>(j)]);
      partner[static_cast<std::size_t>(edge_u_[e])] = edge_v_[e];
      partner[static_cast<std::size_t>(edge_v_[e])] = edge_u_[e];
    }
  }
  std::vector<int> tour;
  const int artificial = 2 * g_ + 1;
  for (int at = partner[static_cast<std::size_t>(2 * g_)]; at != artificial;
       at = partner[static_cast<std::size_t>(at ^ 1)]) {
    if (at < 0 || at >= 2 * g_ || static_cast<int>(tour.size()) >= g_) {
      throw LogicError("branch-and-cut: an integral LP solution is not one path");
    }
    tour.push_back(at);
  }
  if (static_cast<int>(tour.size()) != g_) {
    throw LogicError("branch-and-cut: an integral LP solution misses segments");
  }
  const long long length = costs_->length(tour);
  if (length < *best_length_) {
    *best_length_ = length;
    best_->swap(tour);
  }
}

}  // namespace hullinspect::tsp::detail
