// Leaves: placed on tips and near them, deterministic per seed and independent of the rest of
// the tree, phyllotaxis, atlas UVs, LOD thinning, blade winding, wind data, validation.
#include "ramus/leaves.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ramus/error.hpp"
#include "ramus/tree_wind.hpp"

namespace ramus {
namespace {

// A Y: trunk 0 → 1 (up 2), two branches from 1 to tips 2 and 3.
BranchTree yTree() {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3(0, 0, 0));
    const NodeId fork = tree.addChild(root, Vec3(0, 2, 0));
    tree.addChild(fork, Vec3(-1, 3, 0));
    tree.addChild(fork, Vec3(1, 3, 0));
    return tree;
}

LeafParams plainLeaves() {
    LeafParams p;
    p.size = 0.5;
    p.perTip = 3;
    p.seed = 11;
    return p;
}

TEST(Leaves, PerTipLeavesSitOnEveryTipAndNowhereElse) {
    const BranchTree tree = yTree();
    const std::vector<double> radii(tree.size(), 0.05);
    const std::vector<LeafPlacement> leaves = placeLeaves(tree, radii, plainLeaves());
    ASSERT_EQ(leaves.size(), 6u);
    for (const LeafPlacement& leaf : leaves) {
        EXPECT_TRUE(leaf.node == 2 || leaf.node == 3);
        const Vec3 tip = tree.node(leaf.node).position;
        // Within a few leaf lengths of the tip, on the bark (radius 0.05 from the axis).
        EXPECT_LT((leaf.base - tip).norm(), 0.5);
        EXPECT_NEAR(leaf.axis.norm(), 1.0, 1e-12);
        EXPECT_NEAR(leaf.normal.norm(), 1.0, 1e-12);
        EXPECT_NEAR(leaf.axis.dot(leaf.normal), 0.0, 1e-9);
        EXPECT_GE(leaf.normal.y(), 0.0);  // the blade faces up
        EXPECT_GE(leaf.length, 0.5 * 0.75 - 1e-12);
        EXPECT_LE(leaf.length, 0.5 * 1.25 + 1e-12);
    }
}

TEST(Leaves, SameSeedGivesTheSameLeavesAnotherSeedOthers) {
    const BranchTree tree = yTree();
    const std::vector<double> radii(tree.size(), 0.05);
    LeafParams p = plainLeaves();
    const auto a = placeLeaves(tree, radii, p);
    const auto b = placeLeaves(tree, radii, p);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].base, b[i].base);
        EXPECT_EQ(a[i].axis, b[i].axis);
        EXPECT_EQ(a[i].length, b[i].length);
    }
    p.seed = 12;
    const auto c = placeLeaves(tree, radii, p);
    ASSERT_EQ(c.size(), a.size());
    EXPECT_NE(c[1].axis, a[1].axis);
}

TEST(Leaves, ALeafDoesNotDependOnTheRestOfTheTree) {
    BranchTree tree = yTree();
    const std::vector<double> radii(8, 0.05);
    const auto before = placeLeaves(tree, radii, plainLeaves());
    // A new branch grown later (new ids at the end) leaves the old tips' leaves unchanged.
    tree.addChild(0, Vec3(2, 1, 0));
    const auto after = placeLeaves(tree, radii, plainLeaves());
    ASSERT_EQ(after.size(), before.size() + 3);
    for (const LeafPlacement& old : before) {
        const auto same = std::find_if(after.begin(), after.end(),
                                       [&](const LeafPlacement& l) { return l.key == old.key; });
        ASSERT_NE(same, after.end());
        EXPECT_EQ(same->base, old.base);
        EXPECT_EQ(same->axis, old.axis);
        EXPECT_EQ(same->normal, old.normal);
    }
}

TEST(Leaves, AlongABranchConsecutiveLeavesTurnByThePhyllotaxisAngle) {
    BranchTree tree;
    NodeId n = tree.addRoot(Vec3::Zero());
    for (int i = 1; i <= 10; ++i) n = tree.addChild(n, Vec3(0, i, 0));
    LeafParams p;
    p.perTip = 0;
    p.perLength = 2.0;  // a leaf every 0.5
    p.zone = 100.0;
    p.size = 0.3;
    p.jitterDegrees = 0.0;
    p.tiltDegrees = 90.0;  // straight out: the axis is the azimuth direction
    const std::vector<double> radii(tree.size(), 0.0);
    const auto leaves = placeLeaves(tree, radii, p);
    ASSERT_EQ(leaves.size(), 20u);  // slots at 0.25, 0.75, …, 9.75
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        EXPECT_NEAR(leaves[i].base.y(), 0.25 + 0.5 * static_cast<double>(i), 1e-9);
        if (i == 0) continue;
        const Vec3& a = leaves[i - 1].axis;
        const Vec3& b = leaves[i].axis;
        double turn = radToDeg(std::atan2(a.cross(b).y(), a.dot(b)));
        if (turn < 0.0) turn += 360.0;
        EXPECT_NEAR(turn, 137.5, 1e-6);
    }
}

TEST(Leaves, PerLengthLeavesStayWithinTheZoneOfATip) {
    BranchTree tree;
    NodeId n = tree.addRoot(Vec3::Zero());
    for (int i = 1; i <= 10; ++i) n = tree.addChild(n, Vec3(0, i, 0));
    LeafParams p;
    p.perTip = 0;
    p.perLength = 4.0;
    p.zone = 2.0;
    p.size = 0.3;
    const std::vector<double> radii(tree.size(), 0.0);
    const auto leaves = placeLeaves(tree, radii, p);
    EXPECT_EQ(leaves.size(), 8u);  // slots 8.125 … 9.875
    for (const LeafPlacement& leaf : leaves) EXPECT_GE(leaf.base.y(), 8.0);
}

TEST(Leaves, KeepThinsToANestedSubsetOfGrownLeaves) {
    BranchTree tree;
    NodeId n = tree.addRoot(Vec3::Zero());
    for (int i = 1; i <= 10; ++i) n = tree.addChild(n, Vec3(0, i, 0));
    LeafParams p;
    p.perLength = 5.0;
    p.zone = 100.0;
    p.size = 0.3;
    const std::vector<double> radii(tree.size(), 0.0);
    const auto all = placeLeaves(tree, radii, p);
    p.keep = 0.5;
    const auto half = placeLeaves(tree, radii, p);
    p.keep = 0.25;
    const auto quarter = placeLeaves(tree, radii, p);
    EXPECT_EQ(half.size(), static_cast<std::size_t>(std::llround(0.5 * all.size())));
    EXPECT_EQ(quarter.size(), static_cast<std::size_t>(std::llround(0.25 * all.size())));
    std::set<std::uint64_t> halfKeys;
    for (const auto& l : half) halfKeys.insert(l.key);
    for (const auto& l : quarter) EXPECT_EQ(halfKeys.count(l.key), 1u);
    EXPECT_NEAR(half[0].length / all[0].length, 0.0, 100.0);  // sizes grow by 1/sqrt(keep):
    for (const auto& l : half) {
        const auto same = std::find_if(all.begin(), all.end(),
                                       [&](const LeafPlacement& x) { return x.key == l.key; });
        ASSERT_NE(same, all.end());
        EXPECT_NEAR(l.length, same->length * std::sqrt(2.0), 1e-12);
    }
}

TEST(Leaves, BladeMeshIsCounterClockwiseAroundItsNormalWithUvsInTheAtlas) {
    const BranchTree tree = yTree();
    LeafParams p = plainLeaves();
    p.atlas = {0.5f, 0.25f, 1.0f, 0.75f};
    TubeMeshParams tube;
    tube.leafRadius = 0.05;
    const Mesh mesh = buildLeafMesh(tree, p, tube);
    ASSERT_EQ(mesh.vertexCount(), 6u * 11u);
    ASSERT_EQ(mesh.triangleCount(), 6u * 12u);
    ASSERT_EQ(mesh.primitives.size(), 1u);
    EXPECT_EQ(mesh.primitives[0].name, "leaves");
    EXPECT_TRUE(mesh.materials[0].doubleSided);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const Vec3f a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                    c = mesh.positions[mesh.indices[t + 2]];
        const Vec3f face = (b - a).cross(c - a);
        ASSERT_GT(face.norm(), 0.0f);
        EXPECT_GT(face.normalized().dot(mesh.normals[mesh.indices[t]]), 0.9f);
    }
    for (const Vec2f& uv : mesh.uvs) {
        EXPECT_GE(uv.x(), 0.5f);
        EXPECT_LE(uv.x(), 1.0f);
        EXPECT_GE(uv.y(), 0.25f);
        EXPECT_LE(uv.y(), 0.75f);
    }
}

TEST(Leaves, CardsAreQuadsAndCarryWindDataOfTheirBranchPoint) {
    const BranchTree tree = yTree();
    LeafParams p = plainLeaves();
    p.shape = LeafShape::Card;
    TubeMeshParams tube;
    tube.windAttributes = true;
    tube.windSeed = 5;
    const Mesh mesh = buildLeafMesh(tree, p, tube);
    ASSERT_EQ(mesh.vertexCount(), 24u);
    ASSERT_EQ(mesh.triangleCount(), 12u);
    const VertexAttribute* w = findAttribute(mesh, kWindAttribute);
    const VertexAttribute* leaf = findAttribute(mesh, kWindLeafAttribute);
    ASSERT_NE(w, nullptr);
    ASSERT_NE(leaf, nullptr);
    const TreeWind wind(tree, 5);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        // Tip 2 continues the trunk (level 0), tip 3 is a side branch (level 1).
        const float level = w->values[4 * v];
        ASSERT_TRUE(level == 0.0f || level == 1.0f);
        EXPECT_EQ(w->values[4 * v + 1], wind.at(level == 0.0f ? 2 : 3).phase);
        EXPECT_LE(w->values[4 * v + 3], wind.at(level == 0.0f ? 2 : 3).distance);
        EXPECT_GT(w->values[4 * v + 3], 0.0f);
        const float flutter = leaf->values[2 * v + 1];
        EXPECT_TRUE(flutter == 0.0f || flutter == 1.0f);  // base or tip corner of the card
        // One phase per leaf: the four corners of a card share it.
        EXPECT_EQ(leaf->values[2 * v], leaf->values[2 * (v / 4 * 4)]);
    }
}

TEST(Leaves, NoTipsOrNoTreeGiveNoLeaves) {
    EXPECT_TRUE(placeLeaves(BranchTree{}, {}, plainLeaves()).empty());
    BranchTree single;
    single.addRoot(Vec3::Zero());
    EXPECT_TRUE(buildLeafMesh(single, plainLeaves()).positions.empty());
}

TEST(Leaves, LeavesBelowTheMinimumHeightAreLeftOut) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    tree.addChild(root, Vec3(0, 2, 0));
    tree.addChild(root, Vec3(0, -2, 0));  // a root
    LeafParams p = plainLeaves();
    p.minHeight = 0.0;
    const auto leaves = placeLeaves(tree, std::vector<double>(3, 0.0), p);
    ASSERT_EQ(leaves.size(), 3u);
    for (const auto& leaf : leaves) EXPECT_EQ(leaf.node, 1);
}

TEST(Leaves, InvalidSettingsAreNamedErrors) {
    LeafParams p;
    p.perTip = -1;
    EXPECT_THROW(validateLeafParams(p), Error);
    p = LeafParams{};
    p.widthRatio = 0.0;
    EXPECT_THROW(validateLeafParams(p), Error);
    p = LeafParams{};
    p.keep = 0.0;
    EXPECT_THROW(validateLeafParams(p), Error);
    p = LeafParams{};
    p.atlas = {0.5f, 0.0f, 0.5f, 1.0f};
    EXPECT_THROW(validateLeafParams(p), Error);
    try {
        p = LeafParams{};
        p.sizeVariation = 1.5;
        validateLeafParams(p);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("size_variation"), std::string::npos);
    }
    EXPECT_THROW(parseLeafShape("round"), Error);
}

}  // namespace
}  // namespace ramus
