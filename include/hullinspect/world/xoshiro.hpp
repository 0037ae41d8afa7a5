#pragma once
// The xoshiro256** step (Blackman & Vigna 2018) behind world::RandomStream, exposed so that tests
// can pin it to the reference algorithm's published outputs.

#include <cstdint>

namespace hullinspect::world {

/// Advances the state `s` (not all zero) and returns the next output.
std::uint64_t xoshiro256starstar(std::uint64_t (&s)[4]);

}  // namespace hullinspect::world
