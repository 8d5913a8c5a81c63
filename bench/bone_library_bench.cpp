// Default bone library (seed 000 §5.6): the one-time procedural build per resolution and the
// cached model lookup a skeleton export does per bone.
#include <benchmark/benchmark.h>

#include "ramus/bones.hpp"

namespace {

/// The first call builds and meshes all 18 models; later calls return the cached library, so
/// this runs exactly one iteration per process (run the binary once per resolution to time it
/// cold, e.g. --benchmark_filter=BuiltinBoneLibraryFirstBuild/1).
void BM_BuiltinBoneLibraryFirstBuild(benchmark::State& state) {
    const auto resolution = static_cast<ramus::BoneResolution>(state.range(0));
    for (auto _ : state) {
        benchmark::DoNotOptimize(&ramus::BoneLibrary::builtin(resolution));
    }
}
BENCHMARK(BM_BuiltinBoneLibraryFirstBuild)
    ->Arg(static_cast<int>(ramus::BoneResolution::Low))
    ->Arg(static_cast<int>(ramus::BoneResolution::High))
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

void BM_BuiltinBoneLibraryLookupAllModels(benchmark::State& state) {
    const auto resolution = static_cast<ramus::BoneResolution>(state.range(0));
    const ramus::BoneLibrary& library = ramus::BoneLibrary::builtin(resolution);
    for (auto _ : state) {
        std::size_t triangles = 0;
        for (int k = 0; k < ramus::kBoneModelKindCount; ++k) {
            triangles += library.model(static_cast<ramus::BoneModelKind>(k), resolution)
                             .mesh.triangleCount();
        }
        benchmark::DoNotOptimize(triangles);
    }
}
BENCHMARK(BM_BuiltinBoneLibraryLookupAllModels)
    ->Arg(static_cast<int>(ramus::BoneResolution::Low))
    ->Arg(static_cast<int>(ramus::BoneResolution::High));

}  // namespace
