#include "ramus/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace ramus {
namespace {

TEST(Rng, MatchesThePcg32ReferenceSequence) {
    // pcg32-demo (pcg-c-basic): pcg32_srandom_r(&rng, 42u, 54u) prints these first values.
    Rng rng(42u, 54u);
    const std::uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330,
                                      0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (std::uint32_t e : expected) EXPECT_EQ(rng.nextU32(), e);
}

TEST(Rng, SameSeedGivesSameSequence) {
    Rng a(7, 3), b(7, 3);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(a.nextU32(), b.nextU32());
}

TEST(Rng, SubStreamsDifferAndAreReproducible) {
    Rng a = Rng::forStream(1, 0), b = Rng::forStream(1, 1), c = Rng::forStream(1, 0);
    const std::uint32_t a0 = a.nextU32();
    EXPECT_NE(a0, b.nextU32());
    EXPECT_EQ(a0, c.nextU32());
}

TEST(Rng, Uniform01StaysInHalfOpenUnitInterval) {
    Rng rng(1);
    double sum = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const double u = rng.uniform01();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    EXPECT_NEAR(sum / n, 0.5, 0.01);
}

TEST(Rng, UniformIntCoversTheRangeWithoutGoingPastIt) {
    Rng rng(2);
    std::set<std::uint32_t> seen;
    for (int i = 0; i < 1000; ++i) {
        const std::uint32_t v = rng.uniformInt(6);
        ASSERT_LT(v, 6u);
        seen.insert(v);
    }
    EXPECT_EQ(seen.size(), 6u);
}

TEST(Rng, GaussHasTheRequestedMeanAndDeviation) {
    Rng rng(3);
    const int n = 200000;
    double sum = 0, sumSq = 0;
    for (int i = 0; i < n; ++i) {
        const double x = rng.gauss(2.0, 3.0);
        sum += x;
        sumSq += x * x;
    }
    const double mean = sum / n;
    EXPECT_NEAR(mean, 2.0, 0.05);
    EXPECT_NEAR(std::sqrt(sumSq / n - mean * mean), 3.0, 0.05);
}

}  // namespace
}  // namespace ramus
