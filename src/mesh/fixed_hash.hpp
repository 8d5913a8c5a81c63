// A fixed hash for deterministic perturbations (no generator state): the same input always
// gives the same value. Internal to src/mesh.
#pragma once

#include <cstdint>

namespace ramus::detail {

/// SplitMix64's finalizer (Steele, Lea, Flood 2014): every bit of `x` stirred into every bit.
inline std::uint64_t splitMixFinal(std::uint64_t x) {
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/// SplitMix64's output for the state `x`, mapped to [-1, 1).
inline double hashUnit(std::uint64_t x) {
    x = splitMixFinal(x + 0x9E3779B97F4A7C15ull);
    return static_cast<double>(x >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

}  // namespace ramus::detail
