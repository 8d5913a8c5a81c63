// The bit pattern of a float position, as the solid union welds positions (bit-exact, +0.0 and
// -0.0 alike), and a hash of it. Internal to src/mesh.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "fixed_hash.hpp"
#include "ramus/math.hpp"

namespace ramus::detail {

using PositionBits = std::array<std::uint32_t, 3>;

/// The bits of the position's coordinates, -0.0 taken as +0.0.
inline PositionBits bitsOf(const Vec3f& position) {
    const Vec3f p = position + Vec3f::Zero();  // -0.0 + 0.0 = +0.0
    return {std::bit_cast<std::uint32_t>(p.x()), std::bit_cast<std::uint32_t>(p.y()),
            std::bit_cast<std::uint32_t>(p.z())};
}

/// A hash of `n` 32-bit words, every bit of each stirred into all.
inline std::uint64_t hashOfWords(const std::uint32_t* words, std::size_t n) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::size_t k = 0; k < n; ++k) h = splitMixFinal(h ^ words[k]);
    return h;
}

/// For hash containers of PositionBits.
struct PositionBitsHash {
    std::size_t operator()(const PositionBits& bits) const {
        return static_cast<std::size_t>(hashOfWords(bits.data(), bits.size()));
    }
};

}  // namespace ramus::detail
