// Tube mesher throughput on synthetic trees of doubling size (16k … 1M edges): a full binary
// tree (every node forks: many short chains) and a monopodial tree (chains of 8 internodes with
// random laterals, closer to L-system and space-colonization output). Counters: edges/s
// (items), triangles/s, vertices and triangles per edge. The leaf polygon mesher is measured
// on random convex and concave leaves.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "ramus/rng.hpp"
#include "ramus/tube_mesher.hpp"

namespace {

using ramus::BranchTree;
using ramus::NodeId;
using ramus::Vec3;

// Breadth-first full binary tree with `edges` edges (rounded down to whole levels' worth).
BranchTree binaryTree(std::int64_t edges) {
    BranchTree tree;
    tree.reserve(static_cast<std::size_t>(edges) + 1);
    tree.addRoot(Vec3::Zero());
    ramus::Rng rng(1);
    for (NodeId parent = 0; static_cast<std::int64_t>(tree.edgeCount()) + 2 <= edges; ++parent) {
        const Vec3 p = tree.node(parent).position;
        for (int k = 0; k < 2; ++k) {
            const Vec3 dir(rng.uniform(-0.5, 0.5), 1.0, rng.uniform(-0.5, 0.5));
            tree.addChild(parent, p + 0.3 * dir);
        }
    }
    return tree;
}

// Branches of 8 internodes; each internode starts a lateral with probability 0.3 until the
// edge budget is spent (laterals are queued, so growth is breadth first).
BranchTree monopodialTree(std::int64_t edges) {
    BranchTree tree;
    tree.reserve(static_cast<std::size_t>(edges) + 1);
    tree.addRoot(Vec3::Zero());
    ramus::Rng rng(2);
    std::vector<std::pair<NodeId, Vec3>> buds{{0, Vec3(0, 1, 0)}};
    for (std::size_t b = 0; b < buds.size(); ++b) {
        auto [node, heading] = buds[b];
        for (int i = 0; i < 8 && static_cast<std::int64_t>(tree.edgeCount()) < edges; ++i) {
            heading = (heading + Vec3(rng.gauss(0, 0.1), 0.02, rng.gauss(0, 0.1))).normalized();
            node = tree.addChild(node, tree.node(node).position + 0.2 * heading);
            if (rng.uniform01() < 0.3) {
                const Vec3 side(rng.gauss(0, 1), 0.3, rng.gauss(0, 1));
                buds.emplace_back(node, (heading + side.normalized()).normalized());
            }
        }
        if (static_cast<std::int64_t>(tree.edgeCount()) >= edges) break;
    }
    return tree;
}

void reportMesh(benchmark::State& state, const BranchTree& tree, const ramus::Mesh& mesh) {
    const auto edges = static_cast<double>(tree.edgeCount());
    const auto triangles = static_cast<double>(mesh.triangleCount());
    state.SetItemsProcessed(static_cast<std::int64_t>(tree.edgeCount()) * state.iterations());
    state.counters["edges"] = edges;
    state.counters["triangles/s"] =
        benchmark::Counter(triangles, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tris/edge"] = triangles / edges;
    state.counters["verts/edge"] = static_cast<double>(mesh.vertexCount()) / edges;
}

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
