#include "hullinspect/world/instance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::world {
namespace {

const HullMask& hull() { return default_hull(); }

TEST(Instance, SameSeedSameInstanceDifferentSeedDifferent) {
  const auto p = CorrosionParams::homogeneous(230, 0.005, 5, 0.6, 0.003);
  const auto a = generate_instance(hull(), p, 42);
  const auto b = generate_instance(hull(), p, 42);
  const auto c = generate_instance(hull(), p, 43);
  EXPECT_EQ(a.truth, b.truth);
  EXPECT_EQ(a.prior, b.prior);
  EXPECT_NE(a.truth, c.truth);
}

TEST(Instance, PinnedValuesGuardCrossPlatformReproducibility) {
  // Explicit distributions: these numbers must never change on any platform or compiler.
  const auto inst = generate_instance(hull(), CorrosionParams::homogeneous(230, 0.005, 5), 1);
  EXPECT_EQ(inst.truth_centres, 31);
  EXPECT_EQ(inst.corroded_cells(), 266);
}

TEST(Instance, NonHullCellsAreMinusOneAndCorrosionOnlyOnHull) {
  const auto inst = generate_instance(hull(), CorrosionParams::homogeneous(230, 0.05, 7, 0.5, 0.05), 3);
  for (int i = 0; i < inst.truth.size(); ++i) {
    if (!hull().is_hull(i)) {
      EXPECT_EQ(inst.truth[i], -1);
      EXPECT_EQ(inst.prior[i], -1);
    } else {
      EXPECT_TRUE(inst.truth[i] == 0 || inst.truth[i] == 1);
      EXPECT_TRUE(inst.prior[i] == 0 || inst.prior[i] == 1);
    }
  }
}

TEST(Instance, PerfectPriorEqualsTruth) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto inst = generate_instance(hull(), CorrosionParams::homogeneous(230, 0.005, 5), seed);
    EXPECT_EQ(inst.truth, inst.prior) << seed;
  }
}

TEST(Instance, GroundTruthDoesNotDependOnPriorParameters) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto base = generate_instance(hull(), CorrosionParams::homogeneous(230, 0.005, 5, 1.0, 0.0), seed);
    for (double p_tp : {0.8, 0.4, 0.0}) {
      for (double p_fp : {0.0, 0.003, 0.02}) {
        const auto other = generate_instance(hull(), CorrosionParams::homogeneous(230, 0.005, 5, p_tp, p_fp), seed);
        ASSERT_EQ(base.truth, other.truth) << seed << " " << p_tp << " " << p_fp;
      }
    }
  }
}

TEST(Instance, TruePositivesAreIdenticalInTruthAndPrior) {
  // With p_fp = 0 every prior cell comes from a true positive, whose rectangle is the same in C.
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const auto inst = generate_instance(hull(), CorrosionParams::homogeneous(230, 0.005, 5, 0.6, 0.0), seed);
    for (int i = 0; i < inst.truth.size(); ++i) {
      if (inst.prior[i] == 1) {
        ASSERT_EQ(inst.truth[i], 1) << "seed " << seed << " cell " << i;
      }
    }
    EXPECT_LE(inst.prior_true_positive_centres, inst.truth_centres);
  }
}

TEST(Instance, CentreCountsMatchTheirProbabilities) {
  // Mean over 400 seeds; the tolerance is 4 standard errors of the mean of a binomial count.
  const int seeds = 400;
  const double n = hull().cell_count();
  double centres = 0;
  double tp = 0;
  double fp = 0;
  for (int s = 0; s < seeds; ++s) {
    const auto inst = generate_instance(hull(), CorrosionParams::homogeneous(230, 0.005, 5, 0.6, 0.003),
                                        static_cast<std::uint64_t>(s));
    centres += inst.truth_centres;
    tp += inst.prior_true_positive_centres;
    fp += inst.prior_false_positive_centres;
  }
  centres /= seeds;
  tp /= seeds;
  fp /= seeds;
  const double expected = 0.005 * n;
  EXPECT_NEAR(centres, expected, 4 * std::sqrt(expected * 0.995 / seeds));
  EXPECT_NEAR(tp, 0.6 * expected, 4 * std::sqrt(expected * 0.6 / seeds));
  const double expected_fp = 0.003 * (n - expected);
  EXPECT_NEAR(fp, expected_fp, 4 * std::sqrt(expected_fp / seeds));
}

TEST(Instance, RectangleSidesAreUniformOverOddValues) {
  // On a one-cell-high hull a lone centre paints exactly its rectangle's width in the row.
  grid::Grid<std::uint8_t> row(41, 1, 1);
  const HullMask line(row, "line");
  std::array<int, 3> counts{};
  int total = 0;
  for (std::uint64_t seed = 0; seed < 3000 && total < 1500; ++seed) {
    CorrosionParams p;
    p.zones = {CorrosionZone{0, 41, 1.0 / 41, 5}};
    const auto inst = generate_instance(line, p, seed);
    if (inst.truth_centres != 1) continue;
    int width = 0;
    int first = -1;
    for (int x = 0; x < 41; ++x) {
      if (inst.truth(x, 0) == 1) {
        ++width;
        if (first < 0) first = x;
      }
    }
    if (first - 0 < 2 || 41 - (first + width) < 2) continue;  // skip clipped rectangles
    ASSERT_TRUE(width == 1 || width == 3 || width == 5) << width;
    ++counts[static_cast<std::size_t>(width / 2)];
    ++total;
  }
  ASSERT_GT(total, 500);
  for (int c : counts) EXPECT_NEAR(static_cast<double>(c) / total, 1.0 / 3, 0.06);
}

TEST(Instance, InhomogeneousZonesHaveTheirOwnDensity) {
  const auto p = CorrosionParams::front_back(230, 0.0025, 3, 0.01, 7);
  double back = 0;
  double front = 0;
  for (std::uint64_t s = 0; s < 100; ++s) {
    const auto inst = generate_instance(hull(), p, s);
    for (int i : hull().cells()) {
      if (inst.truth[i] == 1) (hull().mask().cell(i).x < 115 ? back : front) += 1;
    }
  }
  EXPECT_GT(front, 5 * back);  // 4× the centres and larger rectangles
}

TEST(CorrosionParams, RejectsOutOfRangeValues) {
  auto message = [](CorrosionParams p) {
    try {
      validate(p, default_hull());
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(CorrosionParams::homogeneous(230, 1.5, 5)), "p_c: must be a probability in [0, 1] (got 1.5)");
  EXPECT_EQ(message(CorrosionParams::homogeneous(230, 0.1, 4)), "l_c: must be a positive odd integer (got 4)");
  EXPECT_EQ(message(CorrosionParams::homogeneous(230, 0.1, 5, -0.1)), "p_tp: must be a probability in [0, 1] (got -0.1)");
  EXPECT_EQ(message(CorrosionParams::homogeneous(230, 0.1, 5, 1, 2)), "p_fp: must be a probability in [0, 1] (got 2)");
  EXPECT_EQ(message(CorrosionParams::homogeneous(200, 0.1, 5)), "zones: cover x < 200 but the grid is 230 wide");
}

}  // namespace
}  // namespace hullinspect::world
