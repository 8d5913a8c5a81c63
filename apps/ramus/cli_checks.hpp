// CLI11 validators shared by the subcommands: numbers must be finite (CLI11's own range checks
// let NaN through, since every comparison with it is false, and print infinities badly); and
// the `--seed` text of the tree commands.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "ramus/error.hpp"

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

/// `--seed`: a non-negative whole number that fits 64 bits.
inline std::uint64_t parseSeed(const std::string& text) {
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || text[0] == '-') {
        throw Error("--seed: invalid seed '" + text + "'; expected a non-negative integer");
    }
    return value;
}

}  // namespace ramus::cli
