// Based on: seed 002 §2.4.1 (tree terms), eq 3.7 (branch depth Z), §3.4 (Murray's rule).
#include "ramus/branch_tree.hpp"

#include <cmath>

#include "ramus/error.hpp"

namespace ramus {

NodeId BranchTree::addRoot(const Vec3& position, double radius) {
    RAMUS_ASSERT(nodes_.empty());
    BranchNode root;
    root.position = position;
    root.radius = radius;
    nodes_.push_back(root);
    return 0;
}

NodeId BranchTree::addChild(NodeId parent, const Vec3& position, double radius) {
    RAMUS_ASSERT(parent >= 0 && static_cast<std::size_t>(parent) < nodes_.size());
    const auto id = static_cast<NodeId>(nodes_.size());
    BranchNode child;
    child.position = position;
    child.parent = parent;
    child.radius = radius;
    {
        BranchNode& p = nodes_[static_cast<std::size_t>(parent)];
        child.depth = p.depth + 1;
        // eq 3.7 evaluated at creation: the first child continues its parent's chain.
        child.branchDepth = p.childCount == 0 ? p.branchDepth : p.branchDepth + 1;
        if (p.lastChild == kNoNode) {
            p.firstChild = id;
        } else {
            nodes_[static_cast<std::size_t>(p.lastChild)].nextSibling = id;
        }
        p.lastChild = id;
        ++p.childCount;
    }
    nodes_.push_back(child);
    return id;
}

std::vector<NodeId> BranchTree::children(NodeId id) const {
    std::vector<NodeId> result;
    for (NodeId c = node(id).firstChild; c != kNoNode; c = node(c).nextSibling) result.push_back(c);
    return result;
}

Aabb BranchTree::bounds() const {
    Aabb box;
    for (const BranchNode& n : nodes_) box.add(n.position);
    return box;
}

std::vector<double> computeMurrayRadii(const BranchTree& tree, double leafRadius, double exponent) {
    const std::size_t n = tree.size();
    std::vector<double> sumPow(n, 0.0);
    std::vector<double> radius(n, leafRadius);
    // Children always have larger ids than their parents, so one reverse sweep visits every
    // child before its parent: O(n), no recursion.
    for (std::size_t i = n; i-- > 0;) {
        const BranchNode& node = tree.nodes()[i];
        if (node.childCount > 0) radius[i] = std::pow(sumPow[i], 1.0 / exponent);
        if (node.parent != kNoNode) {
            sumPow[static_cast<std::size_t>(node.parent)] += std::pow(radius[i], exponent);
        }
    }
    return radius;
}

}  // namespace ramus
