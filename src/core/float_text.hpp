// A short decimal text of a float that reads back as the same float, written into a
// caller's buffer: shared by the GLB writer's JSON and the skeleton's glTF extras, where a
// skeleton's ~2000 numbers make formatting a large part of writing its file.
#pragma once

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "ramus/error.hpp"

namespace ramus::detail {

/// Writes the shortest decimal text of `value` at p (room for 16 characters needed) that reads
/// back as the same float: the digits of scientific std::to_chars (Dragonbox), laid out in fixed
/// notation unless scientific saves two characters; "0" for ±0. Precondition: finite. Measured
/// 25-27 ns per float against 32 ns for std::to_chars (docs/BENCHMARKS.md, session 9).
char* writeShortFloat(char* p, float value);

/// Whole numbers below 1000 in magnitude — zeros and ±1 of rotations and axes, angles in whole
/// degrees — are written as integers by writeShortest.
inline bool isSmallWholeNumber(float value) {
    return std::abs(value) < 1000.0f && value == std::trunc(value);
}
/// Writes `value` at `first` (room for 16 characters needed) and returns the end: integers for
/// small whole numbers, else writeShortFloat ("0" for −0). Precondition: finite.
inline char* writeShortest(char* first, char* last, float value) {
    if (isSmallWholeNumber(value)) return std::to_chars(first, last, static_cast<int>(value)).ptr;
    return writeShortFloat(first, value);
}

/// writeShortest with a memory: the texts of recently written floats, kept by bit pattern in a
/// direct-mapped table (a hit copies the text instead of formatting it). A mirrored
/// skeleton writes most of its numbers more than once — twins differ in signs, rest rotations
/// repeat node rotations — so more than half of a skeleton file's numbers hit. The text is the
/// same with or without the cache (−x is "-" and the text of x).
class FloatTextCache {
public:
    // User-provided, so that value-initialization (make_unique) leaves bits_ and texts_ alone.
    FloatTextCache() {}  // NOLINT(modernize-use-equals-default)

    char* write(char* first, char* last, float value) {
        if (isSmallWholeNumber(value)) return writeShortest(first, last, value);
        const float magnitude = std::abs(value);
        const auto bits = std::bit_cast<std::uint32_t>(magnitude);
        const std::uint32_t slot = (bits * 2654435761u) >> (32 - kSlotBits);  // Fibonacci hashing
        char* p = first;
        if (value < 0.0f) *p++ = '-';
        // The copies have a fixed size (the whole slot), which compiles to a few moves: a copy
        // of the text's own length became `rep movsq`, whose start-up costs tens of cycles on
        // Intel cores (docs/BENCHMARKS.md, session 8). The bytes after the text are garbage
        // of the caller's buffer, which has room for them (16 bytes, the sign included).
        RAMUS_ASSERT(last - first >= 16);
        (void)last;
        if (lengths_[slot] > 0 && bits_[slot] == bits) {
            std::memcpy(p, texts_[slot], sizeof texts_[slot]);
            return p + lengths_[slot];
        }
        char* end = writeShortFloat(p, magnitude);
        if (end - p > static_cast<std::ptrdiff_t>(sizeof texts_[slot])) return end;
        bits_[slot] = bits;
        lengths_[slot] = static_cast<std::uint8_t>(end - p);
        std::memcpy(texts_[slot], p, sizeof texts_[slot]);
        return end;
    }

private:
    static constexpr int kSlotBits = 10;
    static constexpr std::size_t kSlots = std::size_t{1} << kSlotBits;
    // Only the lengths start zeroed (0: empty slot), so a new cache costs 1 KB of clearing.
    std::array<std::uint8_t, kSlots> lengths_{};
    std::array<std::uint32_t, kSlots> bits_;
    char texts_[kSlots][15];  // the longest float text without its sign has 14 characters
};

}  // namespace ramus::detail
