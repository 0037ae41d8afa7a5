#include "hullinspect/world/random.hpp"

#include "hullinspect/world/xoshiro.hpp"

namespace hullinspect::world {

namespace {
constexpr std::uint64_t rotl(std::uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}
}  // namespace

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t stream) {
  // Mix the stream id through its own SplitMix round so that nearby (seed, stream) pairs diverge.
  std::uint64_t mix = stream * 0xD1B54A32D192ED03ULL + 0x8CB92BA72F3D8DD7ULL;
  std::uint64_t state = seed ^ splitmix64(mix);
  for (auto& word : s_) word = splitmix64(state);
}

std::uint64_t xoshiro256starstar(std::uint64_t (&s)[4]) {
  const std::uint64_t result = rotl(s[1] * 5, 7) * 9;
  const std::uint64_t t = s[1] << 17;
  s[2] ^= s[0];
  s[3] ^= s[1];
  s[1] ^= s[2];
  s[0] ^= s[3];
  s[2] ^= t;
  s[3] = rotl(s[3], 45);
  return result;
}

std::uint64_t RandomStream::next() { return xoshiro256starstar(s_); }

double RandomStream::uniform01() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

std::uint64_t RandomStream::below(std::uint64_t n) {
  // Rejection of the lowest (2^64 mod n) values makes r mod n exactly uniform.
  const std::uint64_t threshold = (0 - n) % n;
  std::uint64_t r = next();
  while (r < threshold) r = next();
  return r % n;
}

}  // namespace hullinspect::world
