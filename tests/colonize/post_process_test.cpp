// Branch-angle reduction (seed 002 eq 3.4–3.5) and curve reduction (eq 3.8) on hand-computed
// examples.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "colonize_test_util.hpp"
#include "ramus/colonize.hpp"

namespace ramus::testing {
namespace {

void expectNear(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR((a - b).norm(), 0.0, 1e-12) << a.transpose() << " vs " << b.transpose();
}

TEST(BranchAngleReduction, TwoChildrenMoveHalfwayToTheirMean) {
    BranchTree tree;
    const NodeId v = tree.addRoot(Vec3::Zero());
    const NodeId c1 = tree.addChild(v, Vec3(-2, 2, 0));
    const NodeId c2 = tree.addChild(v, Vec3(4, 2, 0));
    const NodeId grandchild = tree.addChild(c1, Vec3(-3, 4, 0));
    const BranchTree reduced = reduceBranchAngles(tree);
    // m = p_v + ((-2,2,0) + (4,2,0)) / 2 = (1,2,0); p += (m - p) / 2.
    expectNear(reduced.node(c1).position, Vec3(-0.5, 2, 0));
    expectNear(reduced.node(c2).position, Vec3(2.5, 2, 0));
    expectNear(reduced.node(grandchild).position, Vec3(-3, 4, 0));  // grandchildren stay
    expectNear(reduced.node(v).position, Vec3::Zero());
    EXPECT_EQ(reduced.size(), tree.size());
}

TEST(BranchAngleReduction, ThreeChildrenOfAnOffsetNode) {
    BranchTree tree;
    const NodeId v = tree.addRoot(Vec3(1, 1, 1));
    const NodeId c1 = tree.addChild(v, Vec3(1, 3, 1));
    tree.addChild(v, Vec3(3, 1, 1));
    tree.addChild(v, Vec3(1, 1, 3));
    // m = (1,1,1) + (2,2,2)/3 = (5/3, 5/3, 5/3); c1 + (m - c1)/2 = (4/3, 7/3, 4/3).
    expectNear(reduceBranchAngles(tree).node(c1).position, Vec3(4.0 / 3, 7.0 / 3, 4.0 / 3));
}

TEST(BranchAngleReduction, AnOnlyChildDoesNotMove) {
    BranchTree tree;
    const NodeId v = tree.addRoot(Vec3::Zero());
    const NodeId c = tree.addChild(v, Vec3(3, 1, 0));
    expectNear(reduceBranchAngles(tree).node(c).position, Vec3(3, 1, 0));
}

TEST(BranchAngleReduction, ReducesTheAnglesBetweenSiblings) {
    ColonizeParams p;
    p.influenceRadius = 30;
    p.killRadius = 8;
    p.step = 4;
    const ColonizeResult r = colonize(p, randomPoints(500, -50, 50, 21));
    const BranchTree& tree = r.trees[0];
    const BranchTree reduced = reduceBranchAngles(tree);
    int forks = 0;
    for (std::size_t i = 0; i < tree.size(); ++i) {
        const BranchNode& n = tree.nodes()[i];
        if (n.childCount != 2) continue;
        auto angle = [&](const BranchTree& t) {
            const NodeId a = t.nodes()[i].firstChild;
            const NodeId b = t.node(a).nextSibling;
            const Vec3 da = (t.node(a).position - t.nodes()[i].position).normalized();
            const Vec3 db = (t.node(b).position - t.nodes()[i].position).normalized();
            return std::acos(std::clamp(da.dot(db), -1.0, 1.0));
        };
        EXPECT_LE(angle(reduced), angle(tree) + 1e-12);
        ++forks;
    }
    EXPECT_GT(forks, 10);
}

// root (0,0,0) → a (0,1,0) → b (0,2,0) → c (1,3,0)
BranchTree bentChain() {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    const NodeId a = tree.addChild(root, Vec3(0, 1, 0));
    const NodeId b = tree.addChild(a, Vec3(0, 2, 0));
    tree.addChild(b, Vec3(1, 3, 0));
    return tree;
}

TEST(CurveReduction, RemovesAStraightChainNodeAndKeepsTheBend) {
    // At a: <(0,1,0), (0,1,0)> = 1 > 0.9: removed. At b, measured from the kept parent (the
    // root): <(0,1,0), (1,1,0)/√2> = 0.707 < 0.9: kept.
    const BranchTree reduced = reduceCurves(bentChain(), 0.9);
    ASSERT_EQ(reduced.size(), 3u);
    expectNear(reduced.node(1).position, Vec3(0, 2, 0));
    EXPECT_EQ(reduced.node(1).parent, 0);
    expectNear(reduced.node(2).position, Vec3(1, 3, 0));
}

TEST(CurveReduction, ALowerMaximumRemovesTheBendToo) {
    const BranchTree reduced = reduceCurves(bentChain(), 0.5);  // 0.707 > 0.5
    ASSERT_EQ(reduced.size(), 2u);
    expectNear(reduced.node(1).position, Vec3(1, 3, 0));
}

TEST(CurveReduction, MaximumOneRemovesNothing) {
    EXPECT_EQ(reduceCurves(bentChain(), 1.0).size(), 4u);
}

TEST(CurveReduction, KeepsForksTipsAndBranchDepths) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    const NodeId v1 = tree.addChild(root, Vec3(0, 1, 0));  // Z 0, one child: removable
    const NodeId w = tree.addChild(root, Vec3(1, 1, 0));   // Z 1
    tree.addChild(v1, Vec3(0, 2, 0));
    tree.addChild(w, Vec3(1, 3, 0));  // bends at w: kept
    const BranchTree reduced = reduceCurves(tree, 0.9);
    ASSERT_EQ(reduced.size(), 4u);
    // The chain's end takes v1's place as the root's first child, so Z stays 0 (an id-order
    // rebuild would have made w the first child).
    const std::vector<NodeId> children = reduced.children(0);
    ASSERT_EQ(children.size(), 2u);
    expectNear(reduced.node(children[0]).position, Vec3(0, 2, 0));
    EXPECT_EQ(reduced.node(children[0]).branchDepth, 0u);
    expectNear(reduced.node(children[1]).position, Vec3(1, 1, 0));
    EXPECT_EQ(reduced.node(children[1]).branchDepth, 1u);
}

TEST(CurveReduction, EveryChainNodeIsRemovedExactlyWhenTheDotProductExceedsTheMaximum) {
    ColonizeParams p;
    p.influenceRadius = 30;
    p.killRadius = 8;
    p.step = 4;
    const BranchTree tree = colonize(p, randomPoints(500, -50, 50, 22)).trees[0];
    const double maxDot = 0.97;
    const BranchTree reduced = reduceCurves(tree, maxDot);
    EXPECT_LT(reduced.size(), tree.size());
    // Which original nodes were kept (positions are unique: nodes are never that close).
    std::map<std::array<double, 3>, NodeId> keptAt;
    for (const BranchNode& n : reduced.nodes()) {
        keptAt[{n.position.x(), n.position.y(), n.position.z()}] = 0;
    }
    auto kept = [&](NodeId id) {
        const Vec3& q = tree.node(id).position;
        return keptAt.count({q.x(), q.y(), q.z()}) > 0;
    };
    int removed = 0, checked = 0;
    for (NodeId v = 1; v < static_cast<NodeId>(tree.size()); ++v) {
        const BranchNode& n = tree.node(v);
        if (n.childCount != 1) {
            EXPECT_TRUE(kept(v));  // forks and tips always stay
            continue;
        }
        NodeId keptParent = n.parent;  // the nearest kept ancestor: v's parent in the result
        while (!kept(keptParent)) keptParent = tree.node(keptParent).parent;
        const Vec3 r1 = (n.position - tree.node(keptParent).position).normalized();
        const Vec3 r2 = (tree.node(n.firstChild).position - n.position).normalized();
        EXPECT_EQ(kept(v), r1.dot(r2) <= maxDot) << v;
        removed += !kept(v);
        ++checked;
    }
    EXPECT_GT(removed, 20);
    EXPECT_EQ(reduced.size() + static_cast<std::size_t>(removed), tree.size());
    EXPECT_GT(checked, removed);
}

TEST(CurveReduction, EmptyTreeStaysEmpty) { EXPECT_TRUE(reduceCurves(BranchTree{}, 0.5).empty()); }

}  // namespace
}  // namespace ramus::testing
