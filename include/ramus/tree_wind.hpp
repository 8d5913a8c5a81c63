// Wind data for game engines (issue 9): per-branch hierarchy level, phase and distance from the
// branch base, computed on a BranchTree and written by the meshers as custom vertex attributes.
#pragma once

#include <cstdint>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/mesh.hpp"

namespace ramus {

/// Names of the custom vertex attributes (docs/export.md "Wind data").
inline constexpr const char* kWindAttribute = "_WIND";             ///< VEC4, see WindSample
inline constexpr const char* kWindPivotAttribute = "_WIND_PIVOT";  ///< VEC3 branch base
inline constexpr const char* kWindLeafAttribute = "_WIND_LEAF";    ///< VEC2 leaf phase, flutter

/// The wind data of one point on a branch. A *branch* is a chain of edges of equal branch
/// depth Z (seed 002 eq 3.7): the trunk, then each side branch from the node it grows out of
/// to its tip — the same chains the tube mesher puts one tube along.
struct WindSample {
    float level = 0.0f;     ///< the branch's Z: 0 trunk, 1 its side branches, …
    float phase = 0.0f;     ///< in [0, 1): hashed from (seed, branch), the same along a branch
    float relative = 0.0f;  ///< distance from the branch base / branch length, in [0, 1]
    float distance = 0.0f;  ///< distance from the branch base along the branch, model units
    Vec3f pivot = Vec3f::Zero();  ///< the branch base (where it grows out of its parent)
};

/// Per-node wind data: node i's entry describes the end of the edge into i (the root: its
/// trunk's base). Hidden edges (turtle `f`) count like drawn ones, so a branch continues across
/// them. Linear in the tree size; empty tree → empty result.
class TreeWind {
public:
    TreeWind() = default;
    TreeWind(const BranchTree& tree, std::uint64_t seed);

    /// The node's branch (its first node; the root's branch is 0).
    NodeId branchOf(NodeId node) const { return branch_[static_cast<std::size_t>(node)]; }
    /// Wind data at the end of the edge into `node` (t = 1) or at a fraction t ∈ [0, 1] along
    /// it from its parent (the branch is the node's; at t = 0 a side branch starts at distance
    /// 0). The root gives its branch base for every t.
    WindSample at(NodeId node, double t = 1.0) const;
    std::size_t size() const { return branch_.size(); }

private:
    std::vector<NodeId> branch_, parent_;
    std::vector<float> distance_, level_;
    std::vector<Vec3f> position_;
    std::vector<float> branchLength_, branchPhase_;  // indexed by the branch's first node
};

/// The wind attributes of a mesh being built, as flat arrays: sized once, then filled by
/// vertex ranges, then moved into the mesh as `_WIND` (VEC4: level, phase, relative,
/// distance), `_WIND_PIVOT` (VEC3) and `_WIND_LEAF` (VEC2: leaf phase in [0, 1), flutter
/// weight in [0, 1] from the leaf's base to its tip; (0, 0) on bark).
struct WindAttributes {
    std::vector<float> wind, pivot, leaf;

    void resize(std::size_t vertexCount);
    void reserve(std::size_t vertexCount);
    /// Vertices [first, first + count) get `sample` and the leaf pair (leafPhase, flutter).
    void set(std::size_t first, std::size_t count, const WindSample& sample, float leafPhase = 0.0f,
             float flutter = 0.0f);
    /// Appends `count` bark vertices (leaf pair (0, 0)) with `sample`, for meshers that grow
    /// their vertex arrays as they go.
    void append(std::size_t count, const WindSample& sample);
    /// Appends a copy of vertices [first, first + count) of `other`.
    void appendFrom(const WindAttributes& other, std::size_t first, std::size_t count);
    std::size_t vertexCount() const { return pivot.size() / 3; }
    /// Appends the three attributes to mesh.attributes (sizes must match its vertex count).
    void moveInto(Mesh& mesh);
};

}  // namespace ramus
