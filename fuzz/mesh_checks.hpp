// Checks the fuzz targets share on the meshes they build (fuzz_weld, fuzz_union): traps (so
// libFuzzer reports the input) unless a mesh is well formed.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

#include "ramus/mesh.hpp"

namespace ramus::fuzz {

using Position = std::tuple<float, float, float>;

inline Position positionOf(const ramus::Mesh& mesh, std::uint32_t v) {
    const ramus::Vec3f& p = mesh.positions[v];
    return {p.x(), p.y(), p.z()};
}

// Traps unless `mesh` is well formed (indices in range, finite positions, unit normals) and,
// where `closed`, closed: every edge, vertices welded by position, used as often in one
// direction as in the other.
inline void checkMesh(const ramus::Mesh& mesh, bool closed) {
    if (mesh.indices.size() % 3 != 0) __builtin_trap();
    if (mesh.normals.size() != mesh.positions.size()) __builtin_trap();
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!mesh.positions[v].allFinite()) __builtin_trap();
        const float length = mesh.normals[v].norm();
        if (!(std::abs(length - 1.0f) < 1e-3f)) __builtin_trap();
    }
    // Each edge by position, smaller end first, +1 where a triangle runs it that way and −1
    // where the other: sorted, every edge's uses must add up to 0.
    std::vector<std::tuple<Position, Position, int>> uses;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[t + k];
            const std::uint32_t b = mesh.indices[t + (k + 1) % 3];
            if (a >= mesh.positions.size() || b >= mesh.positions.size()) __builtin_trap();
            if (!closed) continue;
            const Position pa = positionOf(mesh, a);
            const Position pb = positionOf(mesh, b);
            if (pa == pb) continue;  // a degenerate edge bounds nothing
            uses.emplace_back(std::min(pa, pb), std::max(pa, pb), pa < pb ? 1 : -1);
        }
    }
    std::sort(uses.begin(), uses.end());
    for (std::size_t i = 0; i < uses.size();) {
        int sum = 0;
        std::size_t j = i;
        for (; j < uses.size() && std::get<0>(uses[j]) == std::get<0>(uses[i]) &&
               std::get<1>(uses[j]) == std::get<1>(uses[i]);
             ++j) {
            sum += std::get<2>(uses[j]);
        }
        if (sum != 0) __builtin_trap();
        i = j;
    }
}

}  // namespace ramus::fuzz
