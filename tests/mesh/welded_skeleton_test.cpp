// The welded mesher's skeleton (src/mesh/welded_skeleton.hpp): the limb directions it keeps per
// point, and the bound on how far a ring reaches in front of another's plane that the junction
// solver passes rings over by (session 45).
#include "mesh/welded_skeleton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ramus/rng.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus {
namespace {

// A limb from the root along x, bent by a right angle to y at (1, 0, 0), ending at a tip.
TEST(WeldSkeleton, PointDirectionsAreTheLimbsBisectors) {
    BranchTree tree;
    NodeId node = tree.addRoot(Vec3(0, 0, 0));
    node = tree.addChild(node, Vec3(1, 0, 0));
    tree.addChild(node, Vec3(1, 2, 0));
    const detail::WeldSkeleton s = detail::buildWeldSkeleton(tree, TubeMeshParams{});
    ASSERT_EQ(s.limbs.size(), 1u);
    const detail::WeldLimb& limb = s.limbs[0];
    ASSERT_EQ(limb.count, 3u);
    ASSERT_EQ(s.pointDirections.size(), s.pointPosition.size());
    const double half = std::sqrt(0.5);
    const Vec3 expected[] = {Vec3(1, 0, 0), Vec3(half, half, 0), Vec3(0, 1, 0)};
    for (std::uint32_t k = 0; k < limb.count; ++k) {
        EXPECT_LT((detail::pointDirection(s, limb, k) - expected[k]).norm(), 1e-12) << k;
    }
}

// reachInFront is at most the centre's height plus the radius as computed in floating point
// (the sine is at most 1 and rounding is monotone), whatever the angle — also where the normals
// are nearly parallel or opposite and 1 − cos² rounds to 0 or below — and the same whether
// given the centre or its height.
TEST(WeldSkeleton, ReachInFrontIsAtMostTheHeightPlusTheRadius) {
    Rng rng(45);
    auto unit = [&] {
        const Vec3 v(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        return Vec3(v.normalized());
    };
    int nearlyParallel = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        detail::RingPlace ring;
        const double scale = std::pow(10.0, rng.uniform(-4.0, 3.0));
        ring.center =
            scale * Vec3(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        ring.normal = unit();
        const Vec3 center = ring.center + scale * unit();
        Vec3 normal = unit();
        if (trial % 4 == 0) {  // within rounding of ±the ring's normal
            normal = Vec3((trial % 8 == 0 ? 1.0 : -1.0) * ring.normal + 1e-9 * unit()).normalized();
            ++nearlyParallel;
        }
        const double radius = scale * rng.uniform(0.0, 1.0);
        const double height = detail::heightOver(ring, center);
        const double reach = detail::reachInFront(ring, height, normal, radius);
        EXPECT_LE(reach, height + radius) << trial;
        EXPECT_EQ(reach, detail::reachInFront(ring, center, normal, radius)) << trial;
    }
    EXPECT_EQ(nearlyParallel, 5000);
}

}  // namespace
}  // namespace ramus
