// Limb poses (fins, arms, wings, legs), joint limits, and the ground height rule, checked on
// hand-made skeletons against hand-computed values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "limb_test_skeleton.hpp"
#include "skeleton/limbs.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

using test::boneDirection;
using test::makeTestSkeleton;
using test::TestLimb;

void expectDirection(const Mat4& world, const Vec3& expected) {
    const Vec3 d = boneDirection(world);
    EXPECT_NEAR(d.x(), expected.x(), 1e-9);
    EXPECT_NEAR(d.y(), expected.y(), 1e-9);
    EXPECT_NEAR(d.z(), expected.z(), 1e-9);
}

void expectAnglesWithinLimits(const Skeleton& skeleton) {
    for (const Bone& bone : skeleton.bones) {
        for (int i = 0; i < bone.joint.dofCount; ++i) {
            const JointDof& dof = bone.joint.dofs[i];
            EXPECT_LE(dof.minDeg, dof.angleDeg) << bone.name();
            EXPECT_LE(dof.angleDeg, dof.maxDeg) << bone.name();
        }
    }
}

LegReach leg(double jointHeight, double length, double footLength, bool front) {
    return LegReach{jointHeight, length, footLength, front};
}

// ---- ground height -----------------------------------------------------------------------------

TEST(GroundHeight, StaysAtZeroWhenEveryLegReachesItWithFourFifthsOfItsLength) {
    const std::vector<LegReach> legs = {leg(300.0, 500.0, 300.0, false)};
    const GroundHeight ground = computeGroundHeight(legs, 0.0);
    EXPECT_DOUBLE_EQ(ground.height, 0.0);
    EXPECT_FALSE(ground.raised);
    EXPECT_NEAR(ground.heelProbability, (500.0 - 300.0) / 300.0, 1e-15);
}

TEST(GroundHeight, IsRaisedToTheHighestReachPointWithZeroHeelProbability) {
    // reach points 400 − 0.8·300 = 160 and 350 − 0.8·500 = −50: the ground is at 160
    const std::vector<LegReach> legs = {leg(400.0, 300.0, 50.0, true),
                                        leg(350.0, 500.0, 80.0, false)};
    const GroundHeight ground = computeGroundHeight(legs, -1000.0);
    EXPECT_DOUBLE_EQ(ground.height, 160.0);
    EXPECT_TRUE(ground.raised);
    EXPECT_DOUBLE_EQ(ground.heelProbability, 0.0);
}

TEST(GroundHeight, HeelProbabilityIsOneWhenTheHeelAlreadyReachesZero) {
    // 600 − 300 = 300 ≥ foot 100
    const std::vector<LegReach> legs = {leg(300.0, 600.0, 100.0, false)};
    EXPECT_DOUBLE_EQ(computeGroundHeight(legs, 0.0).heelProbability, 1.0);
}

TEST(GroundHeight, AveragesTheFrontAndTheHindLegsSeparately) {
    // hind: (450 − 300)/100 → 1 and (400 − 300)/200 = 0.5, mean 0.75; front: (400 − 300)/500
    // = 0.2; result (0.75 + 0.2)/2 = 0.475
    const std::vector<LegReach> legs = {leg(300.0, 450.0, 100.0, false),
                                        leg(300.0, 400.0, 200.0, false),
                                        leg(300.0, 400.0, 500.0, true)};
    const GroundHeight ground = computeGroundHeight(legs, 0.0);
    EXPECT_FALSE(ground.raised);
    EXPECT_NEAR(ground.heelProbability, 0.475, 1e-15);
}

TEST(GroundHeight, ZeroFootLengthGivesCertainHeelContactWhenTheLegReachesZero) {
    const std::vector<LegReach> legs = {leg(100.0, 200.0, 0.0, false)};
    EXPECT_DOUBLE_EQ(computeGroundHeight(legs, 0.0).heelProbability, 1.0);
}

TEST(GroundHeight, WithoutLegsRestsOnTheLowestPoint) {
    const GroundHeight ground = computeGroundHeight({}, 37.5);
    EXPECT_DOUBLE_EQ(ground.height, 37.5);
    EXPECT_FALSE(ground.raised);
    EXPECT_DOUBLE_EQ(ground.heelProbability, 0.0);
}

TEST(GroundHeight, PoseLimbsMeasuresFromThePlacedHipJoints) {
    Skeleton skeleton = makeTestSkeleton(
        500.0, {{Attachment::Hip, LimbKind::Leg, {150.0, 140.0, 60.0}, 0.0, 40.0}});
    const std::vector<LimbChain> chains = findLimbChains(skeleton);
    ASSERT_EQ(chains.size(), 1u);
    const double hipHeight = skeleton.worldTransforms()[chains[0].bones[0]](1, 3);
    poseLimbs(skeleton, SkeletonDesign{});
    EXPECT_NEAR(skeleton.groundHeight, hipHeight - 0.8 * 350.0, 1e-9);
    EXPECT_DOUBLE_EQ(skeleton.heelProbability, 0.0);
    EXPECT_FALSE(skeleton.heelContact);
}

// ---- poses
// ---------------------------------------------------------------------------------------

TEST(LimbPose, FinsPointStraightBackAlongWorldX) {
    Skeleton skeleton = makeTestSkeleton(
        300.0, {{Attachment::Shoulder, LimbKind::Fin, {30.0, 20.0, 20.0}, 25.0, 30.0},
                {Attachment::Hip, LimbKind::Fin, {30.0, 20.0, 20.0}, -15.0, 30.0}});
    poseLimbs(skeleton, SkeletonDesign{});
    const std::vector<Mat4> world = skeleton.worldTransforms();
    for (const LimbChain& chain : findLimbChains(skeleton))
        for (int b : chain.bones) expectDirection(world[b], Vec3::UnitX());
    expectAnglesWithinLimits(skeleton);
}

TEST(LimbPose, ArmsHangDownWithTheForearmAndHandForward) {
    Skeleton skeleton = makeTestSkeleton(
        300.0, {{Attachment::Shoulder, LimbKind::Arm, {80.0, 70.0, 30.0}, 20.0, 30.0}});
    poseLimbs(skeleton, SkeletonDesign{});
    const std::vector<Mat4> world = skeleton.worldTransforms();
    const LimbChain chain = findLimbChains(skeleton).at(0);
    expectDirection(world[chain.bones[0]], -Vec3::UnitY());
    expectDirection(world[chain.bones[1]], -Vec3::UnitX());
    expectDirection(world[chain.bones[2]], -Vec3::UnitX());
    EXPECT_DOUBLE_EQ(skeleton.bones[chain.bones[1]].joint.dofs[0].angleDeg, -90.0);
    expectAnglesWithinLimits(skeleton);
}

TEST(LimbPose, WingsTakeTheDesignAnglesInsideTheWingIntervals) {
    Skeleton skeleton = makeTestSkeleton(
        300.0, {{Attachment::Shoulder, LimbKind::Wing, {80.0, 90.0, 60.0}, 10.0, 30.0}});
    SkeletonDesign design;
    design.wingAngles[static_cast<int>(Attachment::Shoulder)] = {140.0, 30.0, -10.0, 60.0};
    poseLimbs(skeleton, design);
    const LimbChain chain = findLimbChains(skeleton).at(0);
    const Joint& shoulder = skeleton.bones[chain.bones[0]].joint;
    ASSERT_EQ(shoulder.dofCount, 2);
    EXPECT_DOUBLE_EQ(shoulder.dofs[0].angleDeg, 140.0);
    EXPECT_DOUBLE_EQ(shoulder.dofs[0].minDeg, 130.0);
    EXPECT_DOUBLE_EQ(shoulder.dofs[0].maxDeg, 170.0);
    EXPECT_DOUBLE_EQ(shoulder.dofs[1].angleDeg, 30.0);
    EXPECT_DOUBLE_EQ(shoulder.dofs[1].maxDeg, 45.0);
    EXPECT_DOUBLE_EQ(skeleton.bones[chain.bones[1]].joint.dofs[0].angleDeg, -10.0);
    EXPECT_DOUBLE_EQ(skeleton.bones[chain.bones[2]].joint.dofs[0].angleDeg, 60.0);
    expectAnglesWithinLimits(skeleton);
    // spread 140° from the girdle's downward x: the wing rises away from the body (+z)
    const Vec3 d = boneDirection(skeleton.worldTransforms()[chain.bones[0]]);
    EXPECT_GT(d.y(), 0.5);
    EXPECT_GT(d.z(), 0.5);
}

TEST(LimbPose, WingAnglesOutsideTheIntervalsAreClamped) {
    Skeleton skeleton = makeTestSkeleton(
        300.0, {{Attachment::Shoulder, LimbKind::Wing, {80.0, 90.0, 60.0}, 0.0, 30.0}});
    SkeletonDesign design;
    design.wingAngles[static_cast<int>(Attachment::Shoulder)] = {200.0, -5.0, 10.0, 100.0};
    poseLimbs(skeleton, design);
    expectAnglesWithinLimits(skeleton);
    const LimbChain chain = findLimbChains(skeleton).at(0);
    EXPECT_DOUBLE_EQ(skeleton.bones[chain.bones[0]].joint.dofs[0].angleDeg, 170.0);
    EXPECT_DOUBLE_EQ(skeleton.bones[chain.bones[2]].joint.dofs[0].angleDeg, 90.0);
}

TEST(LimbPose, LegJointsFollowFigureFiveThree) {
    Skeleton skeleton = makeTestSkeleton(
        400.0, {{Attachment::Shoulder, LimbKind::Leg, {120.0, 110.0, 50.0}, 20.0, 40.0},
                {Attachment::Hip, LimbKind::Leg, {130.0, 120.0, 60.0}, -20.0, 40.0}});
    poseLimbs(skeleton, SkeletonDesign{});
    const std::vector<LimbChain> chains = findLimbChains(skeleton);
    ASSERT_EQ(chains.size(), 2u);
    // front: upper arm φ ∈ [0, 170] → joint [−20, 150]; elbow bends forwards
    const Joint& shoulder = skeleton.bones[chains[0].bones[0]].joint;
    EXPECT_DOUBLE_EQ(shoulder.dofs[0].minDeg, 0.0);
    EXPECT_DOUBLE_EQ(shoulder.dofs[0].maxDeg, 45.0);
    EXPECT_DOUBLE_EQ(shoulder.dofs[0].angleDeg, 0.0);
    EXPECT_NEAR(shoulder.dofs[1].minDeg, -20.0, 1e-9);
    EXPECT_NEAR(shoulder.dofs[1].maxDeg, 150.0, 1e-9);
    EXPECT_DOUBLE_EQ(skeleton.bones[chains[0].bones[1]].joint.dofs[0].minDeg, -170.0);
    EXPECT_DOUBLE_EQ(skeleton.bones[chains[0].bones[1]].joint.dofs[0].maxDeg, 0.0);
    // hind: thigh φ ∈ [−170, 0] → joint [−150, 20] after the girdle's −20°; knee bends back
    const Joint& hip = skeleton.bones[chains[1].bones[0]].joint;
    EXPECT_NEAR(hip.dofs[1].minDeg, -150.0, 1e-9);
    EXPECT_NEAR(hip.dofs[1].maxDeg, 20.0, 1e-9);
    EXPECT_DOUBLE_EQ(skeleton.bones[chains[1].bones[1]].joint.dofs[0].minDeg, 0.0);
    EXPECT_DOUBLE_EQ(skeleton.bones[chains[1].bones[1]].joint.dofs[0].maxDeg, 170.0);
    EXPECT_DOUBLE_EQ(skeleton.bones[chains[1].bones[2]].joint.dofs[0].minDeg, -170.0);
    expectAnglesWithinLimits(skeleton);
}

TEST(LimbPose, HeelContactIsDrawnAgainstTheHeelProbability) {
    // hip at about 300 px, leg 450 px, foot 100 px: ground stays at 0, probability ≈ 1
    const std::vector<TestLimb> limbs = {
        {Attachment::Hip, LimbKind::Leg, {180.0, 170.0, 100.0}, 0.0, 40.0}};
    Skeleton low = makeTestSkeleton(340.0, limbs);
    Skeleton high = low;
    SkeletonDesign design;
    design.heelDraw = 0.0;
    poseLimbs(low, design);
    EXPECT_DOUBLE_EQ(low.groundHeight, 0.0);
    EXPECT_GT(low.heelProbability, 0.0);
    EXPECT_TRUE(low.heelContact);
    design.heelDraw = 0.9999999;
    poseLimbs(high, design);
    EXPECT_EQ(high.heelContact, design.heelDraw < high.heelProbability);
}

TEST(LimbPose, WithoutLegsTheSkeletonRestsOnTheGround) {
    Skeleton skeleton = makeTestSkeleton(
        300.0, {{Attachment::Shoulder, LimbKind::Arm, {80.0, 70.0, 30.0}, 20.0, 30.0},
                {Attachment::Hip, LimbKind::Fin, {30.0, 20.0, 20.0}, 0.0, 30.0}});
    poseLimbs(skeleton, SkeletonDesign{});
    const std::vector<Mat4> world = skeleton.worldTransforms();
    EXPECT_DOUBLE_EQ(skeleton.groundHeight, lowestBonePoint(skeleton.bones, world));
    // the arm hangs lowest: the lowest corner of its forearm or hand is the ground
    const LimbChain arm = findLimbChains(skeleton).at(0);
    double armLowest = 1e300;
    for (int b : arm.bones)
        armLowest = std::min(armLowest, lowestBoxPoint(world[b], skeleton.bones[b].extents));
    EXPECT_NEAR(skeleton.groundHeight, armLowest, 1e-9);
    EXPECT_FALSE(skeleton.heelContact);
}

TEST(LimbPose, FindsBothThighsOfADoublePelvis) {
    Skeleton skeleton = makeTestSkeleton(
        400.0, {{Attachment::Hip, LimbKind::Leg, {120.0, 110.0, 50.0}, 0.0, 40.0},
                {Attachment::Hip2, LimbKind::Leg, {120.0, 110.0, 50.0}, 0.0, 40.0, true}});
    const std::vector<LimbChain> chains = findLimbChains(skeleton);
    ASSERT_EQ(chains.size(), 2u);
    EXPECT_EQ(chains[0].girdle, chains[1].girdle);
    EXPECT_EQ(chains[0].attachment, Attachment::Hip);
    EXPECT_EQ(chains[1].attachment, Attachment::Hip2);
    EXPECT_FALSE(chains[1].front);
}

TEST(LimbPose, SideViewAngleOfAFrame) {
    Mat4 world = Mat4::Identity();
    world.topLeftCorner<3, 3>() = test::rotationZ(-90.0 + 30.0);
    EXPECT_NEAR(sideViewAngle(world), 30.0, 1e-12);  // x pointing down, 30° towards +x
}

TEST(LimbPose, LowestBoxPointOfATurnedBox) {
    Mat4 world = Mat4::Identity();
    world.topLeftCorner<3, 3>() = test::rotationZ(-90.0);  // x down, y along +x world
    world(1, 3) = 100.0;
    EXPECT_NEAR(lowestBoxPoint(world, Vec3(40.0, 10.0, 6.0)), 60.0, 1e-12);
    world.topLeftCorner<3, 3>() = test::rotationZ(-45.0);
    const double expected = 100.0 - 40.0 * std::sqrt(0.5) - 5.0 * std::sqrt(0.5);
    EXPECT_NEAR(lowestBoxPoint(world, Vec3(40.0, 10.0, 6.0)), expected, 1e-12);
}

TEST(LimbPose, IsDeterministic) {
    const std::vector<TestLimb> limbs = {
        {Attachment::Shoulder, LimbKind::Leg, {120.0, 110.0, 50.0}, 10.0, 40.0},
        {Attachment::Hip, LimbKind::Leg, {150.0, 130.0, 70.0}, -10.0, 40.0}};
    Skeleton a = makeTestSkeleton(420.0, limbs);
    Skeleton b = makeTestSkeleton(420.0, limbs);
    poseLimbs(a, SkeletonDesign{});
    poseLimbs(b, SkeletonDesign{});
    const std::vector<Mat4> wa = a.worldTransforms(), wb = b.worldTransforms();
    for (std::size_t i = 0; i < wa.size(); ++i) EXPECT_EQ(wa[i], wb[i]);
    EXPECT_EQ(a.groundHeight, b.groundHeight);
}

}  // namespace
}  // namespace ramus::detail
