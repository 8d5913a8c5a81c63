// Synthetic trees of a given edge count for the mesher benchmarks (mesh_bench.cpp,
// welded_bench.cpp, tree_asset_bench.cpp, io_bench.cpp), and the counters they report.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/mesh.hpp"
#include "ramus/rng.hpp"

namespace ramus::bench {

// Breadth-first full binary tree with `edges` edges (rounded down to whole levels' worth).
inline BranchTree binaryTree(std::int64_t edges) {
    BranchTree tree;
    tree.reserve(static_cast<std::size_t>(edges) + 1);
    tree.addRoot(Vec3::Zero());
    Rng rng(1);
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
inline BranchTree monopodialTree(std::int64_t edges, std::uint64_t seed) {
    BranchTree tree;
    tree.reserve(static_cast<std::size_t>(edges) + 1);
    tree.addRoot(Vec3::Zero());
    Rng rng(seed);
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

// The default seed, as a one-argument function the mesher benchmarks take by pointer.
inline BranchTree monopodialTree(std::int64_t edges) { return monopodialTree(edges, 2); }

inline void reportMesh(benchmark::State& state, const BranchTree& tree, const Mesh& mesh) {
    const auto edges = static_cast<double>(tree.edgeCount());
    const auto triangles = static_cast<double>(mesh.triangleCount());
    state.SetItemsProcessed(static_cast<std::int64_t>(tree.edgeCount()) * state.iterations());
    state.counters["edges"] = edges;
    state.counters["triangles/s"] =
        benchmark::Counter(triangles, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tris/edge"] = triangles / edges;
    state.counters["verts/edge"] = static_cast<double>(mesh.vertexCount()) / edges;
}

}  // namespace ramus::bench
