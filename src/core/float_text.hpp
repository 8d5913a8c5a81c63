// The shortest decimal text of a float that reads back as the same float, written into a
// caller's buffer: shared by the GLB writer's JSON and the skeleton's glTF extras, where a
// skeleton's ~2000 numbers make formatting a large part of writing its file.
#pragma once

#include <charconv>
#include <cmath>

namespace ramus::detail {

/// Writes `value` at `first` (room for 16 characters needed) and returns the end: the same text
/// as std::to_chars(first, last, value) (its shortest round-trip form), except that −0 is
/// written as "0". Whole numbers below 1000 in magnitude — zeros and ±1 of rotations and axes,
/// angles in whole degrees — take an integer fast path (std::to_chars writes them as integers
/// too). Precondition: finite.
inline char* writeShortest(char* first, char* last, float value) {
    if (std::abs(value) < 1000.0f && value == std::trunc(value)) {
        return std::to_chars(first, last, static_cast<int>(value)).ptr;
    }
    return std::to_chars(first, last, value).ptr;
}

}  // namespace ramus::detail
