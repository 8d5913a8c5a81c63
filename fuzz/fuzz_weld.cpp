// libFuzzer target for the welded mesher (docs/welded.md) on the trees of arbitrary L-systems:
// the text is parsed as a .lsys file, derived for at most 4 steps under a 20 000-module limit and
// drawn by the turtle; every tree of at most 2 000 nodes is meshed welded (shrunk junctions, or
// convex ones when the text's length is odd; wind data when it is a multiple of 3) and with plain
// tubes. Only ramus::Error may escape, and each mesh must be well formed whatever the tree:
// indices in range, finite positions, unit normals; the welded one also closed, every edge
// (vertices welded by position) used as often in one direction as in the other, as glTF viewers
// and the solid union need (tubes are open where a branch starts inside its parent's). Anything
// else (crash, sanitizer report, other exception, hang) is a bug. Run with scripts/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "fuzzed_tree.hpp"
#include "mesh_checks.hpp"
#include "ramus/error.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/welded_mesher.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::optional<ramus::BranchTree> tree = ramus::fuzz::fuzzedTree(text, 2000);
    if (!tree) return 0;
    ramus::WeldedMeshParams params;
    params.shrinkJunctions = size % 2 == 0;
    params.tube.windAttributes = size % 3 == 0;
    try {
        ramus::fuzz::checkMesh(ramus::buildWeldedTreeMesh(*tree, params), true);
        // Tubes are open where a branch starts inside its parent's tube.
        ramus::fuzz::checkMesh(ramus::buildTubeMesh(*tree, params.tube), false);
    } catch (const ramus::Error&) {
    }
    return 0;
}
