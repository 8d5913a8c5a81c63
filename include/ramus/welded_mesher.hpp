// Welded branch meshes (issue 9 item 1): a BranchTree meshed as one connected closed surface —
// tubes along the branches, stitched together at branch nodes by convex-hull junctions
// (Bærentzen, Misztal, Wełnicka 2012, "Converting skeletal structures to quad dominant
// meshes"; Blender's skin modifier). The per-chain tubes of buildTubeMesh stay available.
#pragma once

#include <cstddef>

#include "ramus/branch_tree.hpp"
#include "ramus/mesh.hpp"
#include "ramus/solid_union.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus {

/// Welded meshing parameters. Radii, segment counts, curve reduction, start rotation, UV
/// aspect and material mean the same as for buildTubeMesh (see TubeMeshParams); `tube.capTips`
/// is ignored: a welded mesh is always closed.
struct WeldedMeshParams {
    TubeMeshParams tube;
    /// Clearance between the branches' rings at a junction, as a fraction of the ring's own
    /// radius (> 0; 0.05 = 5 %). Larger values move the rings farther from the branch node.
    double junctionMargin = 0.05;
    /// Replace the surfaces by the boundary of the solid they enclose (unionClosedSurfaces):
    /// pieces left by fallbacks and crossings become one surface wherever they overlap, and
    /// branches that cross in the skeleton stop piercing each other. Slower (an exact
    /// refinement of the intersecting triangles: 0.17–1.1 M united triangles/s on the shipped
    /// examples against welding's 1.3–3.3 M, docs/BENCHMARKS.md; docs/welded.md, "Solid
    /// union"); junction triangles are then no longer the last ones of the index buffer.
    bool solidUnion = false;
    /// Junctions whose convex hull spans far past the branches (a web over a crotch where
    /// several branches leave at small angles) are subdivided and shrunk onto the branches'
    /// filleted surface; a shrunk junction does not intersect itself, and two at a crossing
    /// (a limb too short for both rings) overlap each other as their hulls did
    /// (docs/welded.md, "Shrunk junctions"). With solidUnion the shrunk junctions are united
    /// first (those whose faces stay more than a local radius outside the branches as tubes,
    /// WeldReport::tubedForUnion); where that union is not clean (see
    /// WeldReport::convexForUnion) the hulls are.
    bool shrinkJunctions = true;
    /// Without solidUnion: junctions at a crossing are capped tubes, as fallbacks
    /// (WeldReport::crossingTubes), instead of hulls, which would overlap each other there
    /// anyway and, shrunk over the crowded clusters where crossings happen, leave webs far
    /// outside the branches. False keeps their hulls, as the solid union does.
    bool tubesAtCrossings = true;
    /// With solidUnion: the most attempts of each union (unionClosedSurfaces' maxAttempts,
    /// clamped to 1–kSolidUnionAttempts): each is a whole union more where the last kept crossings
    /// or pinched edges, so fewer trade a clean surface for time.
    std::size_t unionAttempts = kSolidUnionAttempts;
    /// With solidUnion: the most re-unions after each attempt (unionClosedSurfaces'
    /// maxReunions; 0: none).
    std::size_t unionReunions = kSolidUnionReunions;
    /// With solidUnion: the most rounds of micro-edge collapses after each attempt's or
    /// re-union's moves (unionClosedSurfaces' maxCollapsePasses; 0: none).
    std::size_t unionCollapsePasses = kSolidUnionCollapsePasses;
};

/// What the welder did, for tests and --stats.
struct WeldReport {
    std::size_t junctions = 0;      ///< branch nodes (≥ 2 drawn edges leaving a tree part)
    std::size_t merges = 0;         ///< junctions merged with a neighbour (branch nodes too close)
    std::size_t absorbedLimbs = 0;  ///< short end branches taken whole into a junction
    /// Junctions at their size limit (16 branch nodes, 256 inner ring positions) whose rings
    /// could not be placed clear of each other (dense thick branching); usually a fallback.
    std::size_t crowded = 0;
    /// Limbs between two junctions too short for both end rings, left overlapping (the
    /// surface stays closed but intersects itself there).
    std::size_t crossings = 0;
    /// Such limbs where a plane parts the rings of the two junctions: one ring in that plane,
    /// which both junctions take as their arm's ring, instead of a ring each (then each hull lies
    /// on its own side of the plane and the surface does not intersect itself there).
    std::size_t sharedRings = 0;
    std::size_t fallbacks = 0;  ///< junctions left as separately capped tubes (should be 0)
    /// Without solidUnion: junctions at a crossing (a limb of theirs in `crossings`), meshed as
    /// capped tubes as a fallback is, without a hull: their hull would overlap the neighbour's
    /// across the crossing anyway, and shrunk over such crowded clusters it left webs (fins)
    /// far outside the branches.
    std::size_t crossingTubes = 0;
    /// Limbs inside such junctions (between their merged branch nodes), meshed as capped tubes
    /// of their own.
    std::size_t absorbedTubes = 0;
    /// Branch nodes the hull of their rings left (nearly) bare, as where branches fold back
    /// along their parent, closed over by a ball of the thickest branch's radius.
    std::size_t nodeBalls = 0;
    /// Branch nodes where the branch bends (by more than 10°) and the tube mesher's ring there,
    /// facing the bend's bisector, reached outside the hull: its outer points are hull points.
    std::size_t bendRings = 0;
    std::size_t refinedJunctions = 0;  ///< junctions shrunk onto their branches
    /// With solidUnion: junctions whose faces (shrunk, or the convex hull's where the hulls are
    /// united) stayed more than a local radius outside the branches, meshed as capped tubes
    /// (as fallbacks) for the union to join instead (shrunk ones counted in refinedJunctions
    /// too).
    std::size_t tubedForUnion = 0;
    std::size_t components = 0;  ///< closed surfaces (1 per tree unless hidden edges split it)
    /// Triangles of the junctions: the last ones of the index buffer (tubes and caps first).
    std::size_t junctionTriangles = 0;
    SolidUnionReport solidUnion;  ///< with WeldedMeshParams::solidUnion
    /// With solidUnion and shrinkJunctions: the union of the shrunk junctions failed or kept
    /// crossings or pinched edges, and that of the convex hulls had fewer, so the hulls were
    /// united instead (the counts above are then the convex welding's: refinedJunctions 0).
    bool convexForUnion = false;
};

/// Meshes `tree` as closed surfaces: one per part of the tree connected by drawn edges
/// (hidden edges split it; a normal tree gives one). Every vertex ring of a branch lies on the
/// branch's tapered tube exactly as buildTubeMesh places it (same radii, rotation-minimizing
/// frames, segment rule per unbranched stretch); at each branch node the rings of the meeting
/// branches are moved just far enough from the node that no ring's plane cuts another
/// branch, and the convex hull of those rings, minus the rings' own discs, joins them. Branch
/// nodes closer than that are merged into one junction; end branches shorter than their
/// junction become part of it. Tips and the base are closed with flat fans. Coincident nodes
/// are merged (zero-length edges; an edge drawn twice from one node, which keeps the thicker
/// radius). Output as buildTubeMesh: mesh "tree", unit normals (radial on rings), glTF
/// tangents (w = +1), UVs (u around the ring, v along the branch, continuing through branch
/// nodes), one primitive "bark" with params.tube.material; triangles counter-clockwise from
/// outside. Seam and cap vertices repeat ring positions bit-exactly, so welding by position
/// gives a 2-manifold. With params.tube.windAttributes the mesh carries `_WIND`, `_WIND_PIVOT`
/// and `_WIND_LEAF` (include/ramus/tree_wind.hpp): ring and cap vertices the values
/// buildTubeMesh gives a ring at that point of the branch; rings of limbs absorbed into a
/// junction those of the branch they grow out of at their start node (docs/welded.md).
/// Empty tree, root only or only hidden edges → empty mesh. Deterministic.
/// `report`, when given, receives the counts above.
Mesh buildWeldedTreeMesh(const BranchTree& tree, const WeldedMeshParams& params = {},
                         WeldReport* report = nullptr);

}  // namespace ramus
