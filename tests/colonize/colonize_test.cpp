// Behaviour of space colonization: the rules of SPEC §C, the extensions of seed 002 §3.5 and
// the known failures (§5.2.3), checked on hand-made and random inputs.
#include "ramus/colonize.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "colonize/growth_rules.hpp"
#include "colonize_test_util.hpp"
#include "ramus/error.hpp"

namespace ramus::testing {
namespace {

using colonize_detail::squaredDistance;
using colonize_detail::stepLength;

ColonizeParams smallParams() {
    ColonizeParams p;
    p.influenceRadius = 30;
    p.killRadius = 8;
    p.step = 4;
    p.maxIterations = 500;
    return p;
}

// Number of points that no node is within the kill radius of (exactly what must remain).
std::size_t pointsOutsideKillRadius(const ColonizeResult& r, const std::vector<Vec3>& points,
                                    double killRadius) {
    const std::vector<Vec3> nodes = allNodePositions(r);
    std::size_t count = 0;
    for (const Vec3& p : points) {
        const Vec3f pf = p.cast<float>();
        bool near = false;
        for (const Vec3& n : nodes) near = near || squaredDistance(pf, n) < killRadius * killRadius;
        if (!near) ++count;
    }
    return count;
}

TEST(Colonize, EveryPointWithinTheKillRadiusIsRemovedInTheSameIteration) {
    const std::vector<Vec3> points = randomPoints(400, -50, 50, 5);
    const ColonizeParams base = smallParams();
    const int total = colonize(base, points).iterations;
    ASSERT_GT(total, 10);
    for (int limit = 0; limit <= total; limit += 3) {
        ColonizeParams p = base;
        p.maxIterations = limit;
        const ColonizeResult r = colonize(p, points);
        EXPECT_EQ(r.attractorsLeft, pointsOutsideKillRadius(r, points, p.killRadius))
            << "after iteration " << limit;
    }
}

// Points spread over an extent of 1e14 against an influence radius of a few units: the
// acceleration grid grows its cells until they fit instead of overflowing its cell counts (a
// fuzzed config found this), and growth still reaches the near points.
TEST(Colonize, HugeExtentAgainstTheInfluenceRadiusStillGrows) {
    std::vector<Vec3> points = {Vec3(0, 10, 0), Vec3(0, 20, 0), Vec3(0, 1e14, 0),
                                Vec3(1e14, -1e14, 3e13)};
    const ColonizeResult r = colonize(smallParams(), points);
    ASSERT_EQ(r.trees.size(), 1u);
    EXPECT_GT(r.trees[0].nodes().size(), 2u);
    EXPECT_EQ(r.attractorsLeft, 2u);  // the far ones
}

// A point beyond the float range the attractors are kept in (a finite double, 1e39, as an
// ellipsoid with radii of 3.6e95 gives): an error naming the point, not a grid whose cell search
// never ends (a fuzzed config hung there, session 36).
TEST(Colonize, PointsBeyondTheFloatRangeAreAnError) {
    const std::vector<Vec3> points = {Vec3(0, 10, 0), Vec3(0, 1e39, 0)};
    try {
        (void)colonize(smallParams(), points);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "attraction point 1 (0, 1e+39, 0) is beyond the float range"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Colonize, StopsWhenNoAttractorsRemain) {
    const std::vector<Vec3> points = {Vec3(0, 10, 0), Vec3(0, 20, 0)};
    ColonizeParams p = smallParams();
    const ColonizeResult r = colonize(p, points);
    EXPECT_EQ(r.attractorsLeft, 0u);
    EXPECT_LT(r.iterations, 10);
    // A straight line up: 0, 4, 8 (kills 10? no: |10-8| = 2 < 8 yes) …
    for (const BranchNode& n : r.trees[0].nodes()) {
        EXPECT_DOUBLE_EQ(n.position.x(), 0.0);
        EXPECT_DOUBLE_EQ(n.position.z(), 0.0);
    }
}

TEST(Colonize, EveryEdgeHasTheStepLength) {
    ColonizeParams p = smallParams();
    p.tropism = Vec3(0, 0.4, 0);
    const ColonizeResult r = colonize(p, randomPoints(500, -60, 60, 2));
    ASSERT_GT(r.nodeCount(), 50u);
    for (const BranchNode& n : r.trees[0].nodes()) {
        if (n.parent == kNoNode) continue;
        const double length = (n.position - r.trees[0].node(n.parent).position).norm();
        EXPECT_NEAR(length, p.step, 1e-9);
    }
}

TEST(Colonize, WeightedGrowthStepsFallFromTwiceTheStepToTheStep) {
    ColonizeParams p = smallParams();
    p.weightedGrowth = true;
    p.maxBranchDepth = 4;
    const ColonizeResult r = colonize(p, randomPoints(600, -60, 60, 3));
    const BranchTree& tree = r.trees[0];
    bool sawLong = false, sawShort = false;
    for (const BranchNode& n : tree.nodes()) {
        if (n.parent == kNoNode) continue;
        const BranchNode& parent = tree.node(n.parent);
        const double expected = p.step * (2.0 - std::min(parent.branchDepth, 4u) / 4.0);
        EXPECT_NEAR((n.position - parent.position).norm(), expected, 1e-9);
        EXPECT_DOUBLE_EQ(stepLength(p, parent.branchDepth), expected);
        sawLong = sawLong || parent.branchDepth == 0;
        sawShort = sawShort || parent.branchDepth == 4;
    }
    EXPECT_TRUE(sawLong);
    EXPECT_TRUE(sawShort);
}

TEST(Colonize, NoTwoNodesAreCloserThanTheMinimumSpacing) {
    ColonizeParams p = smallParams();
    p.roots = {Vec3(0, 0, 0), Vec3(5, 0, 0)};
    const ColonizeResult r = colonize(p, randomPoints(500, -50, 50, 8));
    const std::vector<Vec3> nodes = allNodePositions(r);
    const double minDistance = kMinNodeSpacing * p.step;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        for (std::size_t j = i + 1; j < nodes.size(); ++j) {
            ASSERT_GE((nodes[i] - nodes[j]).norm(), minDistance) << i << " " << j;
        }
    }
}

TEST(Colonize, TwoEquidistantPointsDoNotMakeTheNodeOscillate) {
    // Seed 002 §5.2.3: the node between them would add the same child again and again.
    ColonizeParams p = smallParams();
    p.maxIterations = 100000;
    const std::vector<Vec3> points = {Vec3(-10, 1, 0), Vec3(10, 1, 0)};
    const ColonizeResult r = colonize(p, points);
    // One child straight up (the sum of the two unit vectors), then nothing changes: stop.
    ASSERT_EQ(r.trees[0].size(), 2u);
    EXPECT_NEAR(r.trees[0].node(1).position.y(), p.step, 1e-12);
    EXPECT_EQ(r.attractorsLeft, 2u);
    EXPECT_LE(r.iterations, 2);
}

TEST(Colonize, OppositePointsGiveAZeroDirectionAndNoNaN) {
    ColonizeParams p = smallParams();
    const std::vector<Vec3> points = {Vec3(-10, 0, 0), Vec3(10, 0, 0)};
    const ColonizeResult r = colonize(p, points);
    EXPECT_EQ(r.trees[0].size(), 1u);  // the unit vectors cancel exactly: no growth
    EXPECT_EQ(r.attractorsLeft, 2u);
    EXPECT_LE(r.iterations, 1);
}

TEST(Colonize, TropismCancellingTheAttractionStopsGrowthWithoutNaN) {
    ColonizeParams p = smallParams();
    p.tropism = Vec3(0, -1, 0);
    const ColonizeResult r = colonize(p, std::vector<Vec3>{Vec3(0, 20, 0)});
    for (const BranchNode& n : r.trees[0].nodes()) EXPECT_TRUE(n.position.allFinite());
    EXPECT_EQ(r.trees[0].size(), 1u);
}

TEST(Colonize, PointsOnALineAreAllReachedAndGrowthEnds) {
    std::vector<Vec3> points;
    for (int i = 1; i <= 50; ++i) points.emplace_back(0.0, 3.0 * i, 0.0);
    ColonizeParams p = smallParams();
    p.maxIterations = 100000;
    const ColonizeResult r = colonize(p, points);
    EXPECT_EQ(r.attractorsLeft, 0u);
    EXPECT_LT(r.iterations, 60);
}

TEST(Colonize, PointsCoincidingWithTheRootAreRemovedAtOnce) {
    const std::vector<Vec3> points(20, Vec3(1, 2, 3));
    ColonizeParams p = smallParams();
    p.roots = {Vec3(1, 2, 3)};
    const ColonizeResult r = colonize(p, points);
    EXPECT_EQ(r.attractorsLeft, 0u);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.trees[0].size(), 1u);
}

TEST(Colonize, NoPointsGiveJustTheRootsAndAWarning) {
    ColonizeParams p = smallParams();
    p.roots = {Vec3::Zero(), Vec3(10, 0, 0)};
    const ColonizeResult r = colonize(p, std::vector<Vec3>{});
    ASSERT_EQ(r.trees.size(), 2u);
    EXPECT_EQ(r.trees[0].size(), 1u);
    EXPECT_EQ(r.trees[1].size(), 1u);
    EXPECT_EQ(r.iterations, 0);
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_NE(r.warnings.back().find("no attraction points"), std::string::npos);
}

TEST(Colonize, EmptyEnvelopeGivesNoPoints) {
    Envelope e;
    e.pointCount = 0;
    EXPECT_TRUE(sampleEnvelope(e).empty());
}

TEST(Colonize, KillRadiusBelowTwiceTheStepWarns) {
    ColonizeParams p = smallParams();
    p.killRadius = 7.9;  // < 2 · 4
    const ColonizeResult r = colonize(p, randomPoints(10, -5, 5, 1));
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_NE(r.warnings.front().find("below 2 x step"), std::string::npos);
    p.killRadius = 8.0;
    EXPECT_TRUE(colonize(p, randomPoints(10, -5, 5, 1)).warnings.empty());
}

TEST(Colonize, AFarRootGrowsAStraightTrunkTowardsTheNearestPoint) {
    ColonizeParams p = smallParams();
    p.roots = {Vec3(0, -200, 0)};
    const std::vector<Vec3> points = randomPoints(200, -20, 20, 4);
    const ColonizeResult r = colonize(p, points);
    const BranchTree& tree = r.trees[0];
    // The nearest point decides the direction; the trunk is a chain of equal steps along it.
    Vec3 nearest = points[0];
    for (const Vec3& q : points) {
        if ((q.cast<float>().cast<double>() - p.roots[0]).norm() <
            (nearest.cast<float>().cast<double>() - p.roots[0]).norm()) {
            nearest = q;
        }
    }
    const Vec3 axis = (nearest.cast<float>().cast<double>() - p.roots[0]).normalized();
    auto outOfReach = [&](const Vec3& node) {
        for (const Vec3& q : points) {
            if (squaredDistance(Vec3f(q.cast<float>()), node) <
                p.influenceRadius * p.influenceRadius) {
                return false;
            }
        }
        return true;
    };
    int trunkNodes = 0;
    for (NodeId id = 1; outOfReach(tree.node(id - 1).position); ++id) {
        const Vec3 offset = tree.node(id).position - p.roots[0];
        EXPECT_NEAR(offset.cross(axis).norm(), 0.0, 1e-6 * offset.norm()) << id;
        EXPECT_NEAR((offset - tree.node(id - 1).position + p.roots[0]).norm(), p.step, 1e-9);
        EXPECT_EQ(tree.node(id).parent, id - 1);
        ++trunkNodes;
    }
    EXPECT_GE(trunkNodes, 35);
    EXPECT_LT(r.attractorsLeft, points.size() / 2);
}

TEST(Colonize, MaxDegreeIsRespected) {
    ColonizeParams p = smallParams();
    const std::vector<Vec3> points = randomPoints(800, -60, 60, 9);
    std::uint32_t unlimitedMax = 0;
    const ColonizeResult unlimited = colonize(p, points);
    for (const BranchNode& n : unlimited.trees[0].nodes()) {
        unlimitedMax = std::max(unlimitedMax, n.childCount);
    }
    EXPECT_GT(unlimitedMax, 2u);
    p.maxDegree = 2;
    const ColonizeResult limited = colonize(p, points);
    for (const BranchNode& n : limited.trees[0].nodes()) EXPECT_LE(n.childCount, 2u);
}

TEST(Colonize, MaxBranchDepthIsRespected) {
    ColonizeParams p = smallParams();
    const std::vector<Vec3> points = randomPoints(800, -60, 60, 10);
    std::uint32_t deepest = 0;
    const ColonizeResult unlimited = colonize(p, points);
    for (const BranchNode& n : unlimited.trees[0].nodes()) {
        deepest = std::max(deepest, n.branchDepth);
    }
    EXPECT_GT(deepest, 3u);
    p.maxBranchDepth = 3;
    const ColonizeResult limited = colonize(p, points);
    for (const BranchNode& n : limited.trees[0].nodes()) EXPECT_LE(n.branchDepth, 3u);
}

TEST(Colonize, NoGrowthCounterRetiresIdleNodes) {
    // Two points pull the lower root from opposite sides: it cannot grow. The upper root grows
    // up to a third point. With max_NG = 1 the lower root retires after one idle iteration and
    // its two points go to the nearest node still considered: the upper root, which then grows
    // down towards them.
    ColonizeParams p = smallParams();
    p.roots = {Vec3(0, 0, 0), Vec3(0, 25, 0)};
    const std::vector<Vec3> points = {Vec3(-10, 0, 0), Vec3(10, 0, 0), Vec3(0, 50, 0)};
    auto lowestOfUpperTree = [](const ColonizeResult& r) {
        double y = 1e9;
        for (const BranchNode& n : r.trees[1].nodes()) y = std::min(y, n.position.y());
        return y;
    };
    const ColonizeResult plain = colonize(p, points);
    EXPECT_EQ(plain.trees[0].size(), 1u);
    EXPECT_EQ(lowestOfUpperTree(plain), 25.0);
    EXPECT_EQ(plain.attractorsLeft, 2u);
    p.maxNoGrowth = 1;
    const ColonizeResult retired = colonize(p, points);
    EXPECT_EQ(retired.trees[0].size(), 1u);
    EXPECT_LT(lowestOfUpperTree(retired), 25.0);
}

TEST(Colonize, SeveralRootsCompeteForThePoints) {
    ColonizeParams p = smallParams();
    p.roots = {Vec3(-40, -60, 0), Vec3(40, -60, 0)};
    const std::vector<Vec3> points = randomPoints(600, -50, 50, 12);
    const ColonizeResult r = colonize(p, points);
    ASSERT_EQ(r.trees.size(), 2u);
    EXPECT_GT(r.trees[0].size(), 30u);
    EXPECT_GT(r.trees[1].size(), 30u);
    // Each tree keeps to its side, mostly: the mean x of its nodes has the root's sign.
    double meanLeft = 0, meanRight = 0;
    for (const BranchNode& n : r.trees[0].nodes()) meanLeft += n.position.x();
    for (const BranchNode& n : r.trees[1].nodes()) meanRight += n.position.x();
    EXPECT_LT(meanLeft, 0.0);
    EXPECT_GT(meanRight, 0.0);
}

TEST(Colonize, ObstaclesRemovePointsAndBlockGrowth) {
    Shape wall;
    wall.kind = ShapeKind::Box;
    wall.offset = Vec3(0, 30, 0);
    wall.size = Vec3(200, 4, 200);  // a floor the tree cannot pass
    ColonizeParams p = smallParams();
    const std::vector<Vec3> points = randomPoints(500, -60, 60, 13);
    const std::vector<Shape> obstacles = {wall};
    const ColonizeResult r = colonize(p, points, obstacles);
    EXPECT_LT(r.attractors, points.size());  // the points inside the wall are dropped
    for (const BranchNode& n : r.trees[0].nodes()) {
        EXPECT_LT(n.position.y(), 28.0);
        EXPECT_FALSE(shapeContains(wall, n.position));
    }
}

TEST(Colonize, SameInputsGiveIdenticalTrees) {
    ColonizeParams p = smallParams();
    p.tropism = Vec3(0.2, 0.1, 0);
    p.maxNoGrowth = 3;
    const std::vector<Vec3> points = randomPoints(700, -60, 60, 14);
    expectSameResult(colonize(p, points), colonize(p, points));
}

TEST(Colonize, MurrayRadiiNeverGrowFromRootToTips) {
    const ColonizeResult r = colonize(smallParams(), randomPoints(600, -60, 60, 15));
    const BranchTree& tree = r.trees[0];
    const std::vector<double> radii = computeMurrayRadii(tree, 0.3, 2.0);
    for (const BranchNode& n : tree.nodes()) {
        if (n.parent == kNoNode) continue;
        const auto id = static_cast<std::size_t>(&n - tree.nodes().data());
        EXPECT_LE(radii[id], radii[static_cast<std::size_t>(n.parent)] + 1e-12);
    }
}

TEST(Colonize, InvalidParamsAreRejectedWithTheirName) {
    const std::vector<Vec3> none;
    auto message = [&](ColonizeParams p) {
        try {
            colonize(p, none);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    ColonizeParams p = smallParams();
    p.influenceRadius = -1;
    EXPECT_NE(message(p).find("influenceRadius"), std::string::npos);
    p = smallParams();
    p.killRadius = 40;  // above d_i
    EXPECT_NE(message(p).find("killRadius"), std::string::npos);
    p = smallParams();
    p.step = 0;
    EXPECT_NE(message(p).find("step"), std::string::npos);
    p = smallParams();
    p.weightedGrowth = true;
    EXPECT_NE(message(p).find("maxBranchDepth"), std::string::npos);
    p = smallParams();
    p.roots.clear();
    EXPECT_NE(message(p).find("roots"), std::string::npos);
}

TEST(Colonize, NonFinitePointsAreRejected) {
    const std::vector<Vec3> points = {Vec3(0, 1, 0), Vec3(0, NAN, 0)};
    EXPECT_THROW(colonize(smallParams(), points), Error);
}

}  // namespace
}  // namespace ramus::testing

namespace ramus::testing {
namespace {

TEST(ColonizeLimits, GrowthBeyondTheNodeLimitIsAnError) {
    const std::vector<Vec3> points = randomPoints(400, -50, 50, 5);
    ColonizeParams p = smallParams();
    const std::size_t nodes = colonize(p, points).nodeCount();
    ASSERT_GT(nodes, 20u);
    p.maxNodes = nodes;  // exactly enough: fine
    EXPECT_EQ(colonize(p, points).nodeCount(), nodes);
    p.maxNodes = nodes - 1;
    try {
        colonize(p, points);
        FAIL() << "expected the node limit to stop growth";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("node limit of " + std::to_string(nodes - 1)),
                  std::string::npos)
            << e.what();
    }
}

TEST(ColonizeLimits, AZeroNodeLimitIsInvalid) {
    ColonizeParams p = smallParams();
    p.maxNodes = 0;
    EXPECT_THROW(validateColonizeParams(p), Error);
}

}  // namespace
}  // namespace ramus::testing
