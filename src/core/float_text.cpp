// Shortest round-trip float text: the digits from Dragonbox, the text laid out here.
//
// Based on: Junekey Jeon, "Dragonbox: A New Floating-Point Binary-to-Decimal Conversion
// Algorithm" (2020), as shipped in fmt 9 (Debian's libfmt-dev, used header-only in this one
// file). Dragonbox finds the decimal with the fewest digits in the float's rounding interval
// (its ends included when the significand is even, as round-to-nearest-even reads them back),
// and of those the nearest: the text is as short as std::to_chars's and reads back as the same
// float (tests/core/float_text_test.cpp). It replaced a double-precision digit search (session
// 7) that took 41 ns per float on this machine, against 13 ns for Dragonbox's digits
// (docs/BENCHMARKS.md, session 9).
#include "core/float_text.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

// Dragonbox is a detail of fmt's float formatting, used header-only (CMake's
// fmt::fmt-header-only): nothing of fmt is linked.
#include <fmt/format.h>

namespace ramus::detail {
namespace {

// 10^0 … 10^8: a float's significand has at most 9 digits.
constexpr std::uint32_t kPowersOfTen[] = {1,      10,      100,      1000,     10000,
                                          100000, 1000000, 10000000, 100000000};

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The decimal digits of a text held in an integer, its first character in the lowest byte:
// the digits are built and placed in registers and stored with a few wide stores. (Storing
// them byte by byte and copying them on with wide loads was slower: such a load waits for
// the narrower stores it spans.)
__extension__ typedef unsigned __int128 TextBits;

std::uint64_t digitPair(std::uint32_t n) {  // n < 100: its two characters, tens first
    std::uint16_t pair;
    std::memcpy(&pair, kDigitPairs + 2 * n, 2);
    return pair;
}

// The `count` digits of n < 10^count ≤ 10^9, left-aligned (9 − count leading zeros dropped).
TextBits digitText(std::uint32_t n, int count) {
    const std::uint32_t top = n / 100000000;
    const std::uint32_t rest = n - top * 100000000;
    const std::uint32_t hi = rest / 10000, lo = rest - hi * 10000;
    const std::uint32_t a = hi / 100, b = hi - a * 100, c = lo / 100, d = lo - c * 100;
    const std::uint64_t eight =
        digitPair(a) | digitPair(b) << 16 | digitPair(c) << 32 | digitPair(d) << 48;
    const TextBits nine = ('0' + top) | static_cast<TextBits>(eight) << 8;
    return nine >> (8 * (9 - count));
}

// Stores the first 9 characters of `text` at p.
void storeNine(char* p, TextBits text) {
    const auto first = static_cast<std::uint64_t>(text);
    std::memcpy(p, &first, 8);
    p[8] = static_cast<char>(text >> 64);
}

// digits (count of them, d₁d₂…) × 10^(exponent − count + 1), i.e. d₁.d₂… × 10^exponent, in
// fixed notation or, when that is much longer, scientific ("1e-8", "1.5e20"). The text has at
// most 14 characters, but the stores have a fixed size and write garbage after it, up to 15
// bytes from p: the caller's 16 leave room for that after a sign.
char* writeDecimal(char* p, std::uint32_t digits, int count, int exponent) {
    const TextBits text = digitText(digits, count);
    const int fixedLength = exponent >= 0 ? (count <= exponent + 1 ? exponent + 1 : count + 1)
                                          : 1 + (-exponent) + count;
    const int magnitude = exponent < 0 ? -exponent : exponent;
    const int scientificLength =
        count + (count > 1 ? 1 : 0) + 1 + (exponent < 0 ? 1 : 0) + (magnitude >= 10 ? 2 : 1);
    // Fixed unless scientific saves two characters or more: 1000 and 0.001 stay readable.
    if (fixedLength <= scientificLength + 1) {
        if (exponent < 0) {  // 0.000ddd: at most 3 zeros after the point, else scientific
            std::memcpy(p, "0.000000", 8);
            storeNine(p + 1 - exponent, text);
        } else if (count <= exponent + 1) {  // ddd000: at most 5 zeros, else scientific
            storeNine(p, text);
            std::memcpy(p + count, "000000", 6);
        } else {  // dd.ddd: count − exponent − 1 ≤ 8 − exponent digits after the point
            storeNine(p, text);
            p[exponent + 1] = '.';
            const TextBits fraction = text >> (8 * (exponent + 1));
            if (exponent <= 4) {
                storeNine(p + exponent + 2, fraction);
            } else {
                const auto few = static_cast<std::uint32_t>(fraction);
                std::memcpy(p + exponent + 2, &few, 4);
            }
        }
        return p + fixedLength;
    }
    p[0] = static_cast<char>(text);
    int length = 1;
    if (count > 1) {
        p[1] = '.';
        storeNine(p + 2, text >> 8);
        length = count + 1;
    }
    p[length++] = 'e';
    if (exponent < 0) p[length++] = '-';
    if (magnitude >= 10) p[length++] = static_cast<char>('0' + magnitude / 10);
    p[length++] = static_cast<char>('0' + magnitude % 10);
    return p + length;
}

}  // namespace

char* writeShortFloat(char* p, float value) {
    if (value == 0.0f) {  // ±0
        *p++ = '0';
        return p;
    }
    if (std::signbit(value)) *p++ = '-';
    // |value| = significand · 10^exponent with the fewest digits; subnormals included.
    const auto decimal = fmt::detail::dragonbox::to_decimal(std::abs(value));
    const std::uint32_t digits = decimal.significand;
    int count = 1;
    while (count < 9 && digits >= kPowersOfTen[count]) ++count;
    return writeDecimal(p, digits, count, decimal.exponent + count - 1);
}

}  // namespace ramus::detail
