// Skeleton generation throughput (issue 5): the whole path of one box skeleton — PCA sample,
// limb layout, grammar, bone placement, leg placement, mirror, box meshes, GLB written to disk
// — and its stages alone. The thesis's Java implementation writes about 390 box skeletons/s
// (as OBJ) on this machine; the target is ≥ 4000/s on one thread, files included.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "ramus/bones.hpp"
#include "ramus/export.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_scene.hpp"

namespace {

const ramus::SkeletonStats& stats() {
    static const ramus::SkeletonStats model = ramus::SkeletonStats::builtin();
    return model;
}

std::string benchDirectory() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ramus_bench";
    std::filesystem::create_directories(dir);
    return dir.string();
}

ramus::SkeletonDesign designFor(std::uint64_t i) {
    ramus::Rng rng = ramus::Rng::forStream(7, i);
    return ramus::designSkeleton(stats(), {}, rng);
}

void BM_SkeletonDesign(benchmark::State& state) {
    std::uint64_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(designFor(i++).featurePoint.data());
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SkeletonDesign);

void BM_SkeletonBuild(benchmark::State& state) {
    std::vector<ramus::SkeletonDesign> designs;
    for (std::uint64_t i = 0; i < 64; ++i) designs.push_back(designFor(i));
    std::size_t i = 0;
    for (auto _ : state) {
        const ramus::Skeleton s = ramus::buildSkeleton(designs[i++ % designs.size()]);
        benchmark::DoNotOptimize(s.bones.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SkeletonBuild);

void BM_SkeletonToGlbBytes(benchmark::State& state) {
    std::vector<ramus::Skeleton> skeletons;
    for (std::uint64_t i = 0; i < 64; ++i) skeletons.push_back(ramus::buildSkeleton(designFor(i)));
    std::size_t i = 0;
    for (auto _ : state) {
        const ramus::Scene scene = ramus::skeletonToScene(skeletons[i++ % skeletons.size()], {});
        const std::string glb = ramus::encodeGlb(scene);
        benchmark::DoNotOptimize(glb.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SkeletonToGlbBytes);

/// Directories the end-to-end runs wrote, removed when the process ends: removing them between
/// runs would slow the next runs' file creation — on a journal-less ext4 (as on this machine)
/// the kernel skips inodes freed in the last seconds to minutes when it allocates a new one
/// (ext4 recently_deleted), so every create after a mass delete scans them.
struct OutputDirectories {
    std::vector<std::filesystem::path> paths;
    ~OutputDirectories() {
        for (const auto& path : paths) std::filesystem::remove_all(path);
    }
};
OutputDirectories& outputDirectories() {
    static OutputDirectories directories;
    return directories;
}

/// A new directory for one end-to-end run (kept until the process ends, see above); returns the
/// file name prefix inside it.
std::string newOutputPrefix() {
    OutputDirectories& directories = outputDirectories();
    const std::filesystem::path dir = std::filesystem::path(benchDirectory()) /
                                      ("end_to_end_" + std::to_string(directories.paths.size()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    directories.paths.push_back(dir);
    return (dir / "skeleton").string();
}

/// Skeleton i of the stream, from its PCA sample to its GLB file `prefix<i>.glb`.
void writeSkeletonGlb(std::uint64_t i, ramus::BoneResolution resolution,
                      const std::string& prefix) {
    const ramus::SkeletonDesign design = designFor(i);
    const ramus::Skeleton s = ramus::buildSkeleton(design);
    ramus::writeGlb(ramus::skeletonSceneAt(s, resolution, design.headKind),
                    prefix + std::to_string(i) + ".glb");
}

/// The whole path with the file written: every skeleton gets its own new file in a new
/// directory, as in a batch (overwriting one file instead would add the cost of freeing the old
/// file's blocks and inode, which a batch never pays).
/// Arg: the resolution (0 box, 1 low, 2 high; issue 6 targets ≥ 300 low and ≥ 50 high per
/// second); the bone library is built before timing (once per process, as in a batch).
void BM_SkeletonEndToEndGlbFile(benchmark::State& state) {
    const auto resolution = static_cast<ramus::BoneResolution>(state.range(0));
    if (resolution != ramus::BoneResolution::Box) (void)ramus::BoneLibrary::builtin(resolution);
    const std::string prefix = newOutputPrefix();
    std::uint64_t i = 0;
    for (auto _ : state) writeSkeletonGlb(i++, resolution, prefix);
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(std::string(ramus::boneResolutionName(resolution)));
}
BENCHMARK(BM_SkeletonEndToEndGlbFile)->Arg(0)->Arg(1)->Arg(2);

/// The thesis's own measurement (seed 000's built-in timer: 1 000 box skeletons written in
/// 2.6 s): one batch of 1 000 box skeletons into a new directory per iteration, wall time.
/// Files of earlier batches stay (see OutputDirectories), so repetitions do not reuse the
/// memory a deleted batch freed. Run with --benchmark_repetitions=N for N batches in a row.
void BM_SkeletonBatch1000GlbFiles(benchmark::State& state) {
    constexpr std::uint64_t kBatch = 1000;
    std::uint64_t first = 0;
    for (auto _ : state) {
        const std::string prefix = newOutputPrefix();
        for (std::uint64_t i = first; i < first + kBatch; ++i)
            writeSkeletonGlb(i, ramus::BoneResolution::Box, prefix);
        first += kBatch;
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(first));
}
BENCHMARK(BM_SkeletonBatch1000GlbFiles)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
