// Number <-> text helpers shared by the species file and SVG code: the shortest decimal form
// that reads back to the same double, and locale-independent parsing.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace ramus::detail {

/// Appends `value` in the shortest form that parses back to the identical double; integral
/// values below 1e15 in magnitude are written without a fraction ("4000"). Non-finite values
/// must not be passed.
void appendShortest(std::string& out, double value);

/// `value` as appendShortest writes it.
std::string shortest(double value);

/// Parses a number at text[pos] (optional sign, digits, fraction, exponent — the SVG/JSON
/// number grammar, a leading '+' and ".5" allowed) and advances pos past it; nullopt (pos
/// unchanged) when there is no number there or it is out of range.
std::optional<double> parseNumber(std::string_view text, std::size_t& pos);

}  // namespace ramus::detail
