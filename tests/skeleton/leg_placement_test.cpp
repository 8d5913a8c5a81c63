// The iterative leg placement (seed 000 §5.5.2, §7.5) on hand-made legs: feet on the ground,
// nothing below it, angles inside their limits, the fallbacks, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "limb_test_skeleton.hpp"
#include "ramus/rng.hpp"
#include "skeleton/limbs.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

using test::boneDirection;
using test::makeTestSkeleton;
using test::TestLimb;

double legLength(const Skeleton& skeleton, const LimbChain& chain) {
    double length = 0.0;
    for (int b : chain.bones) length += skeleton.bones[b].extents.x();
    return length;
}

/// Lowest corner of the foot box's end x = at.
double footFaceHeight(const Mat4& foot, const Vec3& extents, double at) {
    return foot(1, 3) + at * foot(1, 0) -
           0.5 * (std::abs(foot(1, 1)) * extents.y() + std::abs(foot(1, 2)) * extents.z());
}

/// Lowest corner of the heel region: the foot's proximal end and the middle bone's distal end.
double heelRegionHeight(const Skeleton& skeleton, const std::vector<Mat4>& world,
                        const LimbChain& chain) {
    const Bone& middle = skeleton.bones[chain.bones[1]];
    const Bone& foot = skeleton.bones[chain.bones[2]];
    return std::min(footFaceHeight(world[chain.bones[2]], foot.extents, 0.0),
                    footFaceHeight(world[chain.bones[1]], middle.extents, middle.extents.x()));
}

enum class Contact {
    Exact,    ///< the leg's contact point (toe tip, or heel region) is on the ground
    FootEnd,  ///< the foot box or the heel region is on the ground (§7.5 point 5 cases)
};

/// The invariants every posed skeleton with legs must satisfy.
void expectStanding(const Skeleton& skeleton, Contact mode = Contact::Exact) {
    const std::vector<Mat4> world = skeleton.worldTransforms();
    const double scale = 1000.0;
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        const Bone& bone = skeleton.bones[i];
        for (int d = 0; d < bone.joint.dofCount; ++d) {
            EXPECT_LE(bone.joint.dofs[d].minDeg, bone.joint.dofs[d].angleDeg) << bone.name();
            EXPECT_LE(bone.joint.dofs[d].angleDeg, bone.joint.dofs[d].maxDeg) << bone.name();
        }
        if (bone.limb == LimbKind::Leg && bone.kind != BoneKind::Scapula &&
            bone.kind != BoneKind::Pelvis)
            EXPECT_GE(lowestBoxPoint(world[i], bone.extents), skeleton.groundHeight - 1e-6 * scale)
                << bone.name();
    }
    for (const LimbChain& chain : findLimbChains(skeleton)) {
        if (chain.kind != LimbKind::Leg) continue;
        const Bone& foot = skeleton.bones[chain.bones[2]];
        const double length = legLength(skeleton, chain);
        const double upperMiddle = length - foot.extents.x();
        // a leg whose heel cannot reach the ground stands on its toes
        const bool heel = skeleton.heelContact &&
                          world[chain.bones[0]](1, 3) - upperMiddle <= skeleton.groundHeight;
        const double toe = footFaceHeight(world[chain.bones[2]], foot.extents, foot.extents.x());
        double contact = heel ? heelRegionHeight(skeleton, world, chain) : toe;
        if (mode == Contact::FootEnd) {
            contact = std::min({lowestBoxPoint(world[chain.bones[2]], foot.extents),
                                heelRegionHeight(skeleton, world, chain)});
        }
        EXPECT_NEAR(contact, skeleton.groundHeight, 0.01 * length) << foot.name();
    }
}

TEST(LegPlacement, FourLegsStandOnTheGround) {
    Skeleton skeleton = makeTestSkeleton(
        400.0, {{Attachment::Shoulder, LimbKind::Leg, {120.0, 110.0, 50.0}, 15.0, 40.0},
                {Attachment::Hip, LimbKind::Leg, {150.0, 140.0, 70.0}, -15.0, 40.0}});
    poseLimbs(skeleton, SkeletonDesign{});
    expectStanding(skeleton);
}

TEST(LegPlacement, RandomLegsStandOnTheGround) {
    Rng rng(20240605);
    for (int trial = 0; trial < 400; ++trial) {
        auto lengths = [&] {
            return std::array<double, 3>{rng.uniform(20.0, 250.0), rng.uniform(20.0, 250.0),
                                         rng.uniform(15.0, 120.0)};
        };
        std::vector<TestLimb> limbs = {{Attachment::Hip, LimbKind::Leg, lengths(),
                                        rng.uniform(-40.0, 40.0), rng.uniform(10.0, 80.0)}};
        if (rng.uniform01() < 0.7)
            limbs.push_back({Attachment::Shoulder, LimbKind::Leg, lengths(),
                             rng.uniform(-40.0, 40.0), rng.uniform(10.0, 80.0)});
        if (rng.uniform01() < 0.2)
            limbs.push_back({Attachment::Hip2, LimbKind::Leg, lengths(), 0.0, 0.0, true});
        Skeleton skeleton = makeTestSkeleton(rng.uniform(150.0, 700.0), limbs);
        SkeletonDesign design;
        design.heelDraw = rng.uniform01();
        poseLimbs(skeleton, design);
        SCOPED_TRACE(trial);
        expectStanding(skeleton);
        if (HasFailure()) break;
    }
}

TEST(LegPlacement, TinyFeetUnderThickBonesRestOnTheirFootEnd) {
    // A foot of a few px under a middle bone tens of px thick cannot always reach the ground
    // with its tip before the middle bone's box does (seed 000 §7.5 point 5): the leg then rests
    // on its heel region. Nothing dips below the ground either way.
    Rng rng(99);
    for (int trial = 0; trial < 200; ++trial) {
        auto lengths = [&] {
            return std::array<double, 3>{rng.uniform(20.0, 250.0), rng.uniform(150.0, 250.0),
                                         rng.uniform(3.0, 15.0)};
        };
        Skeleton skeleton = makeTestSkeleton(
            rng.uniform(150.0, 700.0),
            {{Attachment::Hip, LimbKind::Leg, lengths(), rng.uniform(-40.0, 40.0), 40.0},
             {Attachment::Shoulder, LimbKind::Leg, lengths(), rng.uniform(-40.0, 40.0), 40.0}});
        poseLimbs(skeleton, SkeletonDesign{});
        SCOPED_TRACE(trial);
        expectStanding(skeleton, Contact::FootEnd);
        if (HasFailure()) break;
    }
}

TEST(LegPlacement, VeryShortLegsStillReachTheGround) {
    // §7.5 points 2 and 3: legs of a few px total length
    for (double scale : {0.02, 0.05, 0.2}) {
        Skeleton skeleton = makeTestSkeleton(200.0, {{Attachment::Hip,
                                                      LimbKind::Leg,
                                                      {120.0 * scale, 110.0 * scale, 50.0 * scale},
                                                      5.0,
                                                      40.0}});
        poseLimbs(skeleton, SkeletonDesign{});
        SCOPED_TRACE(scale);
        expectStanding(skeleton);
    }
}

TEST(LegPlacement, HeelContactLaysTheFootFlat) {
    Skeleton skeleton = makeTestSkeleton(
        340.0, {{Attachment::Hip, LimbKind::Leg, {180.0, 170.0, 100.0}, 0.0, 40.0}});
    SkeletonDesign design;
    design.heelDraw = 0.0;
    poseLimbs(skeleton, design);
    ASSERT_TRUE(skeleton.heelContact);
    expectStanding(skeleton);
    const LimbChain chain = findLimbChains(skeleton).at(0);
    const Mat4 foot = skeleton.worldTransforms()[chain.bones[2]];
    EXPECT_LT(std::abs(boneDirection(foot).y()), std::sin(degToRad(10.0)));
    EXPECT_FALSE(skeleton.bones[chain.bones[2]].hoof);
}

TEST(LegPlacement, HoofMarksFeetSteeperThanFortyFiveDegrees) {
    Rng rng(7);
    int hooves = 0, flat = 0;
    for (int trial = 0; trial < 60; ++trial) {
        Skeleton skeleton = makeTestSkeleton(
            rng.uniform(200.0, 600.0),
            {{Attachment::Hip,
              LimbKind::Leg,
              {rng.uniform(50.0, 200.0), rng.uniform(50.0, 200.0), rng.uniform(10.0, 150.0)},
              0.0,
              40.0}});
        poseLimbs(skeleton, SkeletonDesign{});
        const LimbChain chain = findLimbChains(skeleton).at(0);
        const Vec3 d = boneDirection(skeleton.worldTransforms()[chain.bones[2]]);
        const bool steep = std::abs(d.y()) >= std::sin(degToRad(45.0));
        EXPECT_EQ(skeleton.bones[chain.bones[2]].hoof, steep);
        (steep ? hooves : flat) += 1;
    }
    EXPECT_GT(hooves + flat, 0);
}

LegPlacementResult placeOnly(Skeleton& skeleton, double ground, bool heel) {
    poseLimbs(skeleton, SkeletonDesign{});  // sets the joints up
    const LimbChain chain = findLimbChains(skeleton).at(0);
    const Mat4 girdle = skeleton.worldTransforms()[chain.girdle];
    return placeLeg(skeleton, chain, girdle, ground, heel);
}

TEST(LegPlacement, LegsTooShortToReachPointStraightDown) {
    Skeleton skeleton =
        makeTestSkeleton(400.0, {{Attachment::Hip, LimbKind::Leg, {60.0, 50.0, 20.0}, 10.0, 40.0}});
    const LegPlacementResult result = placeOnly(skeleton, 0.0, false);
    EXPECT_TRUE(result.straightDown);
    const std::vector<Mat4> world = skeleton.worldTransforms();
    const LimbChain chain = findLimbChains(skeleton).at(0);
    for (int b : chain.bones) EXPECT_NEAR(boneDirection(world[b]).y(), -1.0, 1e-9);
    // the stretched foot points down: its toe tip is 130 px below the hip, the ground at 0
    EXPECT_NEAR(result.contactGap, world[chain.bones[0]](1, 3) - 130.0, 1e-9);
}

TEST(LegPlacement, LegWithItsHipBelowTheGroundPointsStraightDownWithAFlatFoot) {
    Skeleton skeleton = makeTestSkeleton(
        400.0, {{Attachment::Hip, LimbKind::Leg, {150.0, 150.0, 60.0}, 0.0, 40.0}});
    const LegPlacementResult result = placeOnly(skeleton, 380.0, false);
    EXPECT_TRUE(result.straightDown);
    const std::vector<Mat4> world = skeleton.worldTransforms();
    const LimbChain chain = findLimbChains(skeleton).at(0);
    EXPECT_NEAR(boneDirection(world[chain.bones[0]]).y(), -1.0, 1e-9);
    EXPECT_NEAR(boneDirection(world[chain.bones[1]]).y(), -1.0, 1e-9);
    EXPECT_NEAR(boneDirection(world[chain.bones[2]]).x(), -1.0, 1e-9);
}

TEST(LegPlacement, LongShankThatStartsBelowTheGroundStartsFromTheGrid) {
    // folded, the shank hangs 400 px from a knee 100 px above the hip: below a ground 250 px
    // under the hip, so the folded start is invalid and the grid-searched start is used
    Skeleton skeleton = makeTestSkeleton(
        500.0, {{Attachment::Hip, LimbKind::Leg, {100.0, 400.0, 40.0}, 0.0, 40.0}});
    const LimbChain chain = findLimbChains(skeleton).at(0);
    const double hip = skeleton.worldTransforms()[chain.bones[0]](1, 3);
    const LegPlacementResult result = placeOnly(skeleton, hip - 250.0, false);
    skeleton.groundHeight = hip - 250.0;  // placeOnly's poseLimbs set its own
    skeleton.heelContact = false;
    EXPECT_FALSE(result.straightDown);
    EXPECT_TRUE(result.rescued);
    expectStanding(skeleton);
}

TEST(LegPlacement, HeelThatCannotReachTheGroundStandsOnTheToes) {
    // thigh + shank = 200 px under a hip about 300 px high: only the toe tip reaches y = 0
    Skeleton skeleton = makeTestSkeleton(
        340.0, {{Attachment::Hip, LimbKind::Leg, {100.0, 100.0, 180.0}, 0.0, 40.0}});
    const LegPlacementResult result = placeOnly(skeleton, 0.0, true);
    EXPECT_FALSE(result.heelContact);
    EXPECT_NEAR(result.contactGap, 0.0, 0.01 * 380.0);
}

TEST(LegPlacement, ZeroLengthLegsGiveFiniteAnglesWithinLimits) {
    Skeleton skeleton = makeTestSkeleton(
        300.0, {{Attachment::Hip, LimbKind::Leg, {0.0, 0.0, 0.0}, 0.0, 40.0},
                {Attachment::Shoulder, LimbKind::Leg, {100.0, 90.0, 40.0}, 0.0, 40.0}});
    poseLimbs(skeleton, SkeletonDesign{});
    EXPECT_TRUE(std::isfinite(skeleton.groundHeight));
    for (const Mat4& world : skeleton.worldTransforms()) EXPECT_TRUE(world.allFinite());
    for (const Bone& bone : skeleton.bones) {
        for (int d = 0; d < bone.joint.dofCount; ++d) {
            EXPECT_LE(bone.joint.dofs[d].minDeg, bone.joint.dofs[d].angleDeg);
            EXPECT_LE(bone.joint.dofs[d].angleDeg, bone.joint.dofs[d].maxDeg);
        }
    }
}

TEST(LegPlacement, IsDeterministic) {
    const std::vector<TestLimb> limbs = {
        {Attachment::Hip, LimbKind::Leg, {170.0, 90.0, 60.0}, 12.0, 40.0}};
    Skeleton a = makeTestSkeleton(380.0, limbs), b = makeTestSkeleton(380.0, limbs);
    const LegPlacementResult ra = placeOnly(a, 120.0, false), rb = placeOnly(b, 120.0, false);
    EXPECT_EQ(ra.iterations, rb.iterations);
    for (std::size_t i = 0; i < a.bones.size(); ++i)
        for (int d = 0; d < a.bones[i].joint.dofCount; ++d)
            EXPECT_EQ(a.bones[i].joint.dofs[d].angleDeg, b.bones[i].joint.dofs[d].angleDeg);
}

}  // namespace
}  // namespace ramus::detail
