// Branch meshes (seed 002 §4.4; SPEC §D): a BranchTree becomes tapered tubes — rings around
// each node, shared along chains of equal branch depth, joined by quads.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/mesh.hpp"

namespace ramus {

/// Where edge radii come from.
enum class RadiusMode {
    Auto,    ///< Widths when any node has a radius (turtle `!`), else Murray
    Murray,  ///< Murray's rule from the tips (seed 002 §3.4): r^g = Σ r_child^g
    Widths,  ///< BranchNode::radius; nodes without one inherit their parent's
};

/// Tube meshing parameters (names of the seed's editor UI, seed 002 §4.4).
struct TubeMeshParams {
    RadiusMode radiusMode = RadiusMode::Auto;
    /// r_0, radius at the tips for Murray's rule, model units; 0 = automatic (4 % of the mean
    /// length of the drawn edges).
    double leafRadius = 0.0;
    double radiusExponent = 2.0;   ///< g of Murray's rule (> 0); 2 = area preserving
    double trunkMultiplier = 1.0;  ///< root ring radius = multiplier × root edge's end radius
    /// Ring vertices (segments) per chain: min + round((max - min) · r_first / r_max), r_first
    /// the chain's first ring radius, r_max the tree's largest. Clamped to [3, 4096].
    int minSegments = 4;   ///< for the thinnest branches (≥ 3)
    int maxSegments = 16;  ///< for the thickest (≥ minSegments)
    /// Curve reduction max_K in (0,1): a chain node whose two unit edge directions have a dot
    /// product above it gets no ring of its own. 0 = off.
    double curveReduction = 0.0;
    double startRotationDegrees = 0.0;  ///< rot_z: angle of the first ring vertex
    /// Close open tube ends with a flat fan: branch tips, and chain starts that no drawn tube
    /// passes through (the root, after hidden edges).
    bool capTips = true;
    /// Bark texture repeats: u goes 0 → 1 once around a ring (seam vertex duplicated); v starts
    /// at 0 on a chain's first ring and decreases by length / (mean circumference × uvAspect)
    /// per tube piece, so texels stay square (uvAspect = texture height / width) and, with
    /// glTF's top-left UV origin, the image's top points along the growth direction.
    double uvAspect = 1.0;
    /// Write the wind attributes `_WIND`, `_WIND_PIVOT`, `_WIND_LEAF` (include/ramus/tree_wind.hpp,
    /// docs/export.md); branch phases are hashed from windSeed.
    bool windAttributes = false;
    std::uint64_t windSeed = 0;
    Material material{"bark", {0.42f, 0.30f, 0.20f, 1.0f}, 0.0f, 0.95f, false};
};

/// The radius of the edge ending at each node, exactly as buildTubeMesh uses it (radius mode,
/// automatic leaf radius, inheritance of `!` widths); the root's entry is its end radius
/// (before trunkMultiplier). Indexed by node id; empty tree → empty vector.
std::vector<double> computeEdgeRadii(const BranchTree& tree, const TubeMeshParams& params = {});

/// Meshes `tree` into tubes. Every edge not marked hidden gets a tube piece; edges of equal
/// branch depth form chains that share rings; other children (and children of hidden nodes)
/// start a new chain with a ring at their parent's position. Rings use rotation-minimizing
/// frames; coincident nodes are merged. Output: mesh "tree" with positions, unit normals,
/// tangents (w = +1: cross(normal, tangent) points to decreasing v), uvs, one primitive "bark"
/// with params.material; triangles counter-clockwise from outside. Empty tree, root only or
/// only hidden edges → empty mesh (no primitives, no materials). Deterministic.
Mesh buildTubeMesh(const BranchTree& tree, const TubeMeshParams& params = {});

/// The number of triangles buildTubeMesh(tree, params) has, found without building the mesh
/// (the same chains, merged and reduced rings and caps; no vertices): what planning levels of
/// detail tries many times.
std::size_t countTubeTriangles(const BranchTree& tree, const TubeMeshParams& params = {});

/// Triangulates planar-ish polygons into a mesh "leaves" with one primitive "leaves": each
/// polygon is ear-clipped in its Newell plane (concave ones too) into one sheet facing its
/// Newell normal, and `material` is returned with doubleSided = true so the sheet shows from
/// both sides. UVs span each polygon's bounds (v = 1 at its first vertex, 0 at the farthest
/// one); tangents w = +1. Polygons with fewer than 3 vertices or no area are skipped; none left
/// → empty mesh. Layout as TurtleResult: offsets has polygonCount + 1 entries. With
/// `vertexPolygons`, it receives the polygon index of every output vertex.
Mesh buildPolygonMesh(
    std::span<const Vec3> vertices, std::span<const std::uint32_t> offsets,
    const Material& material = {"leaves", {0.25f, 0.5f, 0.15f, 1.0f}, 0.0f, 0.8f, true},
    std::vector<std::uint32_t>* vertexPolygons = nullptr);

}  // namespace ramus
