// Welded mesher throughput (issue 9: ≥ 1 M triangles/s) on the synthetic trees of
// mesh_bench.cpp at doubling sizes (16k … 1M edges), the tube mesher on the same trees for
// comparison, on the shipped L-system tree_3d at 5 … 8 derivations and on the slowest ABOP
// plants. Wall-clock time (UseRealTime): the shrunk junctions' rays run on the machine's cores
// (up to 4), so CPU time of the main thread alone would flatter. Counters as mesh_bench.cpp,
// plus the junction count. BM_WeldedUnion: welding plus the solid union (--union) on tree_3d and
// on the dense ABOP 1.24b, with the union's result counters.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "bench_trees.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/turtle.hpp"
#include "ramus/welded_mesher.hpp"

namespace {

using ramus::BranchTree;

void weldRepeatedly(benchmark::State& state, const BranchTree& tree) {
    ramus::Mesh mesh;
    ramus::WeldReport report;
    for (auto _ : state) {
        mesh = ramus::buildWeldedTreeMesh(tree, {}, &report);
        benchmark::DoNotOptimize(mesh.positions.data());
        benchmark::ClobberMemory();
    }
    ramus::bench::reportMesh(state, tree, mesh);
    state.counters["junctions"] = static_cast<double>(report.junctions);
    state.counters["shrunk"] = static_cast<double>(report.refinedJunctions);
}

void BM_WeldedMesh(benchmark::State& state, BranchTree (*makeTree)(std::int64_t)) {
    weldRepeatedly(state, makeTree(state.range(0)));
}

BENCHMARK_CAPTURE(BM_WeldedMesh, binary, ramus::bench::binaryTree)
    ->RangeMultiplier(2)
    ->Range(1 << 14, 1 << 20)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_WeldedMesh, monopodial, ramus::bench::monopodialTree)
    ->RangeMultiplier(2)
    ->Range(1 << 14, 1 << 20)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A shipped L-system example; derivations < 0: the file's own.
BranchTree example(const char* name, std::int64_t derivations) {
    const ramus::LSystem system =
        ramus::loadLSystem(std::string(RAMUS_SOURCE_DIR) + "/examples/lsystems/" + name + ".lsys");
    ramus::DeriveOptions options;
    options.derivations = static_cast<int>(derivations);
    const ramus::ModuleString word = ramus::deriveLSystem(system, options);
    return ramus::interpretTurtle(word, system.symbols, ramus::turtleParamsFrom(system.settings))
        .tree;
}

BranchTree tree3d(std::int64_t derivations) { return example("tree_3d", derivations); }

BENCHMARK_CAPTURE(BM_WeldedMesh, tree_3d, tree3d)
    ->DenseRange(5, 8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The slowest ABOP plants to weld, at their own derivations: radii far above their internodes
// near the base (1.24a–c, 1.27, 1.31a) or many branches at small angles (2.8a, 2.8d), so many
// junctions are shrunk (docs/welded.md, "Shrunk junctions").
void BM_WeldedExample(benchmark::State& state, const char* name) {
    weldRepeatedly(state, example(name, -1));
}
// Registered in a loop (names BM_WeldedExample/<example>), one per plant.
const bool kWeldedExamplesRegistered = [] {
    for (const char* name : {"abop_1_24a", "abop_1_24b", "abop_1_24c", "abop_1_27", "abop_1_31a",
                             "abop_2_8a", "abop_2_8d"}) {
        benchmark::RegisterBenchmark(("BM_WeldedExample/" + std::string(name)).c_str(),
                                     BM_WeldedExample, name)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    return true;
}();

// triangles/s counts the welded mesh's triangles (the union's input).
void BM_WeldedUnion(benchmark::State& state, const char* name) {
    const BranchTree tree = example(name, state.range(0));
    const ramus::Mesh welded = ramus::buildWeldedTreeMesh(tree);
    ramus::WeldedMeshParams params;
    params.solidUnion = true;
    ramus::Mesh mesh;
    ramus::WeldReport report;
    for (auto _ : state) {
        mesh = ramus::buildWeldedTreeMesh(tree, params, &report);
        benchmark::DoNotOptimize(mesh.positions.data());
        benchmark::ClobberMemory();
    }
    ramus::bench::reportMesh(state, tree, welded);
    const ramus::SolidUnionReport& u = report.solidUnion;
    state.counters["applied"] = u.applied ? 1.0 : 0.0;
    state.counters["pieces_in"] = static_cast<double>(u.inputComponents);
    state.counters["pieces_out"] = static_cast<double>(u.outputComponents);
    state.counters["crossings_left"] = static_cast<double>(u.remainingIntersections);
    state.counters["attempts"] = static_cast<double>(u.attempts);
}

BENCHMARK_CAPTURE(BM_WeldedUnion, tree_3d, "tree_3d")
    ->DenseRange(5, 8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_WeldedUnion, abop_1_24b, "abop_1_24b")
    ->Arg(-1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
