#include "dual_simplex.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullinspect::tsp::detail {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPrimalTolerance = 1e-8;
constexpr double kDualTolerance = 1e-9;
constexpr double kPivotTolerance = 1e-9;
constexpr long kMinRefactorInterval = 100;  // pivots between fresh inverses: at least this, or 2m
}  // namespace

void DualSimplex::reset(std::span<const double> equality_rhs) {
  total_work_ = 0;
  m_ = 0;
  stride_ = 0;
  rhs_.clear();
  equality_.clear();
  cost_.clear();
  lo_.clear();
  up_.clear();
  d_.clear();
  rows_of_.clear();
  live_.clear();
  state_.clear();
  position_.clear();
  slack_state_.clear();
  slack_position_.clear();
  slack_d_.clear();
  head_.clear();
  basic_.clear();
  inverse_.clear();
  since_refactor_ = 0;
  duals_fresh_ = false;
  grow(static_cast<int>(equality_rhs.size()));
  for (double b : equality_rhs) {
    const int i = m_++;
    rhs_.push_back(b);
    equality_.push_back(1);
    slack_state_.push_back(kBasic);
    slack_position_.push_back(i);
    slack_d_.push_back(0.0);
    head_.push_back(slack(i));
    basic_.push_back(b);  // no column yet
    inverse(i, i) = 1.0;
  }
}

void DualSimplex::grow(int rows) {
  if (rows <= stride_) return;
  const int capacity = std::max(rows, 2 * stride_ + 16);
  std::vector<double> bigger(
      static_cast<std::size_t>(capacity) * static_cast<std::size_t>(capacity), 0.0);
  for (int p = 0; p < m_; ++p) {
    for (int i = 0; i < m_; ++i) {
      bigger[static_cast<std::size_t>(p) * static_cast<std::size_t>(capacity) +
             static_cast<std::size_t>(i)] = inverse(p, i);
    }
  }
  inverse_.swap(bigger);
  stride_ = capacity;
}

double DualSimplex::var_lower(int var) const {
  return var >= 0 ? lo_[static_cast<std::size_t>(var)] : 0.0;
}

double DualSimplex::var_upper(int var) const {
  if (var >= 0) return up_[static_cast<std::size_t>(var)];
  return equality_[static_cast<std::size_t>(-1 - var)] != 0 ? 0.0 : kInfinity;
}

double DualSimplex::value_of_nonbasic(int var) const {
  const int state = var >= 0 ? state_[static_cast<std::size_t>(var)]
                             : slack_state_[static_cast<std::size_t>(-1 - var)];
  return state == kAtUpper ? var_upper(var) : var_lower(var);
}

int DualSimplex::add_column(std::span<const int> rows, double cost, double lower, double upper) {
  const int j = static_cast<int>(cost_.size());
  rows_of_.emplace_back(rows.begin(), rows.end());
  live_.push_back(j);
  cost_.push_back(cost);
  lo_.push_back(lower);
  up_.push_back(upper);
  position_.push_back(-1);
  // Reduced cost with the current duals decides the bound; moving off 0 shifts the basic values.
  recompute_duals();
  double d = cost;
  for (int i : rows) d -= pi_[static_cast<std::size_t>(i)];
  d_.push_back(d);
  // A reduced cost of −1e−14 is zero: such a column starts at its lower bound (at the upper one
  // it would shift the basic values for nothing and can leave them outside their bounds).
  const bool at_upper = d < -kDualTolerance && upper > lower;
  state_.push_back(at_upper ? kAtUpper : kAtLower);
  const double value = at_upper ? upper : lower;
  if (value != 0.0) {
    for (int p = 0; p < m_; ++p) {
      double a = 0;
      for (int i : rows) a += inverse(p, i);
      basic_[static_cast<std::size_t>(p)] -= a * value;
    }
  }
  duals_fresh_ = true;  // a nonbasic column does not change π
  return j;
}

int DualSimplex::add_row(std::span<const int> columns, double rhs) {
  recompute_duals();
  grow(m_ + 1);
  const int i = m_++;
  rhs_.push_back(rhs);
  equality_.push_back(0);
  for (int j : columns) rows_of_[static_cast<std::size_t>(j)].push_back(i);
  // New basis row: B' = [B 0; r_B 1], so B'⁻¹ = [B⁻¹ 0; −r_B B⁻¹ 1] with r_B the row's
  // coefficients on the basic columns.
  for (int k = 0; k < i; ++k) inverse(i, k) = 0.0;
  double activity = 0;
  for (int j : columns) {
    const int p = position_[static_cast<std::size_t>(j)];
    if (p >= 0) {
      for (int k = 0; k < i; ++k) inverse(i, k) -= inverse(p, k);
      activity += basic_[static_cast<std::size_t>(p)];
    } else {
      activity += value_of_nonbasic(j);
    }
  }
  for (int p = 0; p < i; ++p) inverse(p, i) = 0.0;
  inverse(i, i) = 1.0;
  slack_state_.push_back(kBasic);
  slack_position_.push_back(i);
  slack_d_.push_back(0.0);
  head_.push_back(slack(i));
  basic_.push_back(rhs - activity);
  pi_.push_back(0.0);  // the slack is basic with cost 0
  return i;
}

void DualSimplex::set_bounds(int j, double lower, double upper) {
  const auto jj = static_cast<std::size_t>(j);
  const double before = position_[jj] >= 0 ? 0.0 : value_of_nonbasic(j);
  lo_[jj] = lower;
  up_[jj] = upper;
  if (position_[jj] >= 0) return;  // a basic column out of its bounds: the next solve fixes it
  // Keep dual feasibility: the bound the reduced cost prefers.
  state_[jj] = (d_[jj] < -kDualTolerance && upper > lower) ? kAtUpper : kAtLower;
  const double shift = value_of_nonbasic(j) - before;
  if (shift == 0.0) return;
  for (int p = 0; p < m_; ++p) {
    double a = 0;
    for (int i : rows_of_[jj]) a += inverse(p, i);
    basic_[static_cast<std::size_t>(p)] -= a * shift;
  }
}

void DualSimplex::retire(int j) {
  if (position_[static_cast<std::size_t>(j)] >= 0 ||
      lo_[static_cast<std::size_t>(j)] != up_[static_cast<std::size_t>(j)])
    return;
  std::erase(live_, j);
}

bool DualSimplex::slack_row(int row) const {
  const auto i = static_cast<std::size_t>(row);
  if (equality_[i] != 0 || slack_position_[i] < 0) return false;
  return basic_[static_cast<std::size_t>(slack_position_[i])] > kPrimalTolerance;
}

void DualSimplex::remove_rows(std::span<const int> rows) {
  // Dropping row i with its basic slack (column e_i at position p) from B leaves the inverse of
  // what remains as B⁻¹ without row p and column i.
  if (rows.empty()) return;
  recompute_duals();
  std::vector<int> new_row(static_cast<std::size_t>(m_), 0);
  std::vector<char> drop_position(static_cast<std::size_t>(m_), 0);
  for (int i : rows) {
    new_row[static_cast<std::size_t>(i)] = -1;
    drop_position[static_cast<std::size_t>(slack_position_[static_cast<std::size_t>(i)])] = 1;
  }
  int next = 0;
  for (auto& r : new_row) r = r < 0 ? -1 : next++;
  std::vector<int> new_position(static_cast<std::size_t>(m_), -1);
  next = 0;
  for (int p = 0; p < m_; ++p) {
    if (drop_position[static_cast<std::size_t>(p)] == 0)
      new_position[static_cast<std::size_t>(p)] = next++;
  }
  const int m = next;
  for (int p = 0; p < m_; ++p) {
    const int np = new_position[static_cast<std::size_t>(p)];
    if (np < 0) continue;
    for (int i = 0; i < m_; ++i) {
      const int ni = new_row[static_cast<std::size_t>(i)];
      if (ni >= 0) inverse(np, ni) = inverse(p, i);  // np ≤ p and ni ≤ i: in place is safe
    }
  }
  auto compact_rows = [&](auto& v) {
    for (int i = 0; i < m_; ++i) {
      const int ni = new_row[static_cast<std::size_t>(i)];
      if (ni >= 0) v[static_cast<std::size_t>(ni)] = v[static_cast<std::size_t>(i)];
    }
    v.resize(static_cast<std::size_t>(m));
  };
  auto compact_positions = [&](auto& v) {
    for (int p = 0; p < m_; ++p) {
      const int np = new_position[static_cast<std::size_t>(p)];
      if (np >= 0) v[static_cast<std::size_t>(np)] = v[static_cast<std::size_t>(p)];
    }
    v.resize(static_cast<std::size_t>(m));
  };
  compact_rows(rhs_);
  compact_rows(equality_);
  compact_rows(slack_state_);
  compact_rows(slack_position_);
  compact_rows(slack_d_);
  compact_rows(pi_);
  for (auto& var : head_) {  // slacks are named by their row
    if (var < 0 && new_row[static_cast<std::size_t>(-1 - var)] >= 0) {
      var = slack(new_row[static_cast<std::size_t>(-1 - var)]);
    }
  }
  compact_positions(head_);
  compact_positions(basic_);
  for (auto& p : slack_position_) {
    if (p >= 0) p = new_position[static_cast<std::size_t>(p)];
  }
  for (auto& p : position_) {
    if (p >= 0) p = new_position[static_cast<std::size_t>(p)];
  }
  for (auto& list : rows_of_) {
    std::size_t keep = 0;
    for (int i : list) {
      const int ni = new_row[static_cast<std::size_t>(i)];
      if (ni >= 0) list[keep++] = ni;
    }
    list.resize(keep);
  }
  m_ = m;
}

void DualSimplex::recompute_duals() {
  if (duals_fresh_) return;
  // πᵀ = c_Bᵀ B⁻¹.
  pi_.assign(static_cast<std::size_t>(m_), 0.0);
  for (int p = 0; p < m_; ++p) {
    const int var = head_[static_cast<std::size_t>(p)];
    if (var < 0) continue;
    const double c = cost_[static_cast<std::size_t>(var)];
    if (c == 0.0) continue;
    for (int i = 0; i < m_; ++i) pi_[static_cast<std::size_t>(i)] += c * inverse(p, i);
  }
  duals_fresh_ = true;
}

void DualSimplex::recompute_basic() {
  // x_B = B⁻¹ (b − N x_N).
  work_.assign(rhs_.begin(), rhs_.end());
  for (std::size_t j = 0; j < cost_.size(); ++j) {
    if (position_[j] >= 0) continue;
    const double v = value_of_nonbasic(static_cast<int>(j));
    if (v == 0.0) continue;
    for (int i : rows_of_[j]) work_[static_cast<std::size_t>(i)] -= v;
  }
  for (int p = 0; p < m_; ++p) {
    double sum = 0;
    for (int i = 0; i < m_; ++i) sum += inverse(p, i) * work_[static_cast<std::size_t>(i)];
    basic_[static_cast<std::size_t>(p)] = sum;
  }
}

bool DualSimplex::refactor() {
  // Gauss–Jordan with partial pivoting on [B | I]; B's row i, column p is the coefficient of
  // row i in the variable at basis position p.
  const auto m = static_cast<std::size_t>(m_);
  std::vector<double> b(m * m, 0.0);
  for (std::size_t p = 0; p < m; ++p) {
    const int var = head_[p];
    if (var < 0) {
      b[static_cast<std::size_t>(-1 - var) * m + p] = 1.0;
    } else {
      for (int i : rows_of_[static_cast<std::size_t>(var)])
        b[static_cast<std::size_t>(i) * m + p] = 1.0;
    }
  }
  std::vector<double> inv(m * m, 0.0);
  for (std::size_t i = 0; i < m; ++i) inv[i * m + i] = 1.0;
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < m; ++r) {
      if (std::abs(b[r * m + c]) > std::abs(b[pivot * m + c])) pivot = r;
    }
    if (std::abs(b[pivot * m + c]) < 1e-11) return false;
    if (pivot != c) {
      for (std::size_t k = 0; k < m; ++k) {
        std::swap(b[pivot * m + k], b[c * m + k]);
        std::swap(inv[pivot * m + k], inv[c * m + k]);
      }
    }
    const double scale = 1.0 / b[c * m + c];
    for (std::size_t k = 0; k < m; ++k) {
      b[c * m + k] *= scale;
      inv[c * m + k] *= scale;
    }
    for (std::size_t r = 0; r < m; ++r) {
      const double factor = b[r * m + c];
      if (r == c || factor == 0.0) continue;
      for (std::size_t k = 0; k < m; ++k) {
        b[r * m + k] -= factor * b[c * m + k];
        inv[r * m + k] -= factor * inv[c * m + k];
      }
    }
  }
  // inv = B⁻¹ with rows indexed by basis position.
  for (std::size_t p = 0; p < m; ++p) {
    for (std::size_t i = 0; i < m; ++i)
      inverse(static_cast<int>(p), static_cast<int>(i)) = inv[p * m + i];
  }
  since_refactor_ = 0;
  duals_fresh_ = false;
  recompute_basic();
  recompute_duals();
  // Reduced costs from fresh duals.
  for (std::size_t j = 0; j < cost_.size(); ++j) {
    if (position_[j] >= 0) {
      d_[j] = 0.0;
      continue;
    }
    double d = cost_[j];
    for (int i : rows_of_[j]) d -= pi_[static_cast<std::size_t>(i)];
    d_[j] = d;
  }
  for (std::size_t i = 0; i < slack_d_.size(); ++i) {
    slack_d_[i] = slack_position_[i] >= 0 ? 0.0 : -pi_[i];
  }
  return true;
}

DualSimplex::Status DualSimplex::solve(long max_pivots,
                                       std::chrono::steady_clock::time_point deadline) {
  const auto n = cost_.size();
  alpha_.resize(n);
  long pivots = 0;
  bool checked = false;  // values recomputed since the last pivot
  while (true) {
    // Leaving variable: the basic one furthest outside its bounds.
    int r = -1;
    double worst = kPrimalTolerance;
    for (int p = 0; p < m_; ++p) {
      const int var = head_[static_cast<std::size_t>(p)];
      const double x = basic_[static_cast<std::size_t>(p)];
      const double below = var_lower(var) - x;
      const double above = x - var_upper(var);
      const double infeasibility = std::max(below, above);
      if (infeasibility > worst) {
        worst = infeasibility;
        r = p;
      }
    }
    if (r < 0) {
      if (!checked) {  // confirm with values recomputed from the inverse
        recompute_basic();
        checked = true;
        continue;
      }
      duals_fresh_ = false;
      return Status::kOptimal;
    }
    if (pivots >= max_pivots) return Status::kPivotLimit;
    if (pivots % 64 == 63 && std::chrono::steady_clock::now() >= deadline)
      return Status::kPivotLimit;
    const int leaving = head_[static_cast<std::size_t>(r)];
    const bool to_lower = basic_[static_cast<std::size_t>(r)] < var_lower(leaving);
    const double sign = to_lower ? -1.0 : 1.0;

    // ρ = row r of B⁻¹; α_j = ρ a_j for the nonbasic variables; Harris ratio test.
    rho_.assign(&inverse(r, 0), &inverse(r, 0) + m_);
    double max_ratio = kInfinity;
    auto first_pass = [&](double alpha, double d, int state) {
      const double a = sign * alpha;
      if (state == kAtLower && a > kPivotTolerance) {
        max_ratio = std::min(max_ratio, (std::max(d, 0.0) + kDualTolerance) / a);
      } else if (state == kAtUpper && a < -kPivotTolerance) {
        max_ratio = std::min(max_ratio, (std::max(-d, 0.0) + kDualTolerance) / -a);
      }
    };
    for (const int live : live_) {
      const auto j = static_cast<std::size_t>(live);
      if (position_[j] >= 0) continue;
      double a = 0;
      for (int i : rows_of_[j]) a += rho_[static_cast<std::size_t>(i)];
      alpha_[j] = a;  // also for fixed columns: their reduced costs must stay current
      if (lo_[j] != up_[j]) first_pass(a, d_[j], state_[j]);
    }
    for (int i = 0; i < m_; ++i) {
      if (slack_position_[static_cast<std::size_t>(i)] >= 0 ||
          equality_[static_cast<std::size_t>(i)] != 0)
        continue;
      first_pass(rho_[static_cast<std::size_t>(i)], slack_d_[static_cast<std::size_t>(i)],
                 kAtLower);
    }
    if (max_ratio == kInfinity) return Status::kInfeasible;
    int entering = 0;
    bool found = false;
    double best_alpha = 0;
    auto second_pass = [&](int var, double alpha, double d, int state) {
      const double a = sign * alpha;
      double ratio = 0;
      if (state == kAtLower && a > kPivotTolerance) {
        ratio = std::max(d, 0.0) / a;
      } else if (state == kAtUpper && a < -kPivotTolerance) {
        ratio = std::max(-d, 0.0) / -a;
      } else {
        return;
      }
      if (ratio <= max_ratio && std::abs(a) > best_alpha) {
        best_alpha = std::abs(a);
        entering = var;
        found = true;
      }
    };
    for (const int live : live_) {
      const auto j = static_cast<std::size_t>(live);
      if (position_[j] >= 0 || lo_[j] == up_[j]) continue;
      second_pass(live, alpha_[j], d_[j], state_[j]);
    }
    for (int i = 0; i < m_; ++i) {
      if (slack_position_[static_cast<std::size_t>(i)] >= 0 ||
          equality_[static_cast<std::size_t>(i)] != 0)
        continue;
      second_pass(slack(i), rho_[static_cast<std::size_t>(i)],
                  slack_d_[static_cast<std::size_t>(i)], kAtLower);
    }
    if (!found) return Status::kInfeasible;

    // Column of the entering variable: α_q = B⁻¹ a_q.
    alpha_col_.assign(static_cast<std::size_t>(m_), 0.0);
    if (entering >= 0) {
      for (int i : rows_of_[static_cast<std::size_t>(entering)]) {
        for (int p = 0; p < m_; ++p) alpha_col_[static_cast<std::size_t>(p)] += inverse(p, i);
      }
    } else {
      const int i = -1 - entering;
      for (int p = 0; p < m_; ++p) alpha_col_[static_cast<std::size_t>(p)] = inverse(p, i);
    }
    const double alpha_rq = alpha_col_[static_cast<std::size_t>(r)];
    const double alpha_row = entering >= 0 ? alpha_[static_cast<std::size_t>(entering)]
                                           : rho_[static_cast<std::size_t>(-1 - entering)];
    if (std::abs(alpha_rq - alpha_row) > 1e-7 * (1.0 + std::abs(alpha_row)) ||
        std::abs(alpha_rq) < kPivotTolerance) {
      // The row and column disagree: the inverse has drifted. Start over from a fresh one.
      if (since_refactor_ == 0 || !refactor()) return Status::kFailed;
      checked = false;
      continue;
    }

    // Primal step: the entering variable moves so that the leaving one lands on its bound.
    const double target = to_lower ? var_lower(leaving) : var_upper(leaving);
    const double step = (basic_[static_cast<std::size_t>(r)] - target) / alpha_rq;
    const double entering_value = value_of_nonbasic(entering) + step;
    for (int p = 0; p < m_; ++p)
      basic_[static_cast<std::size_t>(p)] -= step * alpha_col_[static_cast<std::size_t>(p)];
    basic_[static_cast<std::size_t>(r)] = entering_value;

    // Dual step.
    const double d_entering = entering >= 0 ? d_[static_cast<std::size_t>(entering)]
                                            : slack_d_[static_cast<std::size_t>(-1 - entering)];
    const double theta = d_entering / alpha_rq;
    for (const int live : live_) {
      const auto j = static_cast<std::size_t>(live);
      if (position_[j] < 0) d_[j] -= theta * alpha_[j];
    }
    for (int i = 0; i < m_; ++i) {
      if (slack_position_[static_cast<std::size_t>(i)] >= 0) continue;
      slack_d_[static_cast<std::size_t>(i)] -= theta * rho_[static_cast<std::size_t>(i)];
    }

    // Basis change.
    if (leaving >= 0) {
      position_[static_cast<std::size_t>(leaving)] = -1;
      state_[static_cast<std::size_t>(leaving)] = to_lower ? kAtLower : kAtUpper;
      d_[static_cast<std::size_t>(leaving)] = -theta;
    } else {
      slack_position_[static_cast<std::size_t>(-1 - leaving)] = -1;
      slack_state_[static_cast<std::size_t>(-1 - leaving)] = to_lower ? kAtLower : kAtUpper;
      slack_d_[static_cast<std::size_t>(-1 - leaving)] = -theta;
    }
    if (entering >= 0) {
      position_[static_cast<std::size_t>(entering)] = r;
      state_[static_cast<std::size_t>(entering)] = kBasic;
      d_[static_cast<std::size_t>(entering)] = 0.0;
    } else {
      slack_position_[static_cast<std::size_t>(-1 - entering)] = r;
      slack_state_[static_cast<std::size_t>(-1 - entering)] = kBasic;
      slack_d_[static_cast<std::size_t>(-1 - entering)] = 0.0;
    }
    head_[static_cast<std::size_t>(r)] = entering;

    // B⁻¹ update: pivot on α_rq.
    double* pivot_row = &inverse(r, 0);
    const double inv_pivot = 1.0 / alpha_rq;
    for (int i = 0; i < m_; ++i) pivot_row[i] *= inv_pivot;
    for (int p = 0; p < m_; ++p) {
      const double factor = alpha_col_[static_cast<std::size_t>(p)];
      if (p == r || factor == 0.0) continue;
      double* row = &inverse(p, 0);
      for (int i = 0; i < m_; ++i) row[i] -= factor * pivot_row[i];
    }
    duals_fresh_ = false;
    checked = false;
    ++pivots;
    total_work_ += static_cast<double>(m_) * static_cast<double>(m_);
    if (++since_refactor_ >= std::max<long>(kMinRefactorInterval, 2L * m_)) {
      if (!refactor()) return Status::kFailed;
    }
  }
}

std::span<const double> DualSimplex::values() {
  values_.resize(cost_.size());
  for (std::size_t j = 0; j < cost_.size(); ++j) {
    const int p = position_[j];
    values_[j] =
        p >= 0 ? basic_[static_cast<std::size_t>(p)] : value_of_nonbasic(static_cast<int>(j));
  }
  return values_;
}

double DualSimplex::objective() {
  double total = 0;
  const auto x = values();
  for (std::size_t j = 0; j < cost_.size(); ++j) total += cost_[j] * x[j];
  return total;
}

std::span<const double> DualSimplex::duals() {
  recompute_duals();
  return pi_;
}

double DualSimplex::dual_bound() {
  recompute_duals();
  work_.assign(pi_.begin(), pi_.end());
  double bound = 0;
  for (int i = 0; i < m_; ++i) {
    auto& pi = work_[static_cast<std::size_t>(i)];
    if (equality_[static_cast<std::size_t>(i)] == 0) pi = std::min(pi, 0.0);  // ≤ rows: π ≤ 0
    bound += pi * rhs_[static_cast<std::size_t>(i)];
  }
  for (std::size_t j = 0; j < cost_.size(); ++j) {
    double d = cost_[j];
    for (int i : rows_of_[j]) d -= work_[static_cast<std::size_t>(i)];
    bound += d >= 0 ? d * lo_[j] : d * up_[j];
  }
  return bound;
}

double DualSimplex::inverse_error() {
  double worst = 0;
  for (int p = 0; p < m_; ++p) {
    for (int q = 0; q < m_; ++q) {
      // (B⁻¹ B)[p][q] = Σ_i B⁻¹[p][i] B[i][q], column q of B being the variable at position q.
      const int var = head_[static_cast<std::size_t>(q)];
      double sum = 0;
      if (var < 0) {
        sum = inverse(p, -1 - var);
      } else {
        for (int i : rows_of_[static_cast<std::size_t>(var)]) sum += inverse(p, i);
      }
      worst = std::max(worst, std::abs(sum - (p == q ? 1.0 : 0.0)));
    }
  }
  return worst;
}

void DualSimplex::save(Snapshot& s) const {
  s.head = head_;
  s.state = state_;
  s.position = position_;
  s.slack_state = slack_state_;
  s.slack_position = slack_position_;
  s.basic = basic_;
  s.d = d_;
  s.slack_d = slack_d_;
  s.lo = lo_;
  s.up = up_;
  s.inverse.resize(static_cast<std::size_t>(m_) * static_cast<std::size_t>(m_));
  for (int p = 0; p < m_; ++p) {
    std::copy_n(&inverse_[static_cast<std::size_t>(p) * static_cast<std::size_t>(stride_)], m_,
                &s.inverse[static_cast<std::size_t>(p) * static_cast<std::size_t>(m_)]);
  }
  s.since_refactor = since_refactor_;
}

void DualSimplex::restore(const Snapshot& s) {
  head_ = s.head;
  state_ = s.state;
  position_ = s.position;
  slack_state_ = s.slack_state;
  slack_position_ = s.slack_position;
  basic_ = s.basic;
  d_ = s.d;
  slack_d_ = s.slack_d;
  lo_ = s.lo;
  up_ = s.up;
  for (int p = 0; p < m_; ++p) {
    std::copy_n(&s.inverse[static_cast<std::size_t>(p) * static_cast<std::size_t>(m_)], m_,
                &inverse_[static_cast<std::size_t>(p) * static_cast<std::size_t>(stride_)]);
  }
  since_refactor_ = s.since_refactor;
  duals_fresh_ = false;
}

}  // namespace hullinspect::tsp::detail
