// Names of enumerators kept in a constexpr array indexed by the enum's value (the vocabularies
// of skeleton.hpp and bones.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace ramus::detail {

/// The enumerator whose name is `name`; nullopt for anything else.
template <typename Enum, std::size_t N>
std::optional<Enum> parseName(const std::array<std::string_view, N>& names, std::string_view name) {
    for (std::size_t i = 0; i < N; ++i) {
        if (names[i] == name) return static_cast<Enum>(i);
    }
    return std::nullopt;
}

/// The name of `value`.
template <std::size_t N, typename Enum>
std::string_view nameOf(const std::array<std::string_view, N>& names, Enum value) {
    return names[static_cast<std::size_t>(value)];
}

}  // namespace ramus::detail
