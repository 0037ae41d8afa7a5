#pragma once
// Seeded random streams with explicitly implemented distributions, so that a seed yields the same
// numbers on every platform, compiler, thread count and process count (std::*_distribution do not
// promise that).

#include <cstdint>

namespace hullinspect::world {

/// SplitMix64 step: used to expand (seed, stream) into generator state.
std::uint64_t splitmix64(std::uint64_t& state);

/// Well-known stream ids, so that independent uses of one seed never share numbers.
enum class Stream : std::uint64_t {
  kTruth = 1,      ///< ground-truth centres and their rectangles
  kPriorTp = 2,    ///< which ground-truth centres the prior knows
  kPriorFp = 3,    ///< false-positive prior centres and their rectangles
  kPartition = 4,  ///< partitioner noise
  kPlanner = 5,    ///< planner randomness, if any
  kFailures = 6,   ///< random UAV failures (docs/model.md, "Failures")
};

/// xoshiro256** generator for one (seed, stream) pair.
class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t stream);
  RandomStream(std::uint64_t seed, Stream stream)
      : RandomStream(seed, static_cast<std::uint64_t>(stream)) {}

  std::uint64_t next();
  /// Uniform in [0, 1) with 53 random bits.
  double uniform01();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  /// Uniform integer in [0, n), n > 0, without modulo bias (rejection).
  std::uint64_t below(std::uint64_t n);
  /// True with probability p (p <= 0: never; p >= 1: always).
  bool bernoulli(double p) { return uniform01() < p; }

 private:
  std::uint64_t s_[4];
};

}  // namespace hullinspect::world
