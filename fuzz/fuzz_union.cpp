// libFuzzer target for the solid union (src/mesh/solid_union.cpp, `--union`) on the welded bark of
// arbitrary L-systems: the text is parsed as a .lsys file, derived for at most 4 steps under a
// 20 000-module limit and drawn by the turtle; every tree of at most 100 nodes (the union under
// ASan takes 0.1–15 s on those) is meshed welded and united (shrunk junctions, or convex ones
// when the text's length is odd; at most 2 attempts when it is a multiple of 3, to reach the
// paths that keep the best of few). Only ramus::Error may escape. Where the union was applied
// its result must be closed like its input (every edge, vertices welded by position, used as
// often in one direction as in the other), with indices in range, finite positions and unit
// normals, and its report must add up; where it was not, the report must say why. Anything else
// (crash, sanitizer report, other exception, internal assertion, a hang past FUZZ_TIMEOUT: the
// union has a work limit, so none may run away) is a bug. Needs a build with CGAL (make
// fuzz-union). Run with scripts/fuzz.sh.
//
// Input that starts with "boxes" is instead up to 24 axis-aligned boxes, 6 bytes each (a corner
// and the sizes on a grid of quarter units), united by unionClosedSurfaces directly: faces in one
// plane, shared edges and corners, boxes inside boxes, the coincidences the union's first moves
// must part. The same checks, and a mesh left as it was where the union was not made.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "../tests/mesh/box_mesh.hpp"
#include "fuzzed_tree.hpp"
#include "mesh_checks.hpp"
#include "ramus/error.hpp"
#include "ramus/solid_union.hpp"
#include "ramus/welded_mesher.hpp"

namespace {

// Traps unless the union's report adds up: applied without a failure, or a failure with its
// reason.
void checkReport(const ramus::SolidUnionReport& united) {
    if (united.applied) {
        if (!united.failure.empty()) __builtin_trap();
        if (united.attempts < 1 || united.attempts > ramus::kSolidUnionAttempts) __builtin_trap();
        if (united.keptPatches > united.patches) __builtin_trap();
        if (united.outputComponents < 1) __builtin_trap();
    } else if (united.failure.empty()) {
        __builtin_trap();
    }
}

void uniteBoxes(std::string_view bytes) {
    ramus::Mesh mesh;
    for (std::size_t b = 0; b + 6 <= bytes.size() && b < 6 * 24; b += 6) {
        auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(bytes[b + k]); };
        const ramus::Vec3 lo(byte(0) % 16 * 0.25, byte(1) % 16 * 0.25, byte(2) % 16 * 0.25);
        const ramus::Vec3 size(1 + byte(3) % 12, 1 + byte(4) % 12, 1 + byte(5) % 12);
        ramus::test::appendBox(mesh, lo, lo + 0.25 * size);
    }
    if (mesh.indices.empty()) return;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {  // normals to interpolate
        const ramus::Vec3f corner = mesh.positions[v] - mesh.positions[v / 8 * 8];
        mesh.normals.push_back(corner.squaredNorm() > 0 ? corner.normalized()
                                                        : ramus::Vec3f::UnitX());
    }
    const ramus::Mesh before = mesh;
    ramus::SolidUnionReport united;
    ramus::unionClosedSurfaces(mesh, &united);
    checkReport(united);
    ramus::fuzz::checkMesh(mesh, true);
    if (!united.applied && (mesh.positions != before.positions || mesh.indices != before.indices)) {
        __builtin_trap();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (text.starts_with("boxes")) {
        uniteBoxes(text.substr(5));
        return 0;
    }
    const std::optional<ramus::BranchTree> tree = ramus::fuzz::fuzzedTree(text, 100);
    if (!tree) return 0;
    ramus::WeldedMeshParams params;
    params.solidUnion = true;
    params.shrinkJunctions = size % 2 == 0;
    if (size % 3 == 0) params.unionAttempts = 2;
    ramus::WeldReport report;
    ramus::Mesh mesh;
    try {
        mesh = ramus::buildWeldedTreeMesh(*tree, params, &report);
    } catch (const ramus::Error&) {
        return 0;
    }
    // Closed whether united or not: a union that is not applied leaves the welded mesh.
    ramus::fuzz::checkMesh(mesh, true);
    if (!mesh.indices.empty()) checkReport(report.solidUnion);
    return 0;
}
