#pragma once
// Internal: a small dense bounded dual simplex for the branch-and-cut's LPs, which are tiny
// (tens to a few hundred rows), have only 0/1 coefficients, and are re-solved thousands of times
// after a bound change or a new cut. A general-purpose LP library spends most of such a re-solve
// setting up; here a warm re-solve costs a few pivots of O(m² + nonzeros) each.
//
// min cᵀx subject to Σ_{j ∋ i} x_j = b_i (equality rows) or ≤ b_i (cut rows), lo ≤ x ≤ up with
// finite bounds on every column. The explicit basis inverse is kept dense and updated per pivot,
// and recomputed from the basis every `refactor interval` pivots. dual_bound() gives a lower bound
// that stays valid whatever the numerical state (a Lagrangian bound from the current duals).

#include <chrono>
#include <span>
#include <vector>

namespace hullinspect::tsp::detail {

class DualSimplex {
 public:
  enum class Status { kOptimal, kInfeasible, kPivotLimit, kFailed };

  /// Empties the LP and creates one equality row Σ x = rhs[i] per entry.
  void reset(std::span<const double> equality_rhs);
  /// Adds a column with coefficient 1 in each of `rows`, nonbasic at the bound its reduced cost
  /// prefers. Returns its index.
  int add_column(std::span<const int> rows, double cost, double lower, double upper);
  /// Adds the cut row Σ_{j ∈ columns} x_j ≤ rhs; its slack enters the basis. Returns its index.
  int add_row(std::span<const int> columns, double rhs);
  void set_bounds(int column, double lower, double upper);
  /// Takes a nonbasic fixed column (lower = upper) out of the pivoting for good: it keeps its
  /// value but its reduced cost is no longer maintained, so its bounds must never change again.
  void retire(int column);
  /// True if cut row i's slack is basic and positive (the row is not binding).
  bool slack_row(int row) const;
  /// Removes cut rows whose slacks are basic (see slack_row); later rows are renumbered down.
  void remove_rows(std::span<const int> rows);

  /// Dual simplex pivots until optimal, infeasible, `max_pivots` or `deadline` (checked every
  /// 64 pivots); the last two give kPivotLimit.
  Status solve(long max_pivots, std::chrono::steady_clock::time_point deadline =
                                    std::chrono::steady_clock::time_point::max());

  int columns() const { return static_cast<int>(cost_.size()); }
  /// Σ m² over the pivots since reset() (the cost of a pivot's inverse update), every solve
  /// included: a deterministic measure of the work done, roughly proportional to time.
  double total_work() const { return total_work_; }
  int rows() const { return m_; }
  double lower(int j) const { return lo_[static_cast<std::size_t>(j)]; }
  double upper(int j) const { return up_[static_cast<std::size_t>(j)]; }
  /// Column values of the current basis (primal feasible after kOptimal).
  std::span<const double> values();
  /// Σ c_j x_j of the current basis: a lower bound whenever the basis is dual feasible.
  double objective();
  /// Reduced cost of a column (after a solve).
  double reduced_cost(int j) const { return d_[static_cast<std::size_t>(j)]; }
  /// Row duals π (after a solve).
  std::span<const double> duals();
  /// min over the column box of (c − Aᵀπ)ᵀx + πᵀb with π the current duals (cut rows' duals
  /// clamped to ≤ 0): a lower bound on the LP optimum that holds for any π, so numerical error can
  /// only weaken it.
  double dual_bound();

  /// max |B⁻¹B − I| over the kept inverse and the basis it claims: a self-check for tests.
  double inverse_error();

  /// Everything a strong-branching trial changes, to undo it.
  struct Snapshot {
    std::vector<int> head, state, position, slack_state, slack_position;
    std::vector<double> basic, d, slack_d, lo, up, inverse;
    long since_refactor = 0;
  };
  void save(Snapshot& snapshot) const;
  void restore(const Snapshot& snapshot);

 private:
  enum State { kBasic = 0, kAtLower = 1, kAtUpper = 2 };
  // Variables: columns j ≥ 0, slacks encoded as −1 − i.
  static int slack(int row) { return -1 - row; }
  double value_of_nonbasic(int var) const;
  double var_lower(int var) const;
  double var_upper(int var) const;
  double& inverse(int pos, int row) {
    return inverse_[static_cast<std::size_t>(pos) * static_cast<std::size_t>(stride_) +
                    static_cast<std::size_t>(row)];
  }
  void grow(int rows);
  bool refactor();
  void recompute_basic();
  void recompute_duals();

  int m_ = 0;
  double total_work_ = 0;
  int stride_ = 0;  // capacity of the inverse's rows and columns
  std::vector<double> rhs_;
  std::vector<char> equality_;
  // Columns.
  std::vector<double> cost_, lo_, up_, d_;
  std::vector<std::vector<int>> rows_of_;
  std::vector<int> live_;              // columns not retired, in index order
  std::vector<int> state_, position_;  // position in the basis when basic
  // Slacks (one per row): bounds [0, 0] for equality rows, [0, ∞) for cut rows.
  std::vector<int> slack_state_, slack_position_;
  std::vector<double> slack_d_;
  // Basis.
  std::vector<int> head_;        // variable at each basis position
  std::vector<double> basic_;    // its value
  std::vector<double> inverse_;  // B⁻¹, [position][row]
  long since_refactor_ = 0;
  bool duals_fresh_ = false;
  std::vector<double> pi_, values_;
  // Scratch.
  std::vector<double> rho_, alpha_col_, alpha_, slack_alpha_, work_;
};

}  // namespace hullinspect::tsp::detail
