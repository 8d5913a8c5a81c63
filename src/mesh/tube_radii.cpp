// Based on: seed 002 §3.5 eq 3.6 (Murray's rule r^g = Σ r_child^g, tips r_0) and §4.4.3
// ("Radiusberechnung": leaf radius, growth exponent, trunk multiplier); SPEC §D.
//
// Edge radii for the tube mesher: one value per node, the radius of the edge ending at it.
#include <cmath>
#include <vector>

#include "ramus/tube_mesher.hpp"

namespace ramus {
namespace {

// r_0 = 4 % of the mean length of the drawn (not hidden) edges; 0 when nothing is drawn.
double automaticLeafRadius(const BranchTree& tree) {
    double total = 0.0;
    std::size_t count = 0;
    for (const BranchNode& node : tree.nodes()) {
        if (node.parent == kNoNode || node.hidden) continue;
        total += (node.position - tree.node(node.parent).position).norm();
        ++count;
    }
    return count == 0 ? 0.0 : 0.04 * total / static_cast<double>(count);
}

std::vector<double> murrayRadii(const BranchTree& tree, const TubeMeshParams& params) {
    const double leaf = params.leafRadius > 0.0 && std::isfinite(params.leafRadius)
                            ? params.leafRadius
                            : automaticLeafRadius(tree);
    const double exponent = params.radiusExponent > 0.0 && std::isfinite(params.radiusExponent)
                                ? params.radiusExponent
                                : 2.0;
    if (exponent != 2.0) return computeMurrayRadii(tree, leaf, exponent);
    // g = 2 (the default): the same sweep as computeMurrayRadii with squares and sqrt instead
    // of pow, which dominates the radius pass otherwise.
    const std::size_t n = tree.size();
    std::vector<double> sumSquares(n, 0.0);
    std::vector<double> radius(n, leaf);
    for (std::size_t i = n; i-- > 0;) {
        const BranchNode& node = tree.nodes()[i];
        if (node.childCount > 0) radius[i] = std::sqrt(sumSquares[i]);
        if (node.parent != kNoNode) {
            sumSquares[static_cast<std::size_t>(node.parent)] += radius[i] * radius[i];
        }
    }
    return radius;
}

bool anyWidth(const BranchTree& tree) {
    for (const BranchNode& node : tree.nodes()) {
        if (node.radius > 0.0) return true;
    }
    return false;
}

// Widths (turtle `!`): a node without a radius inherits its parent's. The root, when unset,
// takes the radius of its chain's first edge (the seed's "root end radius"). Nodes with no set
// radius on their whole path from the root fall back to Murray's rule.
std::vector<double> widthRadii(const BranchTree& tree, const TubeMeshParams& params) {
    const std::size_t n = tree.size();
    std::vector<double> radius(n, 0.0);
    bool unresolved = false;
    // Parents have smaller ids than their children: one forward sweep resolves inheritance.
    for (std::size_t i = 0; i < n; ++i) {
        const BranchNode& node = tree.nodes()[i];
        if (node.radius > 0.0) {
            radius[i] = node.radius;
        } else if (node.parent != kNoNode) {
            radius[i] = radius[static_cast<std::size_t>(node.parent)];
        }
        unresolved = unresolved || (radius[i] <= 0.0 && i > 0);
    }
    const BranchNode& root = tree.node(0);
    if (radius[0] <= 0.0 && root.firstChild != kNoNode) {
        radius[0] = radius[static_cast<std::size_t>(root.firstChild)];
    }
    if (unresolved || radius[0] <= 0.0) {
        const std::vector<double> murray = murrayRadii(tree, params);
        for (std::size_t i = 0; i < n; ++i) {
            if (radius[i] <= 0.0) radius[i] = murray[i];
        }
    }
    return radius;
}

}  // namespace

std::vector<double> computeEdgeRadii(const BranchTree& tree, const TubeMeshParams& params) {
    if (tree.empty()) return {};
    const bool widths = anyWidth(tree);
    switch (params.radiusMode) {
        case RadiusMode::Murray:
            return murrayRadii(tree, params);
        case RadiusMode::Widths:
        case RadiusMode::Auto:
            return widths ? widthRadii(tree, params) : murrayRadii(tree, params);
    }
    return murrayRadii(tree, params);
}

}  // namespace ramus
