#include "branch_and_cut.hpp"

#include <OsiClpSolverInterface.hpp>

#include <algorithm>
#include <cmath>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::tsp::detail {

namespace {
constexpr double kIntegral = 1e-6;   // |x − round(x)| below this counts as integral
constexpr double kSupport = 1e-9;    // edges below this are absent from the support graph
constexpr double kViolation = 1e-6;  // a cut must be violated by more than this
constexpr double kBoundSlack = 1e-6;
}  // namespace

BranchAndCut::BranchAndCut() = default;
BranchAndCut::~BranchAndCut() = default;

BranchAndCutStats BranchAndCut::solve(const EndCosts& costs, std::vector<int>& best,
                                      long long& best_length,
                                      std::chrono::steady_clock::time_point deadline) {
  if (costs.segments() < 2) throw LogicError("branch-and-cut called with g < 2");
  costs_ = &costs;
  g_ = costs.segments();
  nodes_ = 2 * g_ + 2;
  supers_ = g_ + 1;
  best_ = &best;
  best_length_ = &best_length;
  deadline_ = deadline;
  stopped_ = false;
  trouble_ = false;
  stats_ = {};
  known_cuts_.clear();
  build_lp();
  branch(0);
  stats_.optimal = !stopped_ && !trouble_;
  costs_ = nullptr;
  best_ = nullptr;
  best_length_ = nullptr;
  return stats_;
}

void BranchAndCut::build_lp() {
  const int artificial = 2 * g_ + 1;
  edge_u_.clear();
  edge_v_.clear();
  column_of_.assign(static_cast<std::size_t>(nodes_) * static_cast<std::size_t>(nodes_), -1);
  std::vector<double> objective;
  for (int u = 0; u < nodes_; ++u) {
    for (int v = u + 1; v < nodes_; ++v) {
      if (super_of(u) == super_of(v)) continue;  // forced edges are not variables
      const int column = static_cast<int>(edge_u_.size());
      column_of_[static_cast<std::size_t>(u * nodes_ + v)] = column;
      column_of_[static_cast<std::size_t>(v * nodes_ + u)] = column;
      edge_u_.push_back(u);
      edge_v_.push_back(v);
      objective.push_back(v == artificial ? 0.0 : static_cast<double>((*costs_)(u, v)));
    }
  }
  const int columns = static_cast<int>(edge_u_.size());
  std::vector<CoinBigIndex> starts(static_cast<std::size_t>(columns) + 1);
  std::vector<int> rows(2 * static_cast<std::size_t>(columns));
  for (int j = 0; j < columns; ++j) {
    starts[static_cast<std::size_t>(j)] = 2 * j;
    rows[2 * static_cast<std::size_t>(j)] = edge_u_[static_cast<std::size_t>(j)];
    rows[2 * static_cast<std::size_t>(j) + 1] = edge_v_[static_cast<std::size_t>(j)];
  }
  starts[static_cast<std::size_t>(columns)] = 2 * columns;
  const std::vector<double> ones(2 * static_cast<std::size_t>(columns), 1.0);
  const std::vector<double> lower(static_cast<std::size_t>(columns), 0.0);
  const std::vector<double> upper(static_cast<std::size_t>(columns), 1.0);
  const std::vector<double> degree(static_cast<std::size_t>(nodes_), 1.0);

  lp_ = std::make_unique<OsiClpSolverInterface>();
  lp_->messageHandler()->setLogLevel(0);
  lp_->getModelPtr()->setLogLevel(0);
  lp_->setHintParam(OsiDoReducePrint, true, OsiHintTry);
  lp_->loadProblem(columns, nodes_, starts.data(), rows.data(), ones.data(), lower.data(),
                   upper.data(), objective.data(), degree.data(), degree.data());
  lp_->initialSolve();
  ++stats_.lp_solves;
}

void BranchAndCut::branch(int depth) {
  if (stopped_) return;
  ++stats_.nodes;
  const NodeState state = solve_node();
  if (depth == 0 && lp_->isProvenOptimal()) {
    stats_.root_bound = static_cast<long long>(
        std::ceil(lp_->getObjValue() + static_cast<double>(costs_->segment_total()) - kBoundSlack));
  }
  if (state != NodeState::kFractional) return;
  if (depth == 0) fix_by_reduced_cost();

  // Branch on the most fractional edge (lowest column on ties).
  const double* x = lp_->getColSolution();
  int pick = -1;
  double best_distance = 1.0;
  for (int j = 0; j < static_cast<int>(edge_u_.size()); ++j) {
    const double distance = std::abs(x[j] - 0.5);
    if (distance < best_distance) {
      best_distance = distance;
      pick = j;
    }
  }
  if (pick < 0) return;
  lp_->setColLower(pick, 1.0);
  branch(depth + 1);
  lp_->setColLower(pick, 0.0);
  if (stopped_) return;
  lp_->setColUpper(pick, 0.0);
  branch(depth + 1);
  lp_->setColUpper(pick, 1.0);
}

BranchAndCut::NodeState BranchAndCut::solve_node() {
  // The first solve of the root happened in build_lp(); later ones warm-start from the last basis.
  bool fresh = stats_.nodes == 1;
  while (true) {
    if (std::chrono::steady_clock::now() >= deadline_) {
      stopped_ = true;
      return NodeState::kPruned;
    }
    if (!fresh) {
      lp_->resolve();
      ++stats_.lp_solves;
    }
    fresh = false;
    if (!lp_->isProvenOptimal()) {
      if (!lp_->isProvenPrimalInfeasible()) trouble_ = true;
      return NodeState::kPruned;
    }
    const double bound = lp_->getObjValue() + static_cast<double>(costs_->segment_total());
    if (bound > static_cast<double>(*best_length_) - 1.0 + kBoundSlack) return NodeState::kPruned;
    if (separate() > 0) continue;
    const double* x = lp_->getColSolution();
    for (int j = 0; j < static_cast<int>(edge_u_.size()); ++j) {
      if (std::abs(x[j] - std::round(x[j])) > kIntegral) return NodeState::kFractional;
    }
    take_integral_tour();
    return NodeState::kIntegral;
  }
}

void BranchAndCut::fix_by_reduced_cost() {
  // A tour that uses edge j (at 0 in the LP) costs at least bound + reduced cost; if that cannot
  // beat the incumbent by 1, edge j is useless for the rest of the search. Same for edges at 1.
  const double bound = lp_->getObjValue() + static_cast<double>(costs_->segment_total());
  const double room = static_cast<double>(*best_length_) - 1.0 - bound + kBoundSlack;
  const double* x = lp_->getColSolution();
  const double* reduced = lp_->getReducedCost();
  for (int j = 0; j < static_cast<int>(edge_u_.size()); ++j) {
    if (x[j] < kIntegral && reduced[j] > room) lp_->setColUpper(j, 0.0);
    if (x[j] > 1.0 - kIntegral && -reduced[j] > room) lp_->setColLower(j, 1.0);
  }
}

int BranchAndCut::separate() {
  const double* x = lp_->getColSolution();
  const std::size_t s = static_cast<std::size_t>(supers_);
  weight_.assign(s * s, 0.0);
  for (std::size_t j = 0; j < edge_u_.size(); ++j) {
    if (x[j] <= kSupport) continue;
    const auto a = static_cast<std::size_t>(super_of(edge_u_[j]));
    const auto b = static_cast<std::size_t>(super_of(edge_v_[j]));
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
  int added = 0;
  if (components > 1) {
    for (int c = 0; c < components; ++c) {
      side_.clear();
      for (std::size_t a = 0; a < s; ++a) {
        if (label_[a] == c) side_.push_back(static_cast<int>(a));
      }
      if (add_cut(side_)) ++added;
    }
    return added;
  }
  // Connected: minimum cuts between {S, A} and each segment.
  for (int t = 0; t < g_; ++t) {
    if (max_flow(g_, t, 2.0 - kViolation) >= 2.0 - kViolation) continue;
    side_.clear();  // the sink side: super-nodes not reachable from {S, A} in the residual graph
    for (std::size_t a = 0; a < s; ++a) {
      if (parent_[a] < 0) side_.push_back(static_cast<int>(a));
    }
    if (add_cut(side_)) ++added;
  }
  return added;
}

double BranchAndCut::max_flow(int source, int sink, double enough) {
  // Edmonds–Karp on the dense contracted graph; stops once `enough` flow is found.
  const std::size_t s = static_cast<std::size_t>(supers_);
  residual_ = weight_;
  double flow = 0;
  while (true) {
    parent_.assign(s, -1);
    parent_[static_cast<std::size_t>(source)] = source;
    queue_.assign(1, source);
    for (std::size_t head = 0; head < queue_.size() && parent_[static_cast<std::size_t>(sink)] < 0;
         ++head) {
      const auto a = static_cast<std::size_t>(queue_[head]);
      for (std::size_t b = 0; b < s; ++b) {
        if (parent_[b] < 0 && residual_[a * s + b] > kSupport) {
          parent_[b] = static_cast<int>(a);
          queue_.push_back(static_cast<int>(b));
        }
      }
    }
    if (parent_[static_cast<std::size_t>(sink)] < 0) return flow;  // parent_ marks the source side
    double push = enough - flow;
    for (int b = sink; b != source; b = parent_[static_cast<std::size_t>(b)]) {
      const auto a = static_cast<std::size_t>(parent_[static_cast<std::size_t>(b)]);
      push = std::min(push, residual_[a * s + static_cast<std::size_t>(b)]);
    }
    for (int b = sink; b != source; b = parent_[static_cast<std::size_t>(b)]) {
      const auto a = static_cast<std::size_t>(parent_[static_cast<std::size_t>(b)]);
      residual_[a * s + static_cast<std::size_t>(b)] -= push;
      residual_[static_cast<std::size_t>(b) * s + a] += push;
    }
    flow += push;
    if (flow >= enough) return flow;
  }
}

bool BranchAndCut::add_cut(std::vector<int>& supers) {
  // Key: the side without {S, A}. Row: the smaller side (both are equivalent given the degrees).
  std::vector<int> key;
  const bool has_root = std::find(supers.begin(), supers.end(), g_) != supers.end();
  std::vector<char> inside(static_cast<std::size_t>(supers_), 0);
  for (int a : supers) inside[static_cast<std::size_t>(a)] = 1;
  for (int a = 0; a < supers_; ++a) {
    if ((inside[static_cast<std::size_t>(a)] != 0) != has_root) key.push_back(a);
  }
  if (key.empty() || static_cast<int>(key.size()) == supers_) return false;
  if (!known_cuts_.insert(key).second) return false;
  std::vector<int> row_supers;
  if (2 * key.size() <= static_cast<std::size_t>(supers_)) {
    row_supers = key;
  } else {
    for (int a = 0; a < supers_; ++a) {
      if (!std::binary_search(key.begin(), key.end(), a)) row_supers.push_back(a);
    }
  }
  // The nodes of the chosen super-nodes, then every free edge between two of them.
  std::vector<int> members;
  for (int a : row_supers) {
    members.push_back(2 * a);
    members.push_back(2 * a + 1);  // for a = g these are S = 2g and A = 2g + 1
  }
  row_index_.clear();
  for (std::size_t i = 0; i < members.size(); ++i) {
    for (std::size_t k = i + 1; k < members.size(); ++k) {
      const int column = column_of_[static_cast<std::size_t>(members[i] * nodes_ + members[k])];
      if (column >= 0) row_index_.push_back(column);
    }
  }
  row_value_.assign(row_index_.size(), 1.0);
  lp_->addRow(static_cast<int>(row_index_.size()), row_index_.data(), row_value_.data(),
              -lp_->getInfinity(), static_cast<double>(row_supers.size()) - 1.0);
  ++stats_.cuts;
  return true;
}

void BranchAndCut::take_integral_tour() {
  const double* x = lp_->getColSolution();
  std::vector<int> partner(static_cast<std::size_t>(nodes_), -1);
  for (std::size_t j = 0; j < edge_u_.size(); ++j) {
    if (x[j] > 0.5) {
      partner[static_cast<std::size_t>(edge_u_[j])] = edge_v_[j];
      partner[static_cast<std::size_t>(edge_v_[j])] = edge_u_[j];
    }
  }
  std::vector<int> tour;
  const int artificial = 2 * g_ + 1;
  for (int at = partner[static_cast<std::size_t>(2 * g_)]; at != artificial;
       at = partner[static_cast<std::size_t>(at ^ 1)]) {
    if (at < 0 || static_cast<int>(tour.size()) >= g_) {
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
