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
    /// edge length).
    double leafRadius = 0.0;
    double radiusExponent = 2.0;   ///< g of Murray's rule (> 0); 2 = area preserving
    double trunkMultiplier = 1.0;  ///< root ring radius = multiplier × root edge's end radius
    int minSegments = 4;           ///< ring vertices for the thinnest branches (≥ 3)
    int maxSegments = 16;          ///< ring vertices for the thickest (≥ minSegments)
    /// Curve reduction max_K in (0,1): a chain node whose two unit edge directions have a dot
    /// product above it gets no ring of its own. 0 = off.
    double curveReduction = 0.0;
    double startRotationDegrees = 0.0;  ///< rot_z: angle of the first ring vertex
    bool capTips = true;                ///< close branch ends with a cone/fan cap
    /// Bark texture repeats: u goes once around a ring; v = arc length / (circumference at
    /// that ring × uvAspect) so texels stay square (uvAspect = texture height / width).
    double uvAspect = 1.0;
    Material material{"bark", {0.42f, 0.30f, 0.20f, 1.0f}, 0.0f, 0.95f, false};
};

/// The radius of the edge ending at each node, exactly as buildTubeMesh uses it (radius mode,
/// automatic leaf radius, inheritance of `!` widths); the root's entry is its end radius
/// (before trunkMultiplier). Indexed by node id; empty tree → empty vector.
std::vector<double> computeEdgeRadii(const BranchTree& tree, const TubeMeshParams& params = {});

/// Meshes `tree` into tubes. Every edge not marked hidden gets a tube piece; output has
/// positions, unit normals, tangents (w = +1), uvs, one primitive "bark". Empty tree or a tree
/// of only a root gives an empty mesh. Deterministic.
Mesh buildTubeMesh(const BranchTree& tree, const TubeMeshParams& params = {});

/// Triangulates planar-ish polygons (fan from the centroid, both faces so they show from either
/// side) into a mesh with one primitive "leaves" using `material`. Polygons with fewer than 3
/// vertices are skipped. Layout as TurtleResult: offsets has polygonCount + 1 entries.
Mesh buildPolygonMesh(std::span<const Vec3> vertices, std::span<const std::uint32_t> offsets,
                      const Material& material = {
                          "leaves", {0.25f, 0.5f, 0.15f, 1.0f}, 0.0f, 0.8f, true});

}  // namespace ramus
