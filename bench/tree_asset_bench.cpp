// Tree assets on a large monopodial tree (chains of 8 internodes with random laterals, like
// bench/mesh_bench.cpp's; 64k … 512k edges): tubes alone, tubes with wind attributes, leaves
// with wind (3 per tip + 4 per unit length near tips), the whole asset mesh, and three LODs
// (1, 0.4, 0.15). Counters: triangles/s of the output and its triangle count.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "bench_trees.hpp"
#include "ramus/leaves.hpp"
#include "ramus/rng.hpp"
#include "ramus/tree_asset.hpp"
#include "ramus/tube_mesher.hpp"

namespace {

using ramus::BranchTree;
using ramus::NodeId;
using ramus::Vec3;

using ramus::bench::monopodialTree;

ramus::TreeMeshParams assetParams(bool wind) {
    ramus::TreeMeshParams p;
    p.tube.windAttributes = wind;
    p.leaves = true;
    p.leaf.size = 0.15;
    p.leaf.perLength = 4.0;
    p.leaf.zone = 0.6;
    return p;
}

void report(benchmark::State& state, const ramus::Mesh& mesh) {
    const auto triangles = static_cast<double>(mesh.triangleCount());
    state.counters["triangles"] = triangles;
    state.counters["triangles/s"] =
        benchmark::Counter(triangles, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_TubesWind(benchmark::State& state, bool wind) {
    const BranchTree tree = monopodialTree(state.range(0));
    ramus::TubeMeshParams params;
    params.windAttributes = wind;
    ramus::Mesh mesh;
    for (auto _ : state) {
        mesh = ramus::buildTubeMesh(tree, params);
        benchmark::DoNotOptimize(mesh.positions.data());
    }
    report(state, mesh);
}
BENCHMARK_CAPTURE(BM_TubesWind, plain, false)
    ->RangeMultiplier(2)
    ->Range(1 << 16, 1 << 19)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TubesWind, wind, true)
    ->RangeMultiplier(2)
    ->Range(1 << 16, 1 << 19)
    ->Unit(benchmark::kMillisecond);

void BM_LeavesWind(benchmark::State& state) {
    const BranchTree tree = monopodialTree(state.range(0));
    const ramus::TreeMeshParams params = assetParams(true);
    ramus::Mesh mesh;
    for (auto _ : state) {
        mesh = ramus::buildLeafMesh(tree, params.leaf, params.tube);
        benchmark::DoNotOptimize(mesh.positions.data());
    }
    state.counters["leaves"] = static_cast<double>(mesh.triangleCount() / 12);
    report(state, mesh);
}
BENCHMARK(BM_LeavesWind)
    ->RangeMultiplier(2)
    ->Range(1 << 16, 1 << 19)
    ->Unit(benchmark::kMillisecond);

void BM_TreeAsset(benchmark::State& state) {
    const BranchTree tree = monopodialTree(state.range(0));
    const ramus::TreeMeshInput input{&tree, {}, {}, {}};
    const ramus::TreeMeshParams params = assetParams(true);
    ramus::Mesh mesh;
    for (auto _ : state) {
        mesh = ramus::buildTreeMesh({&input, 1}, params);
        benchmark::DoNotOptimize(mesh.positions.data());
    }
    report(state, mesh);
}
BENCHMARK(BM_TreeAsset)->Arg(1 << 16)->Arg(1 << 19)->Unit(benchmark::kMillisecond);

void BM_TreeLods(benchmark::State& state) {
    const BranchTree tree = monopodialTree(state.range(0));
    const ramus::TreeMeshInput input{&tree, {}, {}, {}};
    const ramus::TreeMeshParams params = assetParams(true);
    const double ratios[] = {1.0, 0.4, 0.15};
    std::size_t triangles = 0;
    for (auto _ : state) {
        const auto lods = ramus::buildTreeLods({&input, 1}, params, ratios);
        triangles = 0;
        for (const auto& lod : lods) triangles += lod.mesh.triangleCount();
        benchmark::DoNotOptimize(triangles);
    }
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["triangles/s"] = benchmark::Counter(
        static_cast<double>(triangles), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TreeLods)->Arg(1 << 16)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
