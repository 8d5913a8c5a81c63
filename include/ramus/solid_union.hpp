// Solid union of overlapping closed surfaces (issue 9, "a single closed 2-manifold"): where a
// welded tree mesh still consists of several closed pieces that overlap (fallback junctions,
// crossing limbs of dense L-systems) or one piece that runs through itself (branches crossing
// in the skeleton), the surface of the union of the solids they bound replaces them: no
// triangle pierces another, every edge is shared by two triangles, and pieces that overlap
// become one surface. The intersecting triangles are cut along their intersection curves (exact
// predicates, a constrained triangulation per cut triangle); a winding number per patch, carried
// across the curves from one ray per connected part, keeps the outer ones (Zhou, Grinspun,
// Zorin, Jacobson 2016, "Mesh arrangements for solid geometry", §4).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "ramus/mesh.hpp"

namespace ramus {

/// The most attempts unionClosedSurfaces makes (each with other moves of the vertices).
inline constexpr std::size_t kSolidUnionAttempts = 7;
/// The most re-unions unionClosedSurfaces makes after each attempt that leaves defects.
inline constexpr std::size_t kSolidUnionReunions = 2;
/// The most rounds of micro-edge collapses unionClosedSurfaces makes after the moves of each
/// attempt or re-union where crossings are left (SolidUnionReport::collapsedEdges).
inline constexpr std::size_t kSolidUnionCollapsePasses = 3;

/// The most work unionClosedSurfaces takes on: pairs of intersection segments within one cut
/// triangle (each pair is tested for a crossing, and every crossing becomes a point of that
/// triangle's triangulation), summed over the cut triangles, at most kSolidUnionSegmentPairsFloor
/// plus kSolidUnionSegmentPairsPerTriangle per input triangle. Beyond that the surfaces overlap
/// along whole branches (a branch drawn back over itself, several drawn along one path) and the
/// cut grows quadratically with the overlap: the union is not made (SolidUnionReport::failure
/// says why). The shipped examples reach 21 pairs per triangle (ABOP 1.24c, 1.3 M in all); of
/// 400 random plants (scripts/random-unions.py) 399 at most 71 per triangle (9.3 M in all, a
/// 2.7 s union) or 0.72 M in all (170 per triangle on 4 212 triangles); the other, whose
/// branches turn back along the ones they grow from, 1.5 G (5 117 per triangle; the cut had run
/// for hours, the refusal takes 5 s).
inline constexpr std::size_t kSolidUnionSegmentPairsPerTriangle = 100;
inline constexpr std::size_t kSolidUnionSegmentPairsFloor = 4'000'000;

/// What unionClosedSurfaces did, for tests and --stats.
struct SolidUnionReport {
    bool applied = false;              ///< the mesh was replaced by the union's surface
    std::string failure;               ///< why not, when !applied (the mesh is then unchanged)
    std::size_t inputComponents = 0;   ///< closed surfaces of the input (welded by position)
    std::size_t outputComponents = 0;  ///< closed surfaces of the result
    std::size_t patches = 0;           ///< pieces of surface between the intersection curves
    std::size_t keptPatches = 0;       ///< of those, the ones on the union's boundary
    std::size_t newVertices = 0;       ///< positions on the intersection curves
    std::size_t attempts = 0;          ///< tries with different moves (at most 7)
    /// Moves that made more than 1.5 times the triangles intersect that the first attempt's
    /// did, so their attempts came after the others' (where those left defects).
    std::size_t postponedMoves = 0;
    /// Unions of a result with defects made again after moving the corners at its defects
    /// (at most kSolidUnionReunions after each attempt): much cheaper than an attempt, as
    /// little is cut.
    std::size_t reunions = 0;
    std::size_t cavitiesFilled = 0;  ///< enclosed pockets whose inner surface was removed
    std::size_t enclosedPieces = 0;  ///< pieces inside such pockets, removed with them
    /// separate pieces with < 1e-6 of the largest piece's volume (wedges the cut leaves where
    /// surfaces graze), removed
    std::size_t sliversRemoved = 0;
    /// Triangle pairs of the result that still cross (exact test on the float positions):
    /// where surfaces graze each other, rounding the cut positions to float can make them
    /// cross. The best of the attempts is kept.
    std::size_t remainingIntersections = 0;
    /// Corners moved a few float steps (at most 1e-5 of the extent, in further rounds where
    /// some are left 3e-5 and 1e-4) to separate triangle pairs that rounding made cross, or
    /// sheets it pinched together along an edge;
    /// remainingIntersections and pinchedEdges count what is left after.
    std::size_t crossingMoves = 0;
    /// Edges of crossing triangles shorter than 1e-7 of the extent collapsed where the moves
    /// could not part them: clusters of tiny triangles that the cut leaves where several
    /// intersection curves meet within a float step (since session 36).
    std::size_t collapsedEdges = 0;
    /// Edges of the result (welded by position) where k > 1 sheets meet, each sheet using the
    /// edge once each way: sheets the cut left closer than float resolution, pinched together
    /// by rounding. Each sheet stays closed and oriented; its vertices there are its own.
    std::size_t pinchedEdges = 0;
    /// Positions of the result where surfaces touch at a point (several fans of triangles around
    /// one position, each its own vertex), the ends of pinched edges among them.
    std::size_t touchingPoints = 0;
    /// What keeps the result from being one clean 2-manifold: crossing pairs, pinched edges and
    /// touching points.
    std::size_t defects() const { return remainingIntersections + pinchedEdges + touchingPoints; }
};

/// Replaces the surfaces of `mesh` by the outer boundary of the union of the solids they bound.
/// The input's triangles, welded by position, must form closed, consistently outward-wound
/// surfaces: every edge used as often in one direction as in the other (seam and cap vertices
/// that repeat a position bit-exactly are welded, as the tube and welded meshers write them;
/// surfaces may share edges and vertices, and may overlap each other and themselves).
/// Positions are first moved by at most 1e-5 of the mesh's extent (a fixed hash of the surface
/// vertex) so that no exact coincidences remain (coplanar faces of a flat plant, rings drawn
/// twice). Triangles away from all intersections keep their corners (moved as above) and
/// attributes; triangles cut by another are split along the intersection curves, and every
/// corner of a piece interpolates normal, tangent, UV and custom attributes of the input
/// triangle it came from (normals and tangents renormalized). Pockets enclosed by the solid
/// are filled (their surface and pieces inside them removed), and separate slivers with less
/// than 1e-6 of the largest piece's volume are removed. Primitives are kept in order,
/// each with the pieces of its own triangles. The result must use every edge (welded by
/// position) as often in one direction as in the other; rounding the cut positions to float
/// can break that, pinch sheets together along an edge or make grazing surfaces cross. The
/// corners of crossing pairs are moved apart by a few float steps (at most 1e-5 of the extent,
/// report->crossingMoves) where that lowers the crossings and turns no triangle over, and the
/// corners of pinched sheets into their own solid where that adds no crossing, in up to three
/// rounds while some are left (at most 1e-5, 3e-5, 1e-4 of the extent). Where crossings are
/// left then, in clusters of tiny triangles that the cut leaves where several intersection
/// curves meet within a float step, their edges shorter than 1e-7 of the extent are collapsed
/// (where the surface stays a 2-manifold and no triangle turns over) and the moves made again,
/// up to `maxCollapsePasses` rounds while each leaves fewer defects (report->collapsedEdges;
/// since session 36 no shipped example needs more than its first attempt). Up to `maxAttempts`
/// (clamped to 1–kSolidUnionAttempts) moves are tried, larger and smaller ones in turn (1e-5,
/// 3e-5, 5e-6, 1e-5, 5e-6, 2e-5, 1e-4 of the extent, each time other vertices' moves; a move
/// that makes more than 1.5 times the triangles intersect that the first did is tried last,
/// report->postponedMoves), and the first result without crossings, pinched edges and points
/// where surfaces touch (their corners are moved apart as pinched sheets'), else the one with
/// the fewest, is kept (report->remainingIntersections, report->pinchedEdges,
/// report->touchingPoints). Each attempt is a whole union; fewer trade a clean result for time.
/// After an attempt that leaves defects, the result itself is united again with the corners at
/// its defects moved by as much as the attempt moved every vertex, up to `maxReunions` times
/// (report->reunions): little is cut then, so each costs a fraction of an attempt. On
/// any failure (input not closed, a degenerate configuration the refinement does not handle, no
/// result that passes the check) the mesh is left as it was and the reason goes to report->failure.
/// Where the intersections would make more pairs of segments within cut triangles than
/// kSolidUnionSegmentPairsFloor + kSolidUnionSegmentPairsPerTriangle per triangle, the union
/// stops there with the mesh unchanged (a bound on its work, counted, not timed).
/// Deterministic. Returns report.applied. Throws Error (kSolidUnionMissing) in a build without CGAL
/// (solidUnionAvailable() false).
bool unionClosedSurfaces(Mesh& mesh, SolidUnionReport* report = nullptr,
                         std::size_t maxAttempts = kSolidUnionAttempts,
                         std::size_t maxReunions = kSolidUnionReunions,
                         std::size_t maxCollapsePasses = kSolidUnionCollapsePasses);

/// Whether this build has the solid union: CGAL's Polygon Mesh Processing is GPL-3.0-or-later,
/// and a build configured with -DRAMUS_WITH_CGAL=OFF leaves it (and the GPL) out.
bool solidUnionAvailable();

/// The message of the error a request for the union gets where it is not available.
inline constexpr std::string_view kSolidUnionMissing =
    "the solid union (--union, \"mesh\": {\"union\": true}) is not in this build of ramus: it "
    "needs CGAL's Polygon Mesh Processing (GPL-3.0-or-later), which this build leaves out "
    "(configured with -DRAMUS_WITH_CGAL=OFF); use --weld, or rebuild with -DRAMUS_WITH_CGAL=ON";

}  // namespace ramus
