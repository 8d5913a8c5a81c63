// Based on: seed 002 §3.4 eq 3.4–3.5 (branch-angle reduction), §3.5 eq 3.8 and §4.4.3 (curve
// reduction, walked recursively from the root); Runions et al. 2007 §2 (post-processing).
#include <cmath>
#include <utility>

#include "ramus/colonize.hpp"

namespace ramus {

BranchTree reduceBranchAngles(const BranchTree& tree) {
    BranchTree result = tree;
    for (std::size_t v = 0; v < tree.size(); ++v) {
        const BranchNode& node = tree.nodes()[v];
        if (node.childCount < 2) continue;  // one child: m⃗ is the child itself, nothing moves
        // m⃗ = p_v + Σ(p_vi − p_v)/m (eq 3.4), from the original positions.
        Vec3 offsetSum = Vec3::Zero();
        for (NodeId c = node.firstChild; c != kNoNode; c = tree.node(c).nextSibling) {
            offsetSum += tree.node(c).position - node.position;
        }
        const Vec3 mean = node.position + offsetSum / static_cast<double>(node.childCount);
        // p_vi += (m⃗ − p_vi)/2 (eq 3.5).
        for (NodeId c = node.firstChild; c != kNoNode; c = tree.node(c).nextSibling) {
            const Vec3& p = tree.node(c).position;
            result.node(c).position = p + (mean - p) / 2.0;
        }
    }
    return result;
}

namespace {

Vec3 unitOrZero(const Vec3& v) {
    const double n = v.norm();
    return n > 0.0 ? Vec3(v / n) : Vec3::Zero();
}

}  // namespace

BranchTree reduceCurves(const BranchTree& tree, double maxDot) {
    BranchTree result;
    if (tree.empty()) return result;
    result.reserve(tree.size());
    // Depth-first from the root; each stack entry is (original node, its parent in the result).
    // Children are pushed in reverse so they are added in their original order.
    std::vector<std::pair<NodeId, NodeId>> stack;
    const BranchNode& root = tree.node(0);
    const NodeId newRoot = result.addRoot(root.position, root.radius);
    result.node(newRoot).hidden = root.hidden;
    std::vector<NodeId> children;
    auto pushChildren = [&](NodeId original, NodeId parentInResult) {
        children.clear();
        for (NodeId c = tree.node(original).firstChild; c != kNoNode;
             c = tree.node(c).nextSibling) {
            children.push_back(c);
        }
        for (auto it = children.rbegin(); it != children.rend(); ++it) {
            stack.emplace_back(*it, parentInResult);
        }
    };
    pushChildren(0, newRoot);
    while (!stack.empty()) {
        auto [v, keptParent] = stack.back();
        stack.pop_back();
        const BranchNode& node = tree.node(v);
        // Eq 3.8 with v' = the kept parent: remove v when the path barely bends there.
        if (node.childCount == 1 && !node.hidden && !tree.node(node.firstChild).hidden) {
            const Vec3 r1 = unitOrZero(node.position - result.node(keptParent).position);
            const Vec3 r2 = unitOrZero(tree.node(node.firstChild).position - node.position);
            if (r1.dot(r2) > maxDot) {
                stack.emplace_back(node.firstChild, keptParent);
                continue;
            }
        }
        const NodeId kept = result.addChild(keptParent, node.position, node.radius);
        result.node(kept).hidden = node.hidden;
        pushChildren(v, kept);
    }
    return result;
}

}  // namespace ramus
