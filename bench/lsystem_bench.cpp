// L-system benchmarks: derivation throughput (non-parametric ABOP 1.24f, parametric ABOP 2.6a,
// context-sensitive ABOP 1.31a) at doubling sizes, turtle + tube mesher throughput, and the
// memory one module costs. bench/peers/run.sh runs the derivation cases side by side with the
// npm package `lindenmayer`; figures are in docs/BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "ramus/lsystem.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/turtle.hpp"

namespace {

using ramus::DeriveOptions;
using ramus::LSystem;
using ramus::ModuleString;

LSystem loadExample(const std::string& file) {
    return ramus::loadLSystem(std::string(RAMUS_SOURCE_DIR) + "/examples/lsystems/" + file);
}

ModuleString deriveExample(const LSystem& system, std::int64_t derivations) {
    DeriveOptions options;
    options.derivations = static_cast<int>(derivations);
    return ramus::deriveLSystem(system, options);
}

// Derivation of `file` to n = state.range(0) steps, the word freed inside the timed loop.
// Counters: modules (word length), modules/s, and time/module (seconds per module, to show
// that the context-sensitive search stays linear as the word grows).
void BM_Derive(benchmark::State& state, const char* file) {
    const LSystem system = loadExample(file);
    std::size_t modules = 0;
    for (auto _ : state) {
        ModuleString word = deriveExample(system, state.range(0));
        modules = word.size();
        benchmark::DoNotOptimize(word.modules.data());
        benchmark::ClobberMemory();
    }
    const auto count = static_cast<double>(modules);
    state.SetItemsProcessed(static_cast<std::int64_t>(modules) * state.iterations());
    state.counters["modules"] = count;
    state.counters["modules/s"] =
        benchmark::Counter(count, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["time/module"] = benchmark::Counter(
        count, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(BM_Derive, abop_1_24f, "abop_1_24f.lsys")
    ->DenseRange(6, 10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Derive, abop_2_6a, "abop_2_6a.lsys")
    ->DenseRange(10, 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Derive, abop_1_31a, "abop_1_31a.lsys")
    ->Arg(10)
    ->Arg(20)
    ->Arg(30)
    ->Arg(40)
    ->Unit(benchmark::kMicrosecond);

// Turtle interpretation alone and turtle + tube mesh of a derived word; one segment = one
// drawn edge of the tree. The word is derived once, outside the timed loop.
void BM_Turtle(benchmark::State& state, const char* file) {
    const LSystem system = loadExample(file);
    const ModuleString word = deriveExample(system, state.range(0));
    const ramus::TurtleParams params = ramus::turtleParamsFrom(system.settings);
    std::size_t segments = 0;
    for (auto _ : state) {
        const ramus::TurtleResult turtle = ramus::interpretTurtle(word, system.symbols, params);
        segments = turtle.tree.edgeCount();
        benchmark::DoNotOptimize(turtle.tree.nodes().data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(segments) * state.iterations());
    state.counters["segments"] = static_cast<double>(segments);
    state.counters["segments/s"] = benchmark::Counter(
        static_cast<double>(segments), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_TurtleAndMesh(benchmark::State& state, const char* file) {
    const LSystem system = loadExample(file);
    const ModuleString word = deriveExample(system, state.range(0));
    const ramus::TurtleParams params = ramus::turtleParamsFrom(system.settings);
    std::size_t segments = 0, triangles = 0;
    for (auto _ : state) {
        const ramus::TurtleResult turtle = ramus::interpretTurtle(word, system.symbols, params);
        const ramus::Mesh mesh = ramus::buildTubeMesh(turtle.tree);
        segments = turtle.tree.edgeCount();
        triangles = mesh.triangleCount();
        benchmark::DoNotOptimize(mesh.positions.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(segments) * state.iterations());
    state.counters["segments"] = static_cast<double>(segments);
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["segments/s"] = benchmark::Counter(
        static_cast<double>(segments), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK_CAPTURE(BM_Turtle, tree_3d, "tree_3d.lsys")
    ->Arg(8)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Turtle, abop_1_24f, "abop_1_24f.lsys")
    ->Arg(8)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TurtleAndMesh, tree_3d, "tree_3d.lsys")
    ->Arg(8)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TurtleAndMesh, abop_1_24f, "abop_1_24f.lsys")
    ->Arg(8)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);

// Resident set size of this process in bytes (Linux /proc/self/statm), 0 where unavailable.
double residentBytes() {
    std::ifstream statm("/proc/self/statm");
    double totalPages = 0.0, residentPages = 0.0;
    if (!(statm >> totalPages >> residentPages)) return 0.0;
    return residentPages * 4096.0;
}

// Memory per module of a derived word: sizeof(Module); the bytes the word's modules and
// parameters occupy ("used"); what its arrays reserve (capacity × element size, growth slack
// included); and how much the process' resident memory grows while the word is alive
// ("resident": pages actually touched — the deriver over-reserves address space, which costs
// nothing until written; 0 when the allocator reuses pages that were already resident).
void BM_ModuleMemory(benchmark::State& state, const char* file) {
    const LSystem system = loadExample(file);
    std::size_t reserved = 0, used = 0, modules = 0;
    double resident = 0.0;
    for (auto _ : state) {
        const double before = residentBytes();
        ModuleString word = deriveExample(system, state.range(0));
        resident = residentBytes() - before;
        modules = word.size();
        reserved = word.modules.capacity() * sizeof(ramus::Module) +
                   word.params.capacity() * sizeof(double);
        used = word.modules.size() * sizeof(ramus::Module) + word.params.size() * sizeof(double);
        benchmark::DoNotOptimize(word.modules.data());
    }
    const double count = static_cast<double>(modules == 0 ? 1 : modules);
    state.counters["modules"] = static_cast<double>(modules);
    state.counters["sizeof(Module)"] = static_cast<double>(sizeof(ramus::Module));
    state.counters["used bytes/module"] = static_cast<double>(used) / count;
    state.counters["reserved bytes/module"] = static_cast<double>(reserved) / count;
    state.counters["resident bytes/module"] = resident / count;
}

BENCHMARK_CAPTURE(BM_ModuleMemory, abop_1_24f, "abop_1_24f.lsys")
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModuleMemory, abop_2_6a, "abop_2_6a.lsys")
    ->Arg(16)
    ->Unit(benchmark::kMillisecond);

}  // namespace
