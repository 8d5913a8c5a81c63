// Wind data: branches follow the tube mesher's chains; phase constant along a branch, distance
// growing from 0 at the branch base, relative distance in [0, 1]; the tube mesh carries them.
#include "ramus/tree_wind.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ramus/tube_mesher.hpp"

namespace ramus {
namespace {

// A trunk of three unit edges up +Y (nodes 0, 1, 2, 5) with a side branch of two unit edges
// along +X from node 1 (nodes 3, 4).
BranchTree forkTree() {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3(0, 0, 0));
    const NodeId a = tree.addChild(root, Vec3(0, 1, 0));
    const NodeId b = tree.addChild(a, Vec3(0, 2, 0));   // trunk continues (first child)
    const NodeId s1 = tree.addChild(a, Vec3(1, 1, 0));  // side branch (second child)
    tree.addChild(s1, Vec3(2, 1, 0));
    tree.addChild(b, Vec3(0, 3, 0));
    return tree;
}

TEST(TreeWind, TrunkAndSideBranchAreSeparateBranchesWithTheirOwnLevels) {
    const BranchTree tree = forkTree();
    const TreeWind wind(tree, 7);
    EXPECT_EQ(wind.branchOf(0), 0);
    EXPECT_EQ(wind.branchOf(1), 0);
    EXPECT_EQ(wind.branchOf(2), 0);
    EXPECT_EQ(wind.branchOf(5), 0);
    EXPECT_EQ(wind.branchOf(3), 3);
    EXPECT_EQ(wind.branchOf(4), 3);
    EXPECT_EQ(wind.at(5).level, 0.0f);
    EXPECT_EQ(wind.at(4).level, 1.0f);
}

TEST(TreeWind, DistanceGrowsAlongABranchFromZeroAtItsBase) {
    const BranchTree tree = forkTree();
    const TreeWind wind(tree, 7);
    EXPECT_FLOAT_EQ(wind.at(0).distance, 0.0f);
    EXPECT_FLOAT_EQ(wind.at(1).distance, 1.0f);
    EXPECT_FLOAT_EQ(wind.at(2).distance, 2.0f);
    EXPECT_FLOAT_EQ(wind.at(5).distance, 3.0f);
    EXPECT_FLOAT_EQ(wind.at(5).relative, 1.0f);
    EXPECT_FLOAT_EQ(wind.at(2).relative, 2.0f / 3.0f);
    // The side branch starts at 0 where it leaves the trunk, pivoting about that node.
    EXPECT_FLOAT_EQ(wind.at(3, 0.0).distance, 0.0f);
    EXPECT_FLOAT_EQ(wind.at(3, 0.5).distance, 0.5f);
    EXPECT_FLOAT_EQ(wind.at(4).distance, 2.0f);
    EXPECT_FLOAT_EQ(wind.at(4).relative, 1.0f);
    EXPECT_EQ(wind.at(4).pivot, Vec3f(0, 1, 0));
    EXPECT_EQ(wind.at(2).pivot, Vec3f(0, 0, 0));
}

TEST(TreeWind, PhaseIsConstantAlongABranchAndDiffersBetweenBranchesAndSeeds) {
    const BranchTree tree = forkTree();
    const TreeWind wind(tree, 7);
    EXPECT_EQ(wind.at(1).phase, wind.at(5).phase);
    EXPECT_EQ(wind.at(3).phase, wind.at(4).phase);
    EXPECT_NE(wind.at(1).phase, wind.at(4).phase);
    EXPECT_NE(TreeWind(tree, 8).at(4).phase, wind.at(4).phase);
    for (NodeId i = 0; i < 6; ++i) {
        EXPECT_GE(wind.at(i).phase, 0.0f);
        EXPECT_LT(wind.at(i).phase, 1.0f);
    }
}

TEST(TreeWind, TubeMeshCarriesTheAttributesWithTheirDocumentedRanges) {
    TubeMeshParams params;
    params.windAttributes = true;
    params.windSeed = 3;
    params.minSegments = params.maxSegments = 5;
    const BranchTree tree = forkTree();
    const Mesh mesh = buildTubeMesh(tree, params);
    const VertexAttribute* w = findAttribute(mesh, kWindAttribute);
    const VertexAttribute* pivot = findAttribute(mesh, kWindPivotAttribute);
    const VertexAttribute* leaf = findAttribute(mesh, kWindLeafAttribute);
    ASSERT_NE(w, nullptr);
    ASSERT_NE(pivot, nullptr);
    ASSERT_NE(leaf, nullptr);
    ASSERT_EQ(w->values.size(), 4 * mesh.vertexCount());
    ASSERT_EQ(pivot->values.size(), 3 * mesh.vertexCount());
    ASSERT_EQ(leaf->values.size(), 2 * mesh.vertexCount());
    const TreeWind wind(tree, 3);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const float* x = &w->values[4 * v];
        EXPECT_TRUE(x[0] == 0.0f || x[0] == 1.0f);
        EXPECT_TRUE(x[1] == wind.at(1).phase || x[1] == wind.at(4).phase);
        EXPECT_GE(x[2], 0.0f);
        EXPECT_LE(x[2], 1.0f);
        EXPECT_GE(x[3], 0.0f);
        EXPECT_EQ(leaf->values[2 * v], 0.0f);
        EXPECT_EQ(leaf->values[2 * v + 1], 0.0f);
        // Bark vertices sit at their ring: the distance matches the height on the trunk.
        const Vec3f p = mesh.positions[v];
        if (x[0] == 0.0f) EXPECT_NEAR(x[3], p.y(), 1e-4f);
        if (x[0] == 1.0f) EXPECT_NEAR(x[3], p.x(), 0.2f);  // ring radius around the side axis
    }
}

TEST(TreeWind, EmptyTreeGivesNoData) {
    const TreeWind wind(BranchTree{}, 1);
    EXPECT_EQ(wind.size(), 0u);
}

}  // namespace
}  // namespace ramus
