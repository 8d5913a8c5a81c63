// Tube mesher throughput on synthetic trees of doubling size (16k … 1M edges): a full binary
// tree (every node forks: many short chains) and a monopodial tree (chains of 8 internodes with
// random laterals, closer to L-system and space-colonization output). Counters: edges/s
// (items), triangles/s, vertices and triangles per edge. The leaf polygon mesher is measured
// on random convex and concave leaves.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "bench_trees.hpp"
#include "ramus/rng.hpp"
#include "ramus/tube_mesher.hpp"

namespace {

using ramus::BranchTree;
using ramus::Vec3;
using ramus::bench::binaryTree;
using ramus::bench::monopodialTree;
using ramus::bench::reportMesh;

void BM_TubeMesh(benchmark::State& state, BranchTree (*makeTree)(std::int64_t),
                 double curveReduction) {
    const BranchTree tree = makeTree(state.range(0));
    ramus::TubeMeshParams params;
    params.curveReduction = curveReduction;
    ramus::Mesh mesh;
    for (auto _ : state) {
        mesh = ramus::buildTubeMesh(tree, params);
        benchmark::DoNotOptimize(mesh.positions.data());
        benchmark::ClobberMemory();
    }
    reportMesh(state, tree, mesh);
}

BENCHMARK_CAPTURE(BM_TubeMesh, binary, binaryTree, 0.0)
    ->RangeMultiplier(2)
    ->Range(1 << 14, 1 << 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TubeMesh, monopodial, monopodialTree, 0.0)
    ->RangeMultiplier(2)
    ->Range(1 << 14, 1 << 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TubeMesh, monopodial_reduced, monopodialTree, 0.995)
    ->Arg(1 << 20)
    ->Unit(benchmark::kMillisecond);

// Leaves: n random polygons of 4 … 9 vertices around a circle with a radial jitter that makes
// about half of them concave.
void BM_PolygonMesh(benchmark::State& state) {
    ramus::Rng rng(3);
    std::vector<Vec3> vertices;
    std::vector<std::uint32_t> offsets{0};
    for (std::int64_t p = 0; p < state.range(0); ++p) {
        const int n = 4 + static_cast<int>(rng.uniformInt(6));
        const Vec3 centre(rng.uniform(-10, 10), rng.uniform(0, 10), rng.uniform(-10, 10));
        for (int i = 0; i < n; ++i) {
            const double a = 2.0 * ramus::kPi * i / n;
            const double r = 0.1 * rng.uniform(0.4, 1.0);
            vertices.push_back(centre + Vec3(r * std::cos(a), r * std::sin(a), 0.01 * r));
        }
        offsets.push_back(static_cast<std::uint32_t>(vertices.size()));
    }
    ramus::Mesh mesh;
    for (auto _ : state) {
        mesh = ramus::buildPolygonMesh(vertices, offsets);
        benchmark::DoNotOptimize(mesh.positions.data());
    }
    state.SetItemsProcessed(state.range(0) * state.iterations());
    state.counters["triangles/s"] = benchmark::Counter(
        static_cast<double>(mesh.triangleCount()), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BM_PolygonMesh)->Arg(1 << 16)->Unit(benchmark::kMillisecond);

}  // namespace
