// Short round-trip float text without std::to_chars's exact shortest search.
//
// Based on: a float has a 24-bit significand, so 9 significant decimal digits always tell it
// apart (FLT_DECIMAL_DIG), and a decimal reads back as the float f exactly when it lies
// strictly within half a unit in the last place (ulp) of f. The digits are found in double
// precision: x · 10^(8−e) for the float's decimal exponent e is off by far less than 10⁻⁶ of
// the last of 9 digits, while half an ulp of f is at least 1.49 such units (2.98 for a float
// that is not a power of two, whose lower neighbour is half as far). So the 9-digit integer D
// nearest to it reads back as f, and so does any shorter rounding of D whose distance to the
// double-precision value (good to 10⁻⁶ units) stays below half an ulp; the shortest such
// rounding is written. This gives the shortest text for nearly all floats (0.1f → "0.1") and never
// a text that reads back as another float (tests/core/float_text_test.cpp checks millions of floats
// and every power of two against strtof).
#include "core/float_text.hpp"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

namespace ramus::detail {
namespace {

// 10^k for k in [−30, 47]: 8 − e for every normal float's decimal exponent e and one more (the
// nearest doubles; the compiler rounds the literals).
constexpr int kMinPow10 = -30;
constexpr double kPow10[] = {
    1e-30, 1e-29, 1e-28, 1e-27, 1e-26, 1e-25, 1e-24, 1e-23, 1e-22, 1e-21, 1e-20, 1e-19, 1e-18,
    1e-17, 1e-16, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-9,  1e-8,  1e-7,  1e-6,  1e-5,
    1e-4,  1e-3,  1e-2,  1e-1,  1e0,   1e1,   1e2,   1e3,   1e4,   1e5,   1e6,   1e7,   1e8,
    1e9,   1e10,  1e11,  1e12,  1e13,  1e14,  1e15,  1e16,  1e17,  1e18,  1e19,  1e20,  1e21,
    1e22,  1e23,  1e24,  1e25,  1e26,  1e27,  1e28,  1e29,  1e30,  1e31,  1e32,  1e33,  1e34,
    1e35,  1e36,  1e37,  1e38,  1e39,  1e40,  1e41,  1e42,  1e43,  1e44,  1e45,  1e46,  1e47};
double pow10(int k) { return kPow10[k - kMinPow10]; }

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The `count` decimal digits of n (n < 10^count ≤ 10^9) at p, most significant first, two at
// a time; returns the end.
char* writeDigits(char* p, std::uint32_t n, int count) {
    char* end = p + count;
    char* q = end;
    while (q - p >= 2) {
        q -= 2;
        std::memcpy(q, kDigitPairs + 2 * (n % 100), 2);
        n /= 100;
    }
    if (q > p) *p = static_cast<char>('0' + n);
    return end;
}

// digits (count of them, d₁d₂…) × 10^(exponent − count + 1), i.e. d₁.d₂… × 10^exponent, in
// fixed notation or, when that is much longer, scientific ("1e-8", "1.5e20").
char* writeDecimal(char* p, std::uint32_t digits, int count, int exponent) {
    const int fixedLength = exponent >= 0 ? (count <= exponent + 1 ? exponent + 1 : count + 1)
                                          : 1 + (-exponent) + count;
    const int magnitude = exponent < 0 ? -exponent : exponent;
    const int scientificLength =
        count + (count > 1 ? 1 : 0) + 1 + (exponent < 0 ? 1 : 0) + (magnitude >= 10 ? 2 : 1);
    // Fixed unless scientific saves two characters or more: 1000 and 0.001 stay readable.
    if (fixedLength <= scientificLength + 1) {
        if (exponent < 0) {
            *p++ = '0';
            *p++ = '.';
            for (int i = 1; i < -exponent; ++i) *p++ = '0';
            return writeDigits(p, digits, count);
        }
        if (count <= exponent + 1) {
            p = writeDigits(p, digits, count);
            for (int i = count; i <= exponent; ++i) *p++ = '0';
            return p;
        }
        char text[9];
        writeDigits(text, digits, count);
        std::memcpy(p, text, static_cast<std::size_t>(exponent + 1));
        p += exponent + 1;
        *p++ = '.';
        std::memcpy(p, text + exponent + 1, static_cast<std::size_t>(count - exponent - 1));
        return p + (count - exponent - 1);
    }
    char text[9];
    writeDigits(text, digits, count);
    *p++ = text[0];
    if (count > 1) {
        *p++ = '.';
        std::memcpy(p, text + 1, static_cast<std::size_t>(count - 1));
        p += count - 1;
    }
    *p++ = 'e';
    if (exponent < 0) *p++ = '-';
    if (magnitude >= 10) *p++ = static_cast<char>('0' + magnitude / 10);
    *p++ = static_cast<char>('0' + magnitude % 10);
    return p;
}

// D rounded to the fewest digits whose distance to `scaled` (the float in units of D's last
// digit) stays below `slack`; returns the digit count and sets digits (and bumps exponent when
// rounding carries, 999… → 1…). Rounding to a coarser power of ten never comes closer than to a
// finer one (the nearest multiple of 10 is at least as near as the nearest multiple of 100), so the
// search runs from the finest and stops at the first that is too far: one or two steps for most
// floats, which need 8 or 9 digits.
int shortestRounding(std::uint32_t d, double scaled, double slack, std::uint32_t& digits,
                     int& exponent) {
    // 10^0 … 10^9: the scales tried, and the carry test's 10^count (count ≤ 9).
    constexpr std::uint32_t kScales[] = {1,      10,      100,      1000,      10000,
                                         100000, 1000000, 10000000, 100000000, 1000000000};
    int kept = 0;  // the coarsest scale index that is near enough
    std::uint32_t best = d;
#pragma GCC unroll 8  // each division then is by a constant (a multiplication)
    for (int i = 1; i <= 8; ++i) {
        const std::uint32_t scale = kScales[i];
        // The multiples of scale on either side of the float (D may have rounded up across
        // the midpoint between them).
        const std::uint32_t q = d / scale;
        const double toBelow = std::abs(scaled - static_cast<double>(q * scale));
        const double toAbove = static_cast<double>(q * scale + scale) - scaled;
        const bool up = toAbove < toBelow;  // the nearer of the two
        if (!((up ? toAbove : toBelow) < slack)) break;
        best = up ? q + 1 : q;
        kept = i;
    }
    const int count = 9 - kept;
    digits = best;
    if (best == kScales[count]) {  // a carry: 10^count has count + 1 digits
        digits = best / 10;
        ++exponent;
    }
    return count;
}

}  // namespace

char* writeShortFloat(char* p, float value) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    const std::uint32_t biased = (bits >> 23) & 0xFFu;
    const std::uint32_t mantissa = bits & 0x7FFFFFu;
    if (biased == 0) {
        if (mantissa == 0) {  // ±0
            *p++ = '0';
            return p;
        }
        return std::to_chars(p, p + 16, value).ptr;  // subnormals: rare, left to the library
    }
    if (bits >> 31) *p++ = '-';
    const double x = std::bit_cast<double>((std::uint64_t{biased - 127 + 1023} << 52) |
                                           (std::uint64_t{mantissa} << 29));
    const int binaryExponent = static_cast<int>(biased) - 127;  // 2^E ≤ x < 2^(E+1)
    // floor(log10 x) is floor(E·log10 2) or one more.
    int exponent = (binaryExponent * 78913) >> 18;  // floor(E · 0.30103), exact for |E| < 2^10
    double scaled = x * pow10(8 - exponent);
    if (scaled < 99999999.5) {  // the estimate one too high (not seen; kept for safety)
        --exponent;
        scaled = x * pow10(8 - exponent);
    }
    if (scaled >= 999999999.5) {
        ++exponent;
        scaled = x * pow10(8 - exponent);
    }
    auto d = static_cast<std::uint32_t>(scaled + 0.5);
    // Half an ulp of the float in units of D's last digit (a power of two's lower neighbour is
    // half as far).
    const double halfUlp = std::bit_cast<double>(std::uint64_t(binaryExponent - 24 + 1023) << 52) *
                           pow10(8 - exponent) * (mantissa == 0 ? 0.5 : 1.0);
    std::uint32_t digits = 0;
    const int count = shortestRounding(d, scaled, halfUlp - 1e-6, digits, exponent);
    return writeDecimal(p, digits, count, exponent);
}

}  // namespace ramus::detail
