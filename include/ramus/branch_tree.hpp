// The shared tree representation (seed 002 §2.4.1, §4.1; SPEC §A): a rooted tree of points.
// L-systems (turtle) and space colonization both produce it; the tube mesher consumes it.
#pragma once

#include <cstdint>
#include <vector>

#include "ramus/math.hpp"

namespace ramus {

using NodeId = std::int32_t;
inline constexpr NodeId kNoNode = -1;

/// One node. Children are an ordered singly linked list (firstChild → nextSibling), so adding
/// a child is O(1) and no node owns a heap allocation.
struct BranchNode {
    Vec3 position = Vec3::Zero();
    NodeId parent = kNoNode;
    NodeId firstChild = kNoNode;
    NodeId lastChild = kNoNode;
    NodeId nextSibling = kNoNode;
    std::uint32_t childCount = 0;
    std::uint32_t depth = 0;        ///< edges to the root
    std::uint32_t branchDepth = 0;  ///< Z(v), seed 002 eq 3.7 (see BranchTree::addChild)
    /// Radius of the edge ending at this node (e.g. half the turtle width set by `!`);
    /// 0 = not set, the mesher then computes radii (Murray's rule).
    double radius = 0.0;
    /// The edge ending at this node is not drawn (turtle `f`): the mesher starts a new chain
    /// at its children. The node still belongs to the tree so it stays connected.
    bool hidden = false;
};

/// Rooted tree stored as a flat array; node 0 is the root once one exists. Nodes are never
/// removed in place (post-processing builds a new tree), so ids are stable.
class BranchTree {
public:
    /// Creates the root at `position`; the tree must be empty. Returns its id (0).
    NodeId addRoot(const Vec3& position, double radius = 0.0);

    /// Appends a child of `parent` at `position` (after the existing children) and returns it.
    /// Branch depth Z (seed 002 eq 3.7) is fixed here and never changes afterwards:
    /// Z = Z(parent) if the new node is the parent's only child, else Z(parent) + 1.
    NodeId addChild(NodeId parent, const Vec3& position, double radius = 0.0);

    bool empty() const { return nodes_.empty(); }
    std::size_t size() const { return nodes_.size(); }
    /// Number of edges (size() - 1 for a non-empty tree).
    std::size_t edgeCount() const { return nodes_.empty() ? 0 : nodes_.size() - 1; }

    const BranchNode& node(NodeId id) const { return nodes_[static_cast<std::size_t>(id)]; }
    BranchNode& node(NodeId id) { return nodes_[static_cast<std::size_t>(id)]; }
    const std::vector<BranchNode>& nodes() const { return nodes_; }

    /// Children of `id` in insertion order (allocates; for tests and tools, not hot loops).
    std::vector<NodeId> children(NodeId id) const;

    void reserve(std::size_t n) { nodes_.reserve(n); }

    /// Bounding box of all node positions.
    Aabb bounds() const;

private:
    std::vector<BranchNode> nodes_;
};

/// Murray's rule radii (seed 002 §3.4): tips get `leafRadius`, an inner node v gets
/// r_v = (Σ r_child^exponent)^(1/exponent). Result is indexed by node id; a node's radius is the
/// radius of the edge ending at it (the root's value is its trunk radius before any multiplier).
std::vector<double> computeMurrayRadii(const BranchTree& tree, double leafRadius, double exponent);

}  // namespace ramus
