// Checks shared by the bone tests: closed 2-manifold meshes and their signed volume.
#pragma once

#include <cstdint>
#include <map>
#include <utility>

#include "ramus/mesh.hpp"

namespace ramus {

/// Number of directed uses per undirected edge must be one each way.
inline bool isClosedManifold(const Mesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.indices[3 * t + e];
            const std::uint32_t b = mesh.indices[3 * t + (e + 1) % 3];
            if (++directed[{a, b}] > 1) return false;
        }
    }
    for (const auto& [edge, count] : directed) {
        if (directed.find({edge.second, edge.first}) == directed.end()) return false;
    }
    return true;
}

inline double signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
        const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
        const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
        volume += a.dot(b.cross(c)) / 6.0;
    }
    return volume;
}

}  // namespace ramus
