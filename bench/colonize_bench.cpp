// Space colonization throughput (issue 3): attraction points doubling from 10k to 1M in a fixed
// spherical crown above a root (d_i = 6·D, d_k = 2·D), one thread. The same tree is grown by
// the brute-force reference (O(points × nodes) per iteration, tests/colonize) on the small
// sizes, side by side. Counters: attractors/s (items), nodes, iterations, and bytes per point
// of the colonizer's own arrays (upper bound from their element sizes).
#include <benchmark/benchmark.h>

#include <vector>

#include "../tests/colonize/brute_force_colonize.cpp"  // the reference, without its test main
#include "ramus/colonize.hpp"
#include "ramus/envelope.hpp"

namespace {

using ramus::ColonizeParams;
using ramus::ColonizeResult;
using ramus::Envelope;
using ramus::Vec3;

// A crown: sphere of radius 50 centred 60 above the root; step D = 1.
struct CrownCase {
    ColonizeParams params;
    std::vector<Vec3> points;
};

CrownCase crownCase(std::int64_t pointCount) {
    CrownCase c;
    c.params.step = 1.0;
    c.params.influenceRadius = 6.0;
    c.params.killRadius = 2.0;
    c.params.maxIterations = 100000;
    Envelope crown;
    crown.shape.kind = ramus::ShapeKind::Sphere;
    crown.shape.radius = 50.0;
    crown.shape.offset = Vec3(0, 60, 0);
    crown.pointCount = static_cast<std::uint32_t>(pointCount);
    crown.seed = 1;
    c.points = ramus::sampleEnvelope(crown, 7);
    return c;
}

void report(benchmark::State& state, const ColonizeResult& r) {
    state.SetItemsProcessed(state.iterations() * state.range(0));
    state.counters["nodes"] = static_cast<double>(r.nodeCount());
    state.counters["iterations"] = r.iterations;
    state.counters["left"] = static_cast<double>(r.attractorsLeft);
}

void BM_Colonize(benchmark::State& state) {
    const CrownCase c = crownCase(state.range(0));
    ColonizeResult result;
    for (auto _ : state) {
        result = ramus::colonize(c.params, c.points);
        benchmark::DoNotOptimize(result.trees.data());
    }
    report(state, result);
    // Per point: position and key (4 floats), owner, original index, two list links = 32
    // bytes; the grid adds 12 bytes per cell, at most one cell per 2 points.
    state.counters["bytes_per_point"] = 32.0 + 12.0 * 0.5;
}
BENCHMARK(BM_Colonize)
    ->Arg(10'000)
    ->Arg(20'000)
    ->Arg(40'000)
    ->Arg(80'000)
    ->Arg(100'000)
    ->Arg(160'000)
    ->Arg(320'000)
    ->Arg(640'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond);

void BM_ColonizeBruteForce(benchmark::State& state) {
    const CrownCase c = crownCase(state.range(0));
    ColonizeResult result;
    for (auto _ : state) {
        result = ramus::testing::bruteForceColonize(c.params, c.points);
        benchmark::DoNotOptimize(result.trees.data());
    }
    report(state, result);
}
BENCHMARK(BM_ColonizeBruteForce)->Arg(10'000)->Arg(20'000)->Unit(benchmark::kMillisecond);

}  // namespace
