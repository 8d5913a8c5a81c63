// Based on: M. E. O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation" (2014), pcg32 reference implementation; splitmix64
// finaliser (Steele et al. 2014) for hashing seeds.
#include "ramus/rng.hpp"

#include <cmath>

namespace ramus {

std::uint64_t hashCombine(std::uint64_t a, std::uint64_t b) {
    std::uint64_t z = a + 0x9e3779b97f4a7c15ULL + (b * 0xbf58476d1ce4e5b9ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    // A second round so that nearby (a, b) pairs diverge fully.
    z += b ^ 0x632be59bd9b4e019ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

Rng::Rng(std::uint64_t seed, std::uint64_t stream) {
    inc_ = (stream << 1u) | 1u;
    state_ = 0;
    nextU32();
    state_ += seed;
    nextU32();
}

Rng Rng::forStream(std::uint64_t seed, std::uint64_t id) {
    return Rng(hashCombine(seed, id), hashCombine(id, seed ^ 0x5851f42d4c957f2dULL));
}

std::uint32_t Rng::nextU32() {
    std::uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

double Rng::uniform01() {
    std::uint64_t hi = nextU32() >> 5;  // 27 bits
    std::uint64_t lo = nextU32() >> 6;  // 26 bits
    return static_cast<double>((hi << 26) | lo) * (1.0 / 9007199254740992.0);
}

std::uint32_t Rng::uniformInt(std::uint32_t bound) {
    // Lemire's nearly divisionless method would also do; this is the PCG reference one.
    std::uint32_t threshold = (0u - bound) % bound;
    for (;;) {
        std::uint32_t r = nextU32();
        if (r >= threshold) return r % bound;
    }
}

double Rng::gauss(double mean, double stddev) {
    // Box–Muller; 1 - u keeps the logarithm's argument in (0, 1].
    double u1 = 1.0 - uniform01();
    double u2 = uniform01();
    double radius = std::sqrt(-2.0 * std::log(u1));
    return mean + stddev * radius * std::cos(2.0 * 3.14159265358979323846 * u2);
}

}  // namespace ramus
