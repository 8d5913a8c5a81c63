// Deterministic random numbers: PCG32 (O'Neill 2014, pcg32 "XSH RR" 64/32) with our own
// distributions, so results are identical across standard libraries and platforms.
#pragma once

#include <cstdint>

namespace ramus {

/// 64-bit mix of two values (splitmix64 finaliser); used to derive independent sub-streams.
std::uint64_t hashCombine(std::uint64_t a, std::uint64_t b);

/// PCG32 generator. Cheap to copy; never global — pass it explicitly.
class Rng {
public:
    /// Generator for a seed and a stream selector (any two values give independent sequences).
    explicit Rng(std::uint64_t seed = 0x853c49e6748fea9bULL,
                 std::uint64_t stream = 0xda3e39cb94b95bdbULL);

    /// Independent generator for entity `id` under `seed`: hash(seed, id) picks seed and stream,
    /// so results do not depend on the order entities are processed in.
    static Rng forStream(std::uint64_t seed, std::uint64_t id);

    /// Next uniformly distributed 32-bit value.
    std::uint32_t nextU32();
    /// Uniform in [0, 1) with 53 random bits.
    double uniform01();
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
    /// Uniform integer in [0, bound) without modulo bias; bound must be > 0.
    std::uint32_t uniformInt(std::uint32_t bound);
    /// Normal distribution N(mean, stddev^2) (Box–Muller, one value per call).
    double gauss(double mean = 0.0, double stddev = 1.0);

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 0;
};

}  // namespace ramus
