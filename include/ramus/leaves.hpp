// Leaves and twigs (issue 9): leaf cards or small leaf meshes placed near the tips of a
// BranchTree, with phyllotaxis, tilt, size and density controls and a seed; UVs into a region
// of a texture atlas; one "leaves" primitive with its own (double-sided) material.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/mesh.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus {

/// What one leaf is made of.
enum class LeafShape {
    Card,  ///< a quad (2 triangles): for an alpha-masked leaf texture
    Blade  ///< a leaf outline with a folded midrib (12 triangles): looks like a leaf untextured
};

/// Parses "card" or "blade"; throws Error listing both.
LeafShape parseLeafShape(const std::string& name);

/// Leaf placement and appearance. Lengths in model units, angles in degrees.
struct LeafParams {
    LeafShape shape = LeafShape::Blade;
    int perTip = 3;          ///< leaves at every branch tip (≥ 0)
    double perLength = 0.0;  ///< leaves per model unit along branches near tips (≥ 0)
    /// perLength applies within this distance of a tip, measured along the branches (≥ 0);
    /// 0 = 4 leaf lengths.
    double zone = 0.0;
    double size = 0.0;            ///< leaf length (≥ 0); 0 = the mean length of the drawn edges
    double widthRatio = 0.5;      ///< width / length, in (0, 4]
    double sizeVariation = 0.25;  ///< each leaf's size × uniform(1 − v, 1 + v), v in [0, 1)
    /// Azimuth step between consecutive leaves around their branch (the golden angle by
    /// default), the same along a whole branch.
    double phyllotaxisDegrees = 137.5;
    double tiltDegrees = 50.0;    ///< angle between the leaf and its branch's direction
    double jitterDegrees = 12.0;  ///< uniform random turn added to azimuth and tilt (≥ 0)
    std::uint64_t seed = 0;
    /// Region of the texture atlas the leaf maps to: u0, v0, u1, v1 in glTF UVs (origin at the
    /// image's top-left); the leaf's base is at the bottom centre (v1), its tip at the top (v0).
    std::array<float, 4> atlas{0.0f, 0.0f, 1.0f, 1.0f};
    /// LODs: keep this fraction of the leaves (the same leaves at every level, picked by their
    /// hashed keys, nested: a smaller fraction keeps a subset) and scale the kept ones by
    /// 1/√keep so the foliage covers about the same area. In (0, 1].
    double keep = 1.0;
    /// No leaf grows from a point below this height (y, model units): e.g. the ground, so root
    /// systems stay bare. −∞ = everywhere.
    double minHeight = -std::numeric_limits<double>::infinity();
    Material material{"leaves", {0.22f, 0.45f, 0.13f, 1.0f}, 0.0f, 0.7f, true};
};

/// Throws Error naming the first invalid field, its valid range and units.
void validateLeafParams(const LeafParams& params);

/// One placed leaf.
struct LeafPlacement {
    Vec3 base;          ///< where it grows out of the bark
    Vec3 axis;          ///< unit, base → tip
    Vec3 normal;        ///< unit, the blade's front (turned upwards), ⊥ axis
    double length;      ///< model units
    double width;       ///< model units
    NodeId node;        ///< the edge (into this node) it grows on
    double t;           ///< where along that edge, 0 (parent) … 1 (node)
    std::uint64_t key;  ///< stable hash of its branch and slot: its random stream and LOD rank
};

/// Places leaves: `perTip` at every tip (a node without children whose edge is drawn) and,
/// with perLength > 0, one every 1/perLength along each branch (a chain of equal branch depth,
/// include/ramus/tree_wind.hpp) where it is within `zone` of a tip. Leaf k of a branch turns
/// k · phyllotaxis around it; randomness comes from Rng::forStream(seed, key), so a leaf does
/// not depend on the order or the number of others. Ordered by node, then slot; `keep` < 1
/// drops all but the highest-ranked fraction. `radii` (computeEdgeRadii) puts bases on the
/// bark. Empty tree or no tips → empty.
std::vector<LeafPlacement> placeLeaves(const BranchTree& tree, std::span<const double> radii,
                                       const LeafParams& params);

/// The leaf mesh for `tree`: placeLeaves, then one card or blade per leaf, in mesh "leaves"
/// with one primitive "leaves" (params.material, made double-sided), positions, unit normals,
/// tangents (w = +1), uvs in the atlas region and, with tube.windAttributes, the wind
/// attributes (the leaf moves with the point of the branch it sits on; `_WIND_LEAF` gives a
/// per-leaf phase and a flutter weight from 0 at its base to 1 at its tip). Radii and the
/// automatic size follow `tube`. No leaves → empty mesh without primitives.
Mesh buildLeafMesh(const BranchTree& tree, const LeafParams& params,
                   const TubeMeshParams& tube = {});

/// The `{ . }` polygons of an L-system as leaves: buildPolygonMesh with params.material, UVs
/// mapped into params.atlas and, with tube.windAttributes, wind data from polygonNodes (the
/// node each polygon grows from) and a flutter weight rising from the polygon's first vertex.
/// Layout as TurtleResult (polygonNodes: one node per polygon).
Mesh buildLeafPolygons(const BranchTree& tree, std::span<const Vec3> vertices,
                       std::span<const std::uint32_t> offsets, std::span<const NodeId> polygonNodes,
                       const LeafParams& params, const TubeMeshParams& tube = {});

/// Half the width of the blade outline (and of the default leaf texture's silhouette) at
/// y ∈ [0, 1] from base to tip, as a fraction of the leaf's width: 0 at both ends, at most 0.5.
double leafOutlineHalfWidth(double y);

}  // namespace ramus
