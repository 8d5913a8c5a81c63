// Mirroring (seed 000 §7.3): twins are reflections across the xy-plane in right-handed frames.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "limb_test_skeleton.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

using test::makeTestSkeleton;
using test::TestLimb;

const Mat4 kReflect = Vec4(1.0, 1.0, -1.0, 1.0).asDiagonal();

Skeleton posedSkeleton() {
    Skeleton skeleton = makeTestSkeleton(
        420.0, {{Attachment::Shoulder, LimbKind::Wing, {80.0, 90.0, 60.0}, 15.0, 35.0},
                {Attachment::Hip, LimbKind::Leg, {150.0, 130.0, 70.0}, -10.0, 40.0},
                {Attachment::Hip2, LimbKind::Leg, {140.0, 120.0, 60.0}, 0.0, 0.0, true}});
    poseLimbs(skeleton, SkeletonDesign{});
    return skeleton;
}

std::array<Vec3, 8> boxCorners(const Mat4& world, const Vec3& e) {
    std::array<Vec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        const Vec4 local((i & 1) ? e.x() : 0.0, ((i & 2) ? 0.5 : -0.5) * e.y(),
                         ((i & 4) ? 0.5 : -0.5) * e.z(), 1.0);
        corners[i] = (world * local).head<3>();
    }
    return corners;
}

TEST(Mirror, EveryLeftBoneGetsARightTwinLinkedBothWays) {
    Skeleton skeleton = posedSkeleton();
    const std::size_t before = skeleton.bones.size();
    int left = 0;
    for (const Bone& bone : skeleton.bones) left += bone.side == Side::Left ? 1 : 0;
    mirrorSkeleton(skeleton);
    ASSERT_EQ(skeleton.bones.size(), before + left);
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        const Bone& bone = skeleton.bones[i];
        EXPECT_LT(bone.parent, static_cast<int>(i));  // parents before children
        if (bone.side == Side::Center) {
            EXPECT_EQ(bone.twin, -1);
            continue;
        }
        ASSERT_GE(bone.twin, 0);
        const Bone& twin = skeleton.bones[bone.twin];
        EXPECT_EQ(twin.twin, static_cast<int>(i));
        EXPECT_NE(twin.side, bone.side);
        EXPECT_EQ(twin.kind, bone.kind);
        EXPECT_EQ(twin.limb, bone.limb);
        EXPECT_EQ(twin.attachment, bone.attachment);
        EXPECT_EQ(twin.index, bone.index);
        EXPECT_EQ(twin.doubleJoint, bone.doubleJoint);
        EXPECT_EQ(twin.hoof, bone.hoof);
        EXPECT_EQ(twin.extents, bone.extents);
        // a right bone's parent is the twin of the left bone's parent, or the same center bone
        const Bone& parent = skeleton.bones[bone.parent];
        if (parent.side == Side::Center)
            EXPECT_EQ(twin.parent, bone.parent);
        else
            EXPECT_EQ(twin.parent, parent.twin);
    }
}

TEST(Mirror, TwinWorldTransformIsTheReflectionInRightHandedFrames) {
    Skeleton skeleton = posedSkeleton();
    mirrorSkeleton(skeleton);
    const std::vector<Mat4> world = skeleton.worldTransforms();
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        EXPECT_NEAR((world[i].topLeftCorner<3, 3>().determinant()), 1.0, 1e-12);
        if (skeleton.bones[i].side != Side::Left) continue;
        const Mat4 expected = kReflect * world[i] * kReflect;
        const Mat4& twin = world[skeleton.bones[i].twin];
        EXPECT_LT((twin - expected).cwiseAbs().maxCoeff(), 1e-9) << skeleton.bones[i].name();
        // world x and y equal, z negated
        EXPECT_NEAR(twin(0, 3), world[i](0, 3), 1e-9);
        EXPECT_NEAR(twin(1, 3), world[i](1, 3), 1e-9);
        EXPECT_NEAR(twin(2, 3), -world[i](2, 3), 1e-9);
    }
}

TEST(Mirror, TwinBoxCornersAreMirrorImages) {
    Skeleton skeleton = posedSkeleton();
    mirrorSkeleton(skeleton);
    const std::vector<Mat4> world = skeleton.worldTransforms();
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        const Bone& bone = skeleton.bones[i];
        if (bone.side != Side::Left) continue;
        const auto left = boxCorners(world[i], bone.extents);
        const auto right = boxCorners(world[bone.twin], bone.extents);
        for (const Vec3& corner : left) {
            const Vec3 image(corner.x(), corner.y(), -corner.z());
            double nearest = 1e300;
            for (const Vec3& other : right) nearest = std::min(nearest, (other - image).norm());
            EXPECT_LT(nearest, 1e-9) << bone.name();
        }
    }
}

TEST(Mirror, JointAxesAreReflectedWithTheSameAnglesAndLimits) {
    Skeleton skeleton = posedSkeleton();
    mirrorSkeleton(skeleton);
    for (const Bone& bone : skeleton.bones) {
        if (bone.side != Side::Left) continue;
        const Joint& l = bone.joint;
        const Joint& r = skeleton.bones[bone.twin].joint;
        ASSERT_EQ(r.dofCount, l.dofCount);
        for (int d = 0; d < l.dofCount; ++d) {
            const Vec3 expected(-l.dofs[d].axis.x(), -l.dofs[d].axis.y(), l.dofs[d].axis.z());
            EXPECT_LT((r.dofs[d].axis - expected).norm(), 1e-15);
            EXPECT_EQ(r.dofs[d].angleDeg, l.dofs[d].angleDeg);
            EXPECT_EQ(r.dofs[d].minDeg, l.dofs[d].minDeg);
            EXPECT_EQ(r.dofs[d].maxDeg, l.dofs[d].maxDeg);
        }
        EXPECT_NEAR(r.rest.determinant(), 1.0, 1e-12);
    }
}

TEST(Mirror, ReflectionConjugatesARotationIntoTheReflectedAxis) {
    // S · R(a, θ) · S = R(−S·a, θ), the identity the joint mirroring relies on
    const Mat3 s = Vec3(1.0, 1.0, -1.0).asDiagonal();
    const Vec3 a = Vec3(0.3, -0.5, 0.8).normalized();
    const Mat3 r = Eigen::AngleAxisd(0.7, a).toRotationMatrix();
    const Mat3 expected = Eigen::AngleAxisd(0.7, -(s * a)).toRotationMatrix();
    EXPECT_LT((s * r * s - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(Mirror, MirroringAgainChangesNothing) {
    Skeleton once = posedSkeleton();
    mirrorSkeleton(once);
    Skeleton twice = once;
    mirrorSkeleton(twice);
    ASSERT_EQ(twice.bones.size(), once.bones.size());
    const std::vector<Mat4> a = once.worldTransforms(), b = twice.worldTransforms();
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i], b[i]);
        EXPECT_EQ(once.bones[i].twin, twice.bones[i].twin);
    }
}

TEST(Mirror, SameSkeletonMirrorsIdentically) {
    Skeleton a = posedSkeleton(), b = posedSkeleton();
    mirrorSkeleton(a);
    mirrorSkeleton(b);
    const std::vector<Mat4> wa = a.worldTransforms(), wb = b.worldTransforms();
    ASSERT_EQ(wa.size(), wb.size());
    for (std::size_t i = 0; i < wa.size(); ++i) EXPECT_EQ(wa[i], wb[i]);
}

TEST(Mirror, CenterOnlySkeletonIsUnchanged) {
    Skeleton skeleton = makeTestSkeleton(300.0, {});
    skeleton.bones.pop_back();  // drop the left rib
    const Skeleton before = skeleton;
    mirrorSkeleton(skeleton);
    EXPECT_EQ(skeleton.bones.size(), before.bones.size());
}

TEST(Mirror, RightLegsStandOnTheGroundLikeTheLeftOnes) {
    Skeleton skeleton = posedSkeleton();
    mirrorSkeleton(skeleton);
    const std::vector<Mat4> world = skeleton.worldTransforms();
    for (const Bone& bone : skeleton.bones) {
        if (bone.side != Side::Right || bone.kind != BoneKind::Foot) continue;
        const int i = static_cast<int>(&bone - skeleton.bones.data());
        EXPECT_NEAR(world[i](1, 3), world[bone.twin](1, 3), 1e-9);
    }
}

}  // namespace
}  // namespace ramus::detail
