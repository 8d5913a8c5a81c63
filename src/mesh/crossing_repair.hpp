// Separating triangles that cross only because their corners were rounded to float: the solid
// union's last step (src/mesh/solid_union.cpp). Internal to src/mesh; built with CGAL only.
//
// Where two sheets of the union graze each other, the exact cut leaves them apart by less than
// float resolution, and rounding the new corners to float can make a triangle reach through
// the other sheet by a few units in the last place (docs/welded.md measured at most 4e-8 of the
// plant's extent on all but three plants). Such a crossing goes away when one corner of the
// pair moves by a few ulps off the other sheet. Snap rounding would settle it in general (CGAL
// 5.5 has none for surfaces); this is a greedy local search of ours: corners of crossing pairs
// are moved, smallest move first, where that lowers the number of crossings their triangles
// take part in and turns no triangle over.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "ramus/math.hpp"

namespace ramus::detail {

/// Closed surfaces as surface vertices and triangles over them.
struct CrossingSurface {
    std::vector<Vec3f> points;                            ///< per surface vertex
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< surface vertices, outward wound
    std::vector<char> fixed;  ///< per surface vertex: may not move (empty: all may)
};

/// A pair of triangles (indices into CrossingSurface::triangles) that cross.
using TrianglePair = std::pair<std::uint32_t, std::uint32_t>;

/// What separateCrossings did.
struct CrossingRepair {
    std::size_t movedVertices = 0;  ///< moves made (a vertex may move more than once)
    std::size_t pairsLeft =
        0;                   ///< of the given pairs and those moves made, the ones still crossing
    std::uint64_t work = 0;  ///< pairs of a moving vertex's triangle and one near it looked at
    bool overWorkLimit = false;  ///< stopped moving vertices because `work` passed the limit
};

/// The repair's work limit: the pairs of a moving vertex's triangle and a triangle near it
/// (within reach of its moves) that one repair looks at — to collect them, and then for each
/// move it tries, kept apart by their boxes or tested exactly — before it stops moving
/// vertices, for a surface of `triangles` triangles: kCrossingRepairWorkFloor +
/// kCrossingRepairWorkPerTriangle per triangle. Measured in session 45 (docs/welded.md, Solid
/// union, step 6): the shipped examples' repairs look at 1.3 M at most (ABOP 1.24c; 12 per
/// triangle, 1.24b), those of 400 random plants 5.1 M (seed 260; 46 per triangle, seed 125, on
/// a surface over the floor), where session 43's pinched junctions had looked at billions
/// (21 720 pairs with 90 000 triangles within reach of each corner) and run for minutes. About
/// 75 ns each on the VM: the floor is about a second (the test's star of 24 crossing planks
/// stops at it after 1.2 s, and without a limit ran for more than 2 minutes). Counted, not
/// timed, so the outcome does not depend on the machine.
constexpr std::uint64_t kCrossingRepairWorkFloor = 16'000'000;
constexpr std::uint32_t kCrossingRepairWorkPerTriangle = 100;
std::uint64_t crossingRepairWorkLimit(std::size_t triangles);

/// Moves corners of the crossing pairs `crossing` (as the solid union counts them,
/// trianglesCross in triangle_pairs.hpp: triangles that intersect and share no position, and
/// neighbours that fold through each other; exact predicates on the float positions) by at most
/// `maxMove` each, in float
/// steps, so that they no longer cross. A move is made only where it lowers the number of
/// crossings the vertex's triangles take part in (against every triangle of the surface) and
/// turns none of them over; moves are tried smallest first, along the vertex normal and along
/// the other triangle's normal, both ways. Deterministic. Stops moving vertices once it has
/// looked at more than `workLimit` pairs (default crossingRepairWorkLimit of the surface's
/// triangles; CrossingRepair::overWorkLimit), leaving the pairs not yet separated.
CrossingRepair separateCrossings(CrossingSurface& surface, std::span<const TrianglePair> crossing,
                                 double maxMove,
                                 std::optional<std::uint64_t> workLimit = std::nullopt);

/// Moves each of `vertices` (corners of sheets that rounding pinched to another sheet along an
/// edge: the same positions, other surface vertices) a few float steps off that position, into
/// its own solid first, then out, towards the middle of its neighbours or along an axis, at most
/// `maxMove`, where that adds no crossing around it and turns no triangle over. They are taken in
/// order, and a vertex whose position no other surface vertex shares any more (its partner moved
/// first) stays: listing both sheets' corners, the preferred sheet's first, parts them where the
/// preferred corners are fixed or cannot move. CrossingRepair::pairsLeft stays 0.
/// Deterministic; stops moving vertices past `workLimit`, as separateCrossings.
CrossingRepair unpinchVertices(CrossingSurface& surface, std::span<const std::uint32_t> vertices,
                               double maxMove,
                               std::optional<std::uint64_t> workLimit = std::nullopt);

}  // namespace ramus::detail
