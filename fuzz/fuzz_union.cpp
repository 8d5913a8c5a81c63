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
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "mesh_checks.hpp"
#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/solid_union.hpp"
#include "ramus/turtle.hpp"
#include "ramus/welded_mesher.hpp"

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
    if (drawn.tree.size() > 100) return 0;
    ramus::WeldedMeshParams params;
    params.solidUnion = true;
    params.shrinkJunctions = size % 2 == 0;
    if (size % 3 == 0) params.unionAttempts = 2;
    ramus::WeldReport report;
    ramus::Mesh mesh;
    try {
        mesh = ramus::buildWeldedTreeMesh(drawn.tree, params, &report);
    } catch (const ramus::Error&) {
        return 0;
    }
    // Closed whether united or not: a union that is not applied leaves the welded mesh.
    ramus::fuzz::checkMesh(mesh, true);
    const ramus::SolidUnionReport& united = report.solidUnion;
    if (mesh.indices.empty()) return 0;
    if (united.applied) {
        if (!united.failure.empty()) __builtin_trap();
        if (united.attempts < 1 || united.attempts > ramus::kSolidUnionAttempts) __builtin_trap();
        if (united.keptPatches > united.patches) __builtin_trap();
        if (united.outputComponents < 1) __builtin_trap();
    } else if (united.failure.empty()) {
        __builtin_trap();
    }
    return 0;
}
