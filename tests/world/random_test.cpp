#include "hullinspect/world/random.hpp"
#include "hullinspect/world/xoshiro.hpp"

#include <gtest/gtest.h>

#include <array>
#include <utility>

namespace hullinspect::world {
namespace {

TEST(RandomStream, SplitMix64MatchesThePublishedReference) {
  // SplitMix64 (Steele, Lea & Flood 2014; Vigna's splitmix64.c) seeded with 1234567: the outputs
  // published with the reference implementation, checked independently with a Python
  // re-implementation of the algorithm's definition.
  std::uint64_t state = 1234567;
  for (const std::uint64_t expected :
       {6457827717110365317ULL, 3203168211198807973ULL, 9817491932198370423ULL,
        4593380528125082431ULL, 16408922859458223821ULL}) {
    EXPECT_EQ(splitmix64(state), expected);
  }
}

TEST(RandomStream, Xoshiro256StarStarMatchesThePublishedReference) {
  // xoshiro256** (Blackman & Vigna 2018) from the state {1, 2, 3, 4}: the reference outputs.
  std::uint64_t state[4] = {1, 2, 3, 4};
  for (const std::uint64_t expected :
       {11520ULL, 0ULL, 1509978240ULL, 1215971899390074240ULL, 1216172134540287360ULL,
        607988272756665600ULL, 16172922978634559625ULL, 8476171486693032832ULL,
        10595114339597558777ULL, 2904607092377533576ULL}) {
    EXPECT_EQ(xoshiro256starstar(state), expected);
  }
}

TEST(RandomStream, KnownAnswerPinsTheGenerator) {
  // If these change, every instance on every platform changes: keep them fixed. The constants
  // come from a Python re-implementation of the seeding (stream mix, SplitMix64 expansion) and
  // xoshiro256** above, not from this code.
  const std::pair<std::pair<std::uint64_t, std::uint64_t>, std::array<std::uint64_t, 3>> cases[] = {
      {{1, 1}, {13109969620299401308ULL, 6515553773396612589ULL, 14723271156293588355ULL}},
      {{1, 2}, {4324677927131563033ULL, 300707456007715814ULL, 15818912878518887005ULL}},
      {{2, 1}, {7259443898490505358ULL, 11076341082157267972ULL, 5680562064154601763ULL}},
      {{0, 0}, {16945012685865578099ULL, 16950233581499515423ULL, 13304773819607568442ULL}},
      {{18446744073709551615ULL, 5},
       {3459161989245202466ULL, 6554892679446224721ULL, 5980603740486577968ULL}},
  };
  for (const auto& [seed_stream, expected] : cases) {
    RandomStream rng(seed_stream.first, seed_stream.second);
    for (const std::uint64_t e : expected) EXPECT_EQ(rng.next(), e) << seed_stream.first;
  }
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
