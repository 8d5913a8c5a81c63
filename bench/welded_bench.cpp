// Welded mesher throughput (issue 9: ≥ 1 M triangles/s on one thread) on the synthetic trees of
// mesh_bench.cpp at doubling sizes (16k … 1M edges), the tube mesher on the same trees for
// comparison, and on the shipped L-system tree_3d at 5 … 8 derivations. Counters as
// mesh_bench.cpp, plus the junction count.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "bench_trees.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/turtle.hpp"
#include "ramus/welded_mesher.hpp"

namespace {

using ramus::BranchTree;

void BM_WeldedMesh(benchmark::State& state, BranchTree (*makeTree)(std::int64_t)) {
    const BranchTree tree = makeTree(state.range(0));
    ramus::Mesh mesh;
    ramus::WeldReport report;
    for (auto _ : state) {
        mesh = ramus::buildWeldedTreeMesh(tree, {}, &report);
        benchmark::DoNotOptimize(mesh.positions.data());
        benchmark::ClobberMemory();
    }
    ramus::bench::reportMesh(state, tree, mesh);
    state.counters["junctions"] = static_cast<double>(report.junctions);
}

BENCHMARK_CAPTURE(BM_WeldedMesh, binary, ramus::bench::binaryTree)
    ->RangeMultiplier(2)
    ->Range(1 << 14, 1 << 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WeldedMesh, monopodial, ramus::bench::monopodialTree)
    ->RangeMultiplier(2)
    ->Range(1 << 14, 1 << 20)
    ->Unit(benchmark::kMillisecond);

BranchTree tree3d(std::int64_t derivations) {
    const ramus::LSystem system =
        ramus::loadLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/tree_3d.lsys");
    ramus::DeriveOptions options;
    options.derivations = static_cast<int>(derivations);
    const ramus::ModuleString word = ramus::deriveLSystem(system, options);
    return ramus::interpretTurtle(word, system.symbols, ramus::turtleParamsFrom(system.settings))
        .tree;
}

BENCHMARK_CAPTURE(BM_WeldedMesh, tree_3d, tree3d)->DenseRange(5, 8)->Unit(benchmark::kMillisecond);

}  // namespace
