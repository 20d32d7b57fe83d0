// Seeds and random streams: every seeded part of oceanbox (the ocean's noise, the Gerstner
// waves the spectrum picks, fish jumps, splash drops) draws from splitmix64 (Steele, Lea,
// Flood 2014), written out so a seed gives the same numbers with any C++ library.
#pragma once
#include <cstdint>

namespace ob {

/// splitmix64's finaliser: a bijective 64-bit mix (every input bit moves every output bit).
/// Also how a part derives its own stream from the scene's seed: mix64(seed ^ salt).
constexpr std::uint64_t mix64(std::uint64_t x) {
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/// The next value of the splitmix64 stream whose state is `state` (advanced by the
/// golden-ratio increment; full period 2⁶⁴).
constexpr std::uint64_t splitmix64(std::uint64_t& state) { return mix64(state += 0x9E3779B97F4A7C15ull); }

/// A uniform double in [0, 1) from the stream: its top 53 bits.
inline double uniform01(std::uint64_t& state) { return double(splitmix64(state) >> 11) * 0x1.0p-53; }

/// A uniform float in [0, 1) from the stream: its top 24 bits.
inline float uniform01f(std::uint64_t& state) { return float(splitmix64(state) >> 40) * 0x1.0p-24f; }

} // namespace ob
