// Float text for JSON (src/core/float_text.hpp): writeShortFloat's text reads back as the same
// float (strtof, correctly rounded) with exactly the shortest digits (std::to_chars, scientific);
// writeShortest adds integers for small whole numbers and "0" for −0; FloatTextCache writes exactly
// the same text with or without hits — for repeated values, their negations and values whose slots
// collide. (Every one of the 2^32 bit patterns was checked once against strtof and
// std::to_chars with a throwaway program: docs/BENCHMARKS.md, session 9.)
#include "core/float_text.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus::detail {
namespace {

std::string toChars(float f) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, f).ptr);
}

// Scientific to_chars has the shortest digits always; plain to_chars writes whole numbers in
// fixed notation with all their digits (33554448, where the shortest is 3.355445e7).
std::string toCharsScientific(float f) {
    char buffer[32];
    return std::string(
        buffer,
        std::to_chars(buffer, buffer + sizeof buffer, f, std::chars_format::scientific).ptr);
}

std::string shortest(float f) {
    char buffer[32];
    return std::string(buffer, writeShortest(buffer, buffer + sizeof buffer, f));
}

std::string cached(FloatTextCache& cache, float f) {
    char buffer[32];
    return std::string(buffer, cache.write(buffer, buffer + sizeof buffer, f));
}

std::vector<float> sampleFloats() {
    std::vector<float> values = {0.0f,   -0.0f,       1.0f, -1.0f,           0.1f,
                                 999.0f, 1000.0f,     1e6f, 1.17549435e-38f, 3.40282347e38f,
                                 1e-45f, 0.026422560f};
    Rng rng(5);
    for (int i = 0; i < 3000; ++i) {
        values.push_back(
            static_cast<float>(rng.uniform(-1.0, 1.0) * std::pow(10.0, rng.uniform(-40.0, 38.0))));
    }
    return values;
}

std::string shortFloat(float f) {
    char buffer[32];
    return std::string(buffer, writeShortFloat(buffer, f));
}

// The significant digits of a decimal text: without sign, point, leading zeros and exponent.
std::string significantDigits(const std::string& text) {
    std::string digits;
    for (char c : text) {
        if (c == 'e') break;
        if (c >= '0' && c <= '9' && !(digits.empty() && c == '0')) digits += c;
    }
    while (!digits.empty() && digits.back() == '0') digits.pop_back();  // 1000 → 1
    return digits;
}

// Reads back as f, and has exactly scientific std::to_chars's shortest digits (Dragonbox and
// to_chars both pick the nearest of the shortest decimals); fixed or scientific may differ, and so
// may the length by at most the 3 characters that fixed notation may add.
void expectShortRoundTrip(float f) {
    const std::string text = shortFloat(f);
    const float back = std::strtof(text.c_str(), nullptr);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(back), std::bit_cast<std::uint32_t>(f))
        << text << " for " << toChars(f);
    EXPECT_EQ(significantDigits(text), significantDigits(toCharsScientific(f)))
        << text << " for " << toCharsScientific(f);
    EXPECT_LE(text.size(), toChars(f).size() + 3) << text << " for " << toChars(f);
}

TEST(FloatText, ShortFloatsReadBackAsTheSameFloat) {
    for (float f : sampleFloats()) {
        if (f != 0.0f) expectShortRoundTrip(f);
    }
    // Every power of two (their lower neighbour is half as far), the binades' last floats, and
    // the values next to powers of ten (where rounding carries: 9.9999999 → 10).
    for (int e = -126; e <= 127; ++e) {
        const float p = std::ldexp(1.0f, e);
        expectShortRoundTrip(p);
        expectShortRoundTrip(-p);
        expectShortRoundTrip(std::nextafter(p, 0.0f));
        expectShortRoundTrip(std::nextafter(p, INFINITY));
    }
    for (int e = -37; e <= 38; ++e) {
        float p = static_cast<float>(std::pow(10.0, e));
        for (int k = 0; k < 40; ++k) {
            expectShortRoundTrip(p);
            p = std::nextafter(p, 0.0f);
        }
        p = static_cast<float>(std::pow(10.0, e));
        for (int k = 0; k < 40; ++k) {
            expectShortRoundTrip(p);
            p = std::nextafter(p, INFINITY);
        }
    }
    // Every float in [1, 1 + 2^-7) and in a band around 0.1.
    for (std::uint32_t bits = 0x3F800000u; bits < 0x3F810000u; ++bits) {
        expectShortRoundTrip(std::bit_cast<float>(bits));
    }
    for (std::uint32_t bits = 0x3DCC0000u; bits < 0x3DCD0000u; ++bits) {
        expectShortRoundTrip(std::bit_cast<float>(bits));
    }
    // Subnormals: the smallest, the largest and every 4099th between.
    for (std::uint32_t bits = 1; bits < 0x00800000u; bits += 4099) {
        expectShortRoundTrip(std::bit_cast<float>(bits));
        expectShortRoundTrip(-std::bit_cast<float>(bits));
    }
    expectShortRoundTrip(std::bit_cast<float>(0x007FFFFFu));
    Rng rng(9);
    for (int i = 0; i < 200000; ++i) {  // random bit patterns: all exponents alike
        const auto bits = static_cast<std::uint32_t>(rng.uniform(0.0, 4294967296.0));
        const float f = std::bit_cast<float>(bits);
        if (std::isfinite(f) && f != 0.0f) expectShortRoundTrip(f);
    }
}

TEST(FloatText, ShortFloatTexts) {
    EXPECT_EQ(shortFloat(0.1f), "0.1");
    EXPECT_EQ(shortFloat(0.7f), "0.7");
    EXPECT_EQ(shortFloat(-2.5f), "-2.5");
    EXPECT_EQ(shortFloat(0.026422560f), "0.02642256");
    EXPECT_EQ(shortFloat(1e-8f), "1e-8");
    EXPECT_EQ(shortFloat(1.5e20f), "1.5e20");
    EXPECT_EQ(shortFloat(123456.0f), "123456");
    EXPECT_EQ(shortFloat(1e6f), "1e6");
    EXPECT_EQ(shortFloat(3.40282347e38f), "3.4028235e38");
    EXPECT_EQ(shortFloat(1000.0f), "1000");
    EXPECT_EQ(shortFloat(0.001f), "0.001");
    EXPECT_EQ(shortFloat(0.0f), "0");
    EXPECT_EQ(shortFloat(-0.0f), "0");
    EXPECT_EQ(shortFloat(std::nextafter(10.0f, 0.0f)), "9.999999");
    EXPECT_EQ(shortFloat(1e-45f), "1e-45");                     // the smallest subnormal
    EXPECT_EQ(shortFloat(-1.17549421e-38f), "-1.1754942e-38");  // the largest subnormal
    // The shortest digits padded with a zero, not plain to_chars's exact 33554448.
    EXPECT_EQ(shortFloat(33554448.0f), "33554450");
}

TEST(FloatText, ShortestWritesSmallWholeNumbersAsIntegers) {
    EXPECT_EQ(shortest(0.0f), "0");
    EXPECT_EQ(shortest(-0.0f), "0");
    EXPECT_EQ(shortest(-42.0f), "-42");
    EXPECT_EQ(shortest(999.0f), "999");
    EXPECT_EQ(shortest(0.25f), "0.25");
    for (float f : sampleFloats()) {
        if (!isSmallWholeNumber(f)) EXPECT_EQ(shortest(f), shortFloat(f));
    }
}

TEST(FloatText, CacheWritesTheSameTextOnMissesAndHits) {
    FloatTextCache cache;
    const std::vector<float> values = sampleFloats();
    for (int pass = 0; pass < 3; ++pass) {  // the second and third passes hit where not evicted
        for (float f : values) {
            EXPECT_EQ(cached(cache, f), shortest(f)) << f;
            EXPECT_EQ(cached(cache, -f), shortest(-f)) << -f;
        }
    }
}

// Values a table slot apart share a slot: a hit needs the same bits, never just the same slot.
TEST(FloatText, CollidingValuesKeepTheirOwnText) {
    FloatTextCache cache;
    std::vector<float> values;
    for (std::uint32_t k = 0; k < 4096; ++k) {
        values.push_back(std::bit_cast<float>(0x3F800001u + k));  // just above 1, one ulp apart
    }
    for (int pass = 0; pass < 2; ++pass) {
        for (float f : values) EXPECT_EQ(cached(cache, f), shortFloat(f));
    }
}

// The cache copies whole slots (fixed-size copies, no `rep movsq`): in a buffer of exactly the
// documented 16 bytes the longest texts, signed, on a miss and on a hit, stay inside it (a
// heap buffer, so AddressSanitizer in `make test` sees any byte past it) and come out whole.
TEST(FloatText, CacheWritesWithinSixteenBytes) {
    FloatTextCache cache;
    const std::unique_ptr<char[]> buffer(new char[16]);
    for (float f : {-1.17549435e-38f, -3.40282347e38f, -0.000123456789f, -1.5e-45f, 0.1f}) {
        for (int pass = 0; pass < 2; ++pass) {
            char* end = cache.write(buffer.get(), buffer.get() + 16, f);
            ASSERT_LE(end - buffer.get(), 16);
            EXPECT_EQ(std::string(buffer.get(), end), shortest(f)) << f;
        }
    }
}

}  // namespace
}  // namespace ramus::detail
