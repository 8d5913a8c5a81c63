#include "ramus/branch_tree.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ramus {
namespace {

TEST(BranchTree, FirstChildContinuesTheBranchLaterChildrenStartNewOnes) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    const NodeId a = tree.addChild(root, Vec3(0, 1, 0));
    const NodeId b = tree.addChild(a, Vec3(0, 2, 0));
    const NodeId c = tree.addChild(a, Vec3(1, 2, 0));
    const NodeId d = tree.addChild(c, Vec3(2, 3, 0));
    EXPECT_EQ(tree.node(a).branchDepth, 0u);
    EXPECT_EQ(tree.node(b).branchDepth, 0u);
    EXPECT_EQ(tree.node(c).branchDepth, 1u);
    EXPECT_EQ(tree.node(d).branchDepth, 1u);
    EXPECT_EQ(tree.node(d).depth, 3u);
    EXPECT_EQ(tree.children(a), (std::vector<NodeId>{b, c}));
    EXPECT_EQ(tree.edgeCount(), 4u);
}

TEST(BranchTree, BoundsCoverAllNodes) {
    BranchTree tree;
    tree.addChild(tree.addRoot(Vec3(-1, 0, 2)), Vec3(3, 4, -5));
    const Aabb box = tree.bounds();
    EXPECT_EQ(box.min, Vec3(-1, 0, -5));
    EXPECT_EQ(box.max, Vec3(3, 4, 2));
}

TEST(MurrayRadii, TwoEqualTipsGiveSqrtTwoWithExponentTwo) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    const NodeId fork = tree.addChild(root, Vec3(0, 1, 0));
    tree.addChild(fork, Vec3(-1, 2, 0));
    tree.addChild(fork, Vec3(1, 2, 0));
    const std::vector<double> r = computeMurrayRadii(tree, 1.0, 2.0);
    EXPECT_DOUBLE_EQ(r[2], 1.0);
    EXPECT_DOUBLE_EQ(r[3], 1.0);
    EXPECT_DOUBLE_EQ(r[1], std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(r[0], std::sqrt(2.0));  // one child: radius carries over
}

TEST(MurrayRadii, ExponentThreeSumsCubes) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    for (int i = 0; i < 8; ++i) tree.addChild(root, Vec3(i, 1, 0));
    EXPECT_NEAR(computeMurrayRadii(tree, 0.5, 3.0)[0], 1.0, 1e-12);  // (8 · 0.125)^(1/3)
}

}  // namespace
}  // namespace ramus
