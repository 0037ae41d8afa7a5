#pragma once
// Stable 64-bit hashes for run ids and config fingerprints. FNV-1a is used because its value is
// fixed by its definition (unlike std::hash), so ids match across builds, platforms and machines.

#include <cstdint>
#include <string>
#include <string_view>

namespace hullinspect::experiment {

/// 64-bit FNV-1a of the bytes of `text`.
std::uint64_t fnv1a64(std::string_view text);

/// 16 lower-case hex digits.
std::string to_hex(std::uint64_t value);

/// The 64-bit finaliser of MurmurHash3 (fmix64): spreads every input bit over every output bit, so
/// ids of similar strings (differing in the last character) do not look alike.
std::uint64_t avalanche(std::uint64_t value);

/// to_hex(avalanche(fnv1a64(text))): the run and cell ids.
inline std::string stable_id(std::string_view text) { return to_hex(avalanche(fnv1a64(text))); }

}  // namespace hullinspect::experiment
