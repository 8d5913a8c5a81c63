// An axis-aligned box as a closed mesh of its own: the solid union's tests
// (solid_union_test.cpp) and its fuzzer (fuzz/fuzz_union.cpp) build their inputs from these.
#pragma once

#include <cstdint>

#include "ramus/math.hpp"
#include "ramus/mesh.hpp"

namespace ramus::test {

// An axis-aligned box [lo, hi] as 12 outward triangles (without shared corners between boxes).
inline void appendBox(Mesh& mesh, const Vec3& lo, const Vec3& hi) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (int i = 0; i < 8; ++i) {
        mesh.positions.emplace_back(static_cast<float>(i & 1 ? hi.x() : lo.x()),
                                    static_cast<float>(i & 2 ? hi.y() : lo.y()),
                                    static_cast<float>(i & 4 ? hi.z() : lo.z()));
    }
    // Corner i has bit 0 = x, bit 1 = y, bit 2 = z; each face counter-clockwise from outside.
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        mesh.indices.insert(mesh.indices.end(), {base + q[0], base + q[1], base + q[2]});
        mesh.indices.insert(mesh.indices.end(), {base + q[0], base + q[2], base + q[3]});
    }
}

}  // namespace ramus::test
