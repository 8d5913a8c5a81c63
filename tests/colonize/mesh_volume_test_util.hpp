// Closed test meshes with known volumes: an axis-aligned box, the regular icosahedron and
// subdivided icospheres; all wound counter-clockwise seen from outside.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "ramus/math.hpp"
#include "ramus/mesh_volume.hpp"

namespace ramus::testing {

struct TriangleSoup {
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;

    MeshVolume volume() const { return MeshVolume(vertices, triangles); }
};

/// The box [lo, hi] as 12 triangles; each face is split along a diagonal.
inline TriangleSoup boxMesh(const Vec3& lo, const Vec3& hi) {
    TriangleSoup m;
    for (int i = 0; i < 8; ++i) {
        m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                                i & 4 ? hi.z() : lo.z());
    }
    // Quads (counter-clockwise from outside) split into two triangles each.
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

/// The regular icosahedron with vertices (0, ±1, ±φ), (±1, ±φ, 0), (±φ, 0, ±1).
inline TriangleSoup icosahedron() {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    TriangleSoup m;
    m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    return m;
}

/// The icosahedron subdivided `levels` times (4^levels · 20 triangles), vertices on the unit
/// sphere.
inline TriangleSoup icosphere(int levels) {
    TriangleSoup m = icosahedron();
    for (Vec3& v : m.vertices) v.normalize();
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
            const auto id = static_cast<std::uint32_t>(m.vertices.size() - 1);
            midpoints.emplace(key, id);
            return id;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& t : m.triangles) {
            const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]),
                                ca = midpoint(t[2], t[0]);
            finer.push_back({t[0], ab, ca});
            finer.push_back({t[1], bc, ab});
            finer.push_back({t[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        m.triangles = std::move(finer);
    }
    return m;
}

/// Wavefront OBJ text of the soup (1-based indices).
inline std::string toObj(const TriangleSoup& m) {
    std::ostringstream out;
    out.precision(17);
    for (const Vec3& v : m.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& t : m.triangles) {
        out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
    return out.str();
}

}  // namespace ramus::testing
