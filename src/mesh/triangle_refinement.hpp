// Cutting intersecting triangles of closed surfaces along their intersections: the refinement
// step of the solid union (src/mesh/solid_union.cpp). Internal to src/mesh; needs CGAL.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <compare>
#include <cstdint>
#include <utility>
#include <vector>

namespace ramus::detail {

using RefinementPoint = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

/// The pieces of the cut triangles: new points (numbered after the input's), the pieces with
/// the input triangle each came from, and the regions they make in it.
struct RefinedTriangles {
    struct Piece {
        std::uint32_t origin;
        std::array<std::uint32_t, 3> corners;
    };
    /// A region of a cut triangle: its pieces joined across edges that are not cut, between
    /// the cuts (edges of pieces along an intersection), with its winding number just outside
    /// relative to the triangle's first region: across a cut, the piece on the inner side of
    /// the other triangle (the side its normal points away from) has one more than the piece on
    /// the outer side.
    struct Region {
        std::uint32_t origin;
        int winding;
    };
    /// An edge of a piece on a side of its cut triangle (from → to as the piece uses it): the
    /// face across it, of the neighbouring triangle on the same sheet, has the same winding
    /// number as the piece's region.
    struct Side {
        std::uint32_t from, to, region;
    };
    std::vector<RefinementPoint> newPoints;
    std::vector<Piece> pieces;
    std::vector<std::uint32_t> pieceRegion;  ///< per piece: its region
    std::vector<Region> regions;             ///< by cut triangle, ascending
    std::vector<Side> sides;
};

/// Cuts the triangles of closed surfaces (corners `fan`, three per triangle, at `points`) that
/// intersect others along the intersections, given every intersecting pair (s, t): the pieces
/// of each cut triangle tile it, the intersections are edges of pieces on both sides, and
/// pieces of other triangles meet them only at shared corners. Where a cut point lies inside a
/// triangle or on one of its edges, that triangle's sheet gets a vertex of its own there, so
/// every sheet stays a 2-manifold (the surfaces are joined later, by position). New points are
/// the exact intersections rounded to doubles.
///
/// Every intersection is found from exact predicates on the corners, with no tolerance, and
/// every cut triangle is triangulated (constrained Delaunay, exact) in its own plane, projected
/// on the axis plane where it is largest. The input has to be in general position (the union
/// moves its vertices apart first): a corner on another triangle's plane, edges that meet,
/// coplanar triangles, degenerate triangles among the cut ones — any degeneracy ends the
/// refinement with a message (returned; nullptr on success) so that the caller can move the
/// corners and try again. Cut triangles are refined on two cores; the result does not depend
/// on the threads.
///
/// Each cut triangle's pieces are grouped into regions (joined across the edges that are not
/// cut), each with its winding number relative to the triangle's first region, read off the
/// triangulation's adjacency and the sides of the cut edges (since session 38, when the solid
/// union went from classifying pieces to classifying regions, instead of the directed cut edges:
/// ABOP 1.24a has 576 k pieces in 188 k regions), and the pieces' edges on the triangles' sides
/// are listed with their regions, so that a caller can carry winding numbers from triangle to
/// triangle.
///
/// Replaced CGAL's autorefinement (Polygon Mesh Processing, experimental::autorefine, 5.5) in
/// session 31, which took 10–14 s of the 13–17 s union of a dense plant (docs/welded.md).
const char* refineTriangles(const std::vector<RefinementPoint>& points,
                            const std::vector<std::uint32_t>& fan,
                            const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                            RefinedTriangles& out);

}  // namespace ramus::detail
