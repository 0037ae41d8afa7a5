#include "hullinspect/world/random.hpp"

#include <gtest/gtest.h>

#include <array>

namespace hullinspect::world {
namespace {

TEST(RandomStream, KnownAnswerPinsTheGenerator) {
  // If these change, every instance on every platform changes: keep them fixed.
  RandomStream rng(1, 1);
  const std::uint64_t a = rng.next();
  const std::uint64_t b = rng.next();
  RandomStream again(1, 1);
  EXPECT_EQ(again.next(), a);
  EXPECT_EQ(again.next(), b);
  EXPECT_NE(RandomStream(1, 2).next(), a);
  EXPECT_NE(RandomStream(2, 1).next(), a);
}

TEST(RandomStream, BelowIsUniform) {
  RandomStream rng(9, 3);
  std::array<int, 7> counts{};
  const int draws = 70000;
  for (int i = 0; i < draws; ++i) ++counts[rng.below(7)];
  for (int c : counts) EXPECT_NEAR(c, draws / 7, 400);  // ~4.4 sd
}

TEST(RandomStream, Uniform01InRangeAndBernoulliEdges) {
  RandomStream rng(3, 3);
  double sum = 0;
  for (int i = 0; i < 10000; ++i) {
    const double u = rng.uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    ASSERT_FALSE(rng.bernoulli(0.0));
    ASSERT_TRUE(rng.bernoulli(1.0));
  }
  EXPECT_NEAR(sum / 10000, 0.5, 0.015);
}

}  // namespace
}  // namespace hullinspect::world
