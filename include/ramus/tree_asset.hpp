// Production tree meshes (issue 9): bark tubes, L-system polygons and generated leaves in one
// mesh with one primitive per material, optional wind attributes, and levels of detail.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/leaves.hpp"
#include "ramus/mesh.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus {

/// One tree to mesh: its branches and, from an L-system, its `{ . }` polygons (TurtleResult's
/// layout; polygonNodes may be empty, then polygons follow the root's wind).
struct TreeMeshInput {
    const BranchTree* tree = nullptr;
    std::span<const Vec3> polygonVertices;
    std::span<const std::uint32_t> polygonOffsets;
    std::span<const NodeId> polygonNodes;
};

/// How trees become a mesh.
struct TreeMeshParams {
    TubeMeshParams tube;  ///< bark; tube.windAttributes also adds wind data to the leaves
    /// Bark as one closed surface per tree (buildWeldedTreeMesh, docs/welded.md) instead of
    /// overlapping tubes. It writes no wind data: not together with tube.windAttributes.
    bool weldJunctions = false;
    /// With weldJunctions: replace each tree's welded bark by the surface of the union of its
    /// pieces (unionClosedSurfaces): one closed surface without self-intersections where the
    /// welder leaves overlapping pieces. A fraction of a second for 10⁵ triangles, so LODs are
    /// planned on welded bark and only each level's candidates (up to 5) are united, aiming at
    /// the level's share of the united full detail (docs/welded.md, Solid union).
    bool solidUnion = false;
    /// With weldJunctions: keep every junction the convex hull of its rings
    /// (WeldedMeshParams::shrinkJunctions off): fewer triangles, but webs over the crotches
    /// where several branches leave at small angles. (Without it, a union whose shrunk
    /// junctions do not unite cleanly unites the hulls: WeldReport::convexForUnion.)
    bool convexJunctions = false;
    /// How many trees (of a forest) and LOD levels are meshed at once, on threads of their own:
    /// 0 = one per core. 1 where the caller already runs one job per core (`ramus batch`), so
    /// that jobs × trees × levels welds and unions are not in memory at once. The result does
    /// not depend on it.
    std::size_t threads = 0;
    bool leaves = false;  ///< generate leaves (buildLeafMesh) besides the polygons
    LeafParams leaf;      ///< generated leaves, and the atlas, seed and LOD keep of the polygons
    /// The `{ . }` polygons' material (their primitive is named after it): they have their own
    /// outline, so a leaf texture's cut-out does not suit them.
    Material polygonMaterial{"leaves", {0.25f, 0.5f, 0.15f, 1.0f}, 0.0f, 0.8f, true};
};

/// How welding (params.weldJunctions) and the solid union (params.solidUnion) went on the
/// final bark meshes (not the LOD planner's trials), for --stats and warnings.
struct TreeMeshReport {
    std::size_t weldedMeshes = 0;  ///< tree meshes welded (one per tree and level)
    /// Over them, before any union: WeldReport::fallbacks (crowded junctions closed as separate
    /// capped tubes: the surface is several overlapping pieces), ::crossings (limbs too short
    /// for both their rings) and ::crossingTubes (the junctions at those crossings, capped tubes
    /// too).
    std::size_t weldFallbacks = 0, weldCrossings = 0, weldCrossingTubes = 0;
    /// Over them, WeldReport::sharedRings (such limbs whose two junctions share one ring).
    std::size_t weldSharedRings = 0;
    std::size_t shrunkJunctions = 0;  ///< WeldReport::refinedJunctions over them
    std::size_t unionsApplied = 0;    ///< tree meshes replaced by their union's surface
    std::size_t unionsFailed = 0;     ///< tree meshes left welded (overlapping), see firstFailure
    /// Of the united meshes, those made of convex junctions (WeldReport::convexForUnion).
    std::size_t unionsOfHulls = 0;
    /// Over the united meshes: junctions meshed as tubes for the union (WeldReport::tubedForUnion).
    std::size_t tubedForUnion = 0;
    std::string firstFailure;  ///< SolidUnionReport::failure of the first failed one
    /// Over the united meshes: SolidUnionReport::remainingIntersections, ::pinchedEdges,
    /// ::touchingPoints, ::crossingMoves and ::collapsedEdges.
    std::size_t crossingsLeft = 0, pinchedEdges = 0, touchingPoints = 0, crossingMoves = 0,
                collapsedEdges = 0;
    /// Over the united meshes: SolidUnionReport::attempts (each a whole union), ::postponedMoves
    /// and ::reunions.
    std::size_t unionAttempts = 0, postponedMoves = 0, reunions = 0;
};

/// The full-detail mesh "tree" of all `trees`: tubes, polygons as leaves (buildLeafPolygons),
/// generated leaves when params.leaves; then mergePrimitivesByMaterial, so a forest has one
/// "bark" and one "leaves" primitive. Nothing drawn → empty mesh. A forest's trees are meshed
/// (welded, united) on threads of their own; the result does not depend on them.
Mesh buildTreeMesh(std::span<const TreeMeshInput> trees, const TreeMeshParams& params,
                   TreeMeshReport* report = nullptr);

/// One level of detail.
struct TreeLod {
    double ratio = 1.0;                    ///< the requested fraction of LOD 0's triangles
    std::size_t targetTriangles = 0;       ///< ratio × LOD 0's triangle count, rounded
    Mesh mesh;                             ///< named "tree_LOD<i>"
    int minSegments = 0, maxSegments = 0;  ///< ring segments used
    std::size_t prunedNodes = 0;           ///< branch nodes whose edges were left out
    double leafKeep = 1.0;                 ///< fraction of leaves kept
    bool leafCards = false;                ///< blades replaced by cards
};

/// Levels of detail by tree-aware reduction (no generic simplifier, so every kept vertex keeps
/// its exact UVs and wind data): the leaves get their share of the target by thinning (kept
/// leaves grow by 1/√keep) and, below half, blades become cards; the bark gets the rest by
/// fewer ring segments and then by pruning the thinnest branch edges (by radius, ties: the
/// newest node first; a pruned edge takes everything above it). Radii, wind data and leaf
/// placement are always those of the whole tree. ratios[i] in (0, 1]; LOD 0 is the full mesh
/// when ratios[0] = 1. The result's triangle counts land near ratio × (full count) — within
/// a few percent unless the trunk alone is above the target. Throws Error for ratios outside
/// (0, 1] or an empty list. The levels are planned and meshed on threads of their own; the
/// result does not depend on them, and `report` adds up the levels' in their order.
std::vector<TreeLod> buildTreeLods(std::span<const TreeMeshInput> trees,
                                   const TreeMeshParams& params, std::span<const double> ratios,
                                   TreeMeshReport* report = nullptr);

/// Triangles of `mesh` in primitives called `name` (e.g. "bark", "leaves").
std::size_t primitiveTriangles(const Mesh& mesh, std::string_view name);

}  // namespace ramus
