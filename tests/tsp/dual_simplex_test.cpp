// The branch-and-cut's own LP solver against CLP on random LPs of the same shape (0/1 matrices,
// equality degree rows, ≤ cut rows, boxed columns), through the warm-start operations the
// branch-and-cut uses: new rows, new columns, bound changes, row removal, snapshots.

#include <gtest/gtest.h>

#include <OsiClpSolverInterface.hpp>

#include <cmath>
#include <optional>
#include <vector>

#include "../../src/tsp/dual_simplex.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::tsp::detail {
namespace {

/// The same LP kept as plain data, solved from scratch by CLP.
struct Model {
  int equality_rows = 0;
  std::vector<std::vector<int>> column_rows;
  std::vector<double> cost, lower, upper;
  std::vector<double> rhs;  // all rows; rows ≥ equality_rows are ≤ rows

  std::optional<double> clp_optimum() const {
    OsiClpSolverInterface lp;
    lp.messageHandler()->setLogLevel(0);
    const int m = static_cast<int>(rhs.size());
    std::vector<double> row_lower(rhs.size()), row_upper(rhs.size());
    for (int i = 0; i < m; ++i) {
      row_lower[static_cast<std::size_t>(i)] =
          i < equality_rows ? rhs[static_cast<std::size_t>(i)] : -lp.getInfinity();
      row_upper[static_cast<std::size_t>(i)] = rhs[static_cast<std::size_t>(i)];
    }
    std::vector<CoinBigIndex> starts;
    std::vector<int> rows;
    for (const auto& list : column_rows) {
      starts.push_back(static_cast<CoinBigIndex>(rows.size()));
      rows.insert(rows.end(), list.begin(), list.end());
    }
    starts.push_back(static_cast<CoinBigIndex>(rows.size()));
    const std::vector<double> ones(rows.size(), 1.0);
    lp.loadProblem(static_cast<int>(cost.size()), m, starts.data(), rows.data(), ones.data(),
                   lower.data(), upper.data(), cost.data(), row_lower.data(), row_upper.data());
    lp.initialSolve();
    if (lp.isProvenPrimalInfeasible()) return std::nullopt;
    EXPECT_TRUE(lp.isProvenOptimal());
    return lp.getObjValue();
  }
};

int below(world::RandomStream& r, int n) {
  return static_cast<int>(r.below(static_cast<std::uint64_t>(n)));
}

void expect_same(DualSimplex& lp, const Model& model, DualSimplex::Status status,
                 const char* step) {
  const auto reference = model.clp_optimum();
  SCOPED_TRACE(step);
  if (!reference) {
    EXPECT_EQ(status, DualSimplex::Status::kInfeasible);
    return;
  }
  EXPECT_LT(lp.inverse_error(), 1e-9);
  ASSERT_EQ(status, DualSimplex::Status::kOptimal);
  EXPECT_NEAR(lp.objective(), *reference, 1e-6);
  EXPECT_NEAR(lp.dual_bound(), *reference, 1e-6);
  // The solution satisfies every row and bound.
  const auto x = lp.values();
  std::vector<double> activity(model.rhs.size(), 0.0);
  for (std::size_t j = 0; j < model.column_rows.size(); ++j) {
    EXPECT_GE(x[j], model.lower[j] - 1e-7);
    EXPECT_LE(x[j], model.upper[j] + 1e-7);
    for (int i : model.column_rows[j]) activity[static_cast<std::size_t>(i)] += x[j];
  }
  for (std::size_t i = 0; i < model.rhs.size(); ++i) {
    if (static_cast<int>(i) < model.equality_rows) {
      EXPECT_NEAR(activity[i], model.rhs[i], 1e-7);
    } else {
      EXPECT_LE(activity[i], model.rhs[i] + 1e-7);
    }
  }
}

TEST(DualSimplex, MatchesClpThroughWarmStarts) {
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    world::RandomStream random(seed, 91);
    const int n = 6 + 2 * below(random, 10);  // nodes, each with one degree row Σ x = 1
    Model model;
    model.equality_rows = n;
    model.rhs.assign(static_cast<std::size_t>(n), 1.0);
    DualSimplex lp;
    lp.reset(model.rhs);
    auto add_column = [&](int u, int v) {
      const double cost = below(random, 50);
      model.column_rows.push_back({u, v});
      model.cost.push_back(cost);
      model.lower.push_back(0.0);
      model.upper.push_back(1.0);
      const std::vector<int> rows = {u, v};
      lp.add_column(rows, cost, 0.0, 1.0);
    };
    for (int u = 0; u < n; ++u) {
      for (int v = u + 1; v < n; ++v) {
        if (below(random, 3) == 0) add_column(u, v);
      }
      add_column(u, (u + 1) % n);  // a cycle through every node keeps most LPs feasible
    }
    expect_same(lp, model, lp.solve(1'000'000), "first solve");
    for (int round = 0; round < 8; ++round) {
      // A cut on a random node set: x(E(S)) ≤ ⌊|S| / 2⌋.
      std::vector<char> in(static_cast<std::size_t>(n), 0);
      int size = 0;
      for (int v = 0; v < n; ++v) {
        if (below(random, 3) == 0) {
          in[static_cast<std::size_t>(v)] = 1;
          ++size;
        }
      }
      std::vector<int> columns;
      for (std::size_t j = 0; j < model.column_rows.size(); ++j) {
        const auto& r = model.column_rows[j];
        if (r[0] < n && r[1] < n && in[static_cast<std::size_t>(r[0])] &&
            in[static_cast<std::size_t>(r[1])]) {
          columns.push_back(static_cast<int>(j));
        }
      }
      const int row = static_cast<int>(model.rhs.size());
      model.rhs.push_back(size / 2);
      for (int j : columns) model.column_rows[static_cast<std::size_t>(j)].push_back(row);
      EXPECT_EQ(lp.add_row(columns, size / 2), row);
      expect_same(lp, model, lp.solve(1'000'000), "after a cut");
      // A new column.
      // Named draws (argument order is unspecified; this is the order first used).
      const int to = below(random, n);
      const int from = below(random, n);
      add_column(from, to);
      expect_same(lp, model, lp.solve(1'000'000), "after a column");
      // Branch on a column, try both sides from one snapshot, keep one.
      const int j = below(random, lp.columns());
      DualSimplex::Snapshot snapshot;
      lp.save(snapshot);
      for (double fixed : {0.0, 1.0}) {
        lp.set_bounds(j, fixed, fixed);
        model.lower[static_cast<std::size_t>(j)] = model.upper[static_cast<std::size_t>(j)] = fixed;
        expect_same(lp, model, lp.solve(1'000'000), "after fixing a column");
        lp.restore(snapshot);
        model.lower[static_cast<std::size_t>(j)] = 0.0;
        model.upper[static_cast<std::size_t>(j)] = 1.0;
      }
      expect_same(lp, model, lp.solve(1'000'000), "after restoring a snapshot");
      // Drop the cuts that are not binding.
      std::vector<int> slack;
      for (int i = n; i < lp.rows(); ++i) {
        if (lp.slack_row(i)) slack.push_back(i);
      }
      lp.remove_rows(slack);
      for (auto it = slack.rbegin(); it != slack.rend(); ++it) {
        model.rhs.erase(model.rhs.begin() + *it);
        for (auto& list : model.column_rows) {
          std::vector<int> kept;
          for (int i : list) {
            if (i != *it) kept.push_back(i > *it ? i - 1 : i);
          }
          list = kept;
        }
      }
      expect_same(lp, model, lp.solve(1'000'000), "after removing slack rows");
    }
  }
}

}  // namespace
}  // namespace hullinspect::tsp::detail
