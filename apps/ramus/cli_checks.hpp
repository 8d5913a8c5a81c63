// CLI11 validators shared by the subcommands: numbers must be finite (CLI11's own range checks
// let NaN through, since every comparison with it is false, and print infinities badly).
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <string>

namespace ramus::cli {

/// A finite number above `lo` (or equal to it when `allowLo`) and below `hi` (or equal to it
/// when `allowHi`); the message is "expected <expected>, got <text>".
inline CLI::Validator finiteNumber(double lo, bool allowLo, double hi, const std::string& expected,
                                   bool allowHi = false) {
    return CLI::Validator(
        [=](std::string& text) {
            double value = 0.0;
            const bool ok = CLI::detail::lexical_cast(text, value) && std::isfinite(value) &&
                            (value > lo || (allowLo && value == lo)) &&
                            (value < hi || (allowHi && value == hi));
            return ok ? std::string() : "expected " + expected + ", got " + text;
        },
        expected);
}

/// A finite number in the closed range [lo, hi].
inline CLI::Validator finiteIn(double lo, double hi) {
    const auto text = [](double x) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%g", x);
        return std::string(buffer);
    };
    return finiteNumber(lo, true, hi, "a number in [" + text(lo) + ", " + text(hi) + "]", true);
}

/// Largest magnitude accepted where a flag has no natural bound.
inline constexpr double kHugeNumber = 1e300;

}  // namespace ramus::cli
