// Float text for JSON (src/core/float_text.hpp): writeShortest is std::to_chars's shortest
// round-trip text (−0 as "0"), and FloatTextCache writes exactly the same text with or without
// hits — for repeated values, their negations and values whose slots collide.
#include "core/float_text.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "ramus/rng.hpp"

namespace ramus::detail {
namespace {

std::string toChars(float f) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, f).ptr);
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

TEST(FloatText, ShortestIsStdToCharsWithNegativeZeroAsZero) {
    for (float f : sampleFloats()) {
        if (f == 0.0f) continue;
        EXPECT_EQ(shortest(f), toChars(f));
    }
    EXPECT_EQ(shortest(0.0f), "0");
    EXPECT_EQ(shortest(-0.0f), "0");
    EXPECT_EQ(shortest(-42.0f), "-42");
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
        for (float f : values) EXPECT_EQ(cached(cache, f), toChars(f));
    }
}

}  // namespace
}  // namespace ramus::detail
