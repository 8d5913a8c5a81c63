// libFuzzer target for the welded mesher (docs/welded.md) on the trees of arbitrary L-systems:
// the text is parsed as a .lsys file, derived for at most 4 steps under a 20 000-module limit and
// drawn by the turtle; every tree of at most 2 000 nodes is meshed welded (shrunk junctions, or
// convex ones when the text's length is odd; wind data when it is a multiple of 3) and with plain
// tubes. Only ramus::Error may escape, and each mesh must be well formed whatever the tree:
// indices in range, finite positions, unit normals; the welded one also closed, every edge
// (vertices welded by position) used as often in one direction as in the other, as glTF viewers
// and the solid union need (tubes are open where a branch starts inside its parent's). Anything
// else (crash, sanitizer report, other exception, hang) is a bug. Run with scripts/fuzz.sh.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/turtle.hpp"
#include "ramus/welded_mesher.hpp"

namespace {

using Position = std::tuple<float, float, float>;

Position positionOf(const ramus::Mesh& mesh, std::uint32_t v) {
    const ramus::Vec3f& p = mesh.positions[v];
    return {p.x(), p.y(), p.z()};
}

// Traps unless `mesh` is well formed and, where `closed`, closed (see the file comment).
void checkMesh(const ramus::Mesh& mesh, bool closed) {
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    ramus::TurtleResult drawn;
    try {
        const ramus::LSystem system = ramus::parseLSystem(text, "fuzz.lsys");
        ramus::DeriveOptions options;
        options.derivations = std::min(system.settings.derivations, 4);
        options.maxModules = 20000;
        options.maxMemoryBytes = std::size_t{8} << 20;
        const ramus::ModuleString word = ramus::deriveLSystem(system, options);
        drawn =
            ramus::interpretTurtle(word, system.symbols, ramus::turtleParamsFrom(system.settings));
    } catch (const ramus::Error&) {
        return 0;
    }
    if (drawn.tree.size() > 2000) return 0;
    ramus::WeldedMeshParams params;
    params.shrinkJunctions = size % 2 == 0;
    params.tube.windAttributes = size % 3 == 0;
    try {
        checkMesh(ramus::buildWeldedTreeMesh(drawn.tree, params), true);
        // Tubes are open where a branch starts inside its parent's tube.
        checkMesh(ramus::buildTubeMesh(drawn.tree, params.tube), false);
    } catch (const ramus::Error&) {
    }
    return 0;
}
