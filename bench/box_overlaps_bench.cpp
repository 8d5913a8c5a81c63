// The solid union's broad phase (src/mesh/box_overlaps.cpp) on the boxes of real meshes: the
// triangles of the welded tree_3d and ABOP 1.24a (the union's self-intersection search: every
// pair of overlapping boxes) and the same with a few suspects (the crossing count after the
// repair's moves: only pairs with a suspect). The filter accepts nothing, so this times the search
// alone. BM_BoxTree: building the box tree (src/mesh/box_tree.hpp) over the same boxes, as the
// crossing repair and the winding numbers' rays do.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/box_overlaps.hpp"
#include "mesh/box_tree.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/turtle.hpp"
#include "ramus/welded_mesher.hpp"

namespace {

using ramus::detail::Box3;

std::vector<Box3> weldedTriangleBoxes(const char* name) {
    const ramus::LSystem system =
        ramus::loadLSystem(std::string(RAMUS_SOURCE_DIR) + "/examples/lsystems/" + name + ".lsys");
    const ramus::ModuleString word = ramus::deriveLSystem(system, {});
    const ramus::Mesh mesh = ramus::buildWeldedTreeMesh(
        ramus::interpretTurtle(word, system.symbols, ramus::turtleParamsFrom(system.settings))
            .tree);
    std::vector<Box3> boxes(mesh.triangleCount());
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const ramus::Vec3f& p = mesh.positions[mesh.indices[c]];
        boxes[c / 3].add({p.x(), p.y(), p.z()});
    }
    return boxes;
}

// state.range(0): one suspect in every that many boxes; 0: no suspects (every pair).
void BM_BoxOverlaps(benchmark::State& state, const char* name) {
    const std::vector<Box3> boxes = weldedTriangleBoxes(name);
    std::vector<char> suspect;
    if (state.range(0) > 0) {
        suspect.assign(boxes.size(), 0);
        for (std::size_t i = 0; i < boxes.size(); i += static_cast<std::size_t>(state.range(0))) {
            suspect[i] = 1;
        }
    }
    for (auto _ : state) {
        const auto found = ramus::detail::overlappingBoxes(
            boxes, suspect, [&](std::uint32_t, std::uint32_t) { return false; });
        benchmark::DoNotOptimize(found.data());
    }
    state.counters["boxes"] = static_cast<double>(boxes.size());
    state.counters["boxes/s"] = benchmark::Counter(
        static_cast<double>(boxes.size()) * static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate);
}

void BM_BoxTree(benchmark::State& state, const char* name) {
    const std::vector<Box3> boxes = weldedTriangleBoxes(name);
    for (auto _ : state) {
        const ramus::detail::BoxTree tree(boxes);
        benchmark::DoNotOptimize(&tree);
    }
    state.counters["boxes"] = static_cast<double>(boxes.size());
    state.counters["boxes/s"] = benchmark::Counter(
        static_cast<double>(boxes.size()) * static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(BM_BoxTree, tree_3d, "tree_3d")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_BoxTree, abop_1_24a, "abop_1_24a")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_CAPTURE(BM_BoxOverlaps, tree_3d, "tree_3d")
    ->Arg(0)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_BoxOverlaps, abop_1_24a, "abop_1_24a")
    ->Arg(0)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
