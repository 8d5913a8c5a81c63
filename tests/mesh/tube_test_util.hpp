// Small trees and mesher settings shared by the tube mesher's tests.
#pragma once

#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus::test {

/// An unbranched chain through `points` (root first).
inline BranchTree chainTree(const std::vector<Vec3>& points) {
    BranchTree tree;
    NodeId node = tree.addRoot(points.front());
    for (std::size_t i = 1; i < points.size(); ++i) node = tree.addChild(node, points[i]);
    return tree;
}

/// Tube settings with exactly `n` ring segments everywhere, tips capped or not.
inline TubeMeshParams fixedSegments(int n, bool caps) {
    TubeMeshParams params;
    params.minSegments = n;
    params.maxSegments = n;
    params.capTips = caps;
    return params;
}

}  // namespace ramus::test
