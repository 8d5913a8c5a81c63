// Hand-made skeletons for the limb, leg and mirror tests: a root, a short curved spine and
// girdles with three-bone limbs, built the way placeBones leaves them (girdles at z > 0 turned
// only about z with x pointing roughly down, limb joints at the parent's distal end, rest =
// identity, no degrees of freedom yet).
#pragma once

#include <array>
#include <vector>

#include "ramus/skeleton.hpp"

namespace ramus::test {

/// One limb of a test skeleton.
struct TestLimb {
    Attachment attachment = Attachment::Hip;
    LimbKind kind = LimbKind::Leg;
    std::array<double, 3> lengths{120.0, 110.0, 60.0};  ///< upper, middle, hand/foot (px)
    double girdleTiltDeg = 0.0;       ///< girdle's side-view angle φ (0 = straight down)
    double girdleLength = 40.0;       ///< px
    bool secondOnSameGirdle = false;  ///< hang on the previous limb's girdle (pelvis2)
};

inline Mat3 rotationZ(double degrees) {
    return Eigen::AngleAxisd(degToRad(degrees), Vec3::UnitZ()).toRotationMatrix();
}

inline Bone makeBone(BoneKind kind, Side side, int parent, const Vec3& position, const Mat3& rest,
                     const Vec3& extents) {
    Bone bone;
    bone.kind = kind;
    bone.side = side;
    bone.parent = parent;
    bone.joint.position = position;
    bone.joint.rest = rest;
    bone.extents = extents;
    return bone;
}

/// A root at (0, spineHeight, 0), four front vertebrae towards −x (the shoulder vertebra is the
/// last) and four rear vertebrae towards +x (the hip vertebra is the last), each 50 px long and
/// turned 6° about z against the previous one; one rib on the first front vertebra; the limbs on
/// girdles at z = 20 px. Hip attachments hang on the hip vertebra, all others on the shoulder.
inline Skeleton makeTestSkeleton(double spineHeight, const std::vector<TestLimb>& limbs) {
    Skeleton skeleton;
    const Vec3 vertebra(50.0, 10.0, 10.0);
    skeleton.bones.push_back(makeBone(BoneKind::Root, Side::Center, -1, Vec3(0.0, spineHeight, 0.0),
                                      Mat3::Identity(), Vec3::Zero()));
    int shoulder = 0, hip = 0;
    for (int half = 0; half < 2; ++half) {
        int parent = 0;
        for (int i = 0; i < 4; ++i) {
            const Mat3 rest = i == 0 ? rotationZ(half == 0 ? 174.0 : -6.0) : rotationZ(6.0);
            const Vec3 at = i == 0 ? Vec3::Zero() : Vec3(vertebra.x(), 0.0, 0.0);
            Bone bone = makeBone(BoneKind::Vertebra, Side::Center, parent, at, rest, vertebra);
            bone.region = SpineRegion::Back;
            bone.index = half * 4 + i + 1;
            skeleton.bones.push_back(bone);
            parent = static_cast<int>(skeleton.bones.size()) - 1;
        }
        (half == 0 ? shoulder : hip) = parent;
    }
    Bone rib = makeBone(BoneKind::Rib, Side::Left, 1, Vec3(25.0, 0.0, 5.0), rotationZ(-80.0),
                        Vec3(60.0, 4.0, 4.0));
    rib.index = 1;
    skeleton.bones.push_back(rib);
    const std::vector<Mat4> spineWorld = skeleton.worldTransforms();
    int girdle = -1;
    for (const TestLimb& limb : limbs) {
        const bool front = isFrontAttachment(limb.attachment);
        if (!limb.secondOnSameGirdle) {
            const int vertebraIndex = front ? shoulder : hip;
            const Mat3 parentRotation = spineWorld[vertebraIndex].topLeftCorner<3, 3>();
            Bone g = makeBone(front ? BoneKind::Scapula : BoneKind::Pelvis, Side::Left,
                              vertebraIndex, Vec3(25.0, -5.0, 20.0),
                              parentRotation.transpose() * rotationZ(-90.0 + limb.girdleTiltDeg),
                              Vec3(limb.girdleLength, 12.0, 6.0));
            g.limb = limb.kind;
            g.attachment = limb.attachment;
            skeleton.bones.push_back(g);
            girdle = static_cast<int>(skeleton.bones.size()) - 1;
        } else {
            skeleton.bones[girdle].doubleJoint = true;
        }
        const std::array<BoneKind, 3> kinds =
            front ? std::array{BoneKind::UpperArm, BoneKind::Forearm, BoneKind::Hand}
                  : std::array{BoneKind::Thigh, BoneKind::Shank, BoneKind::Foot};
        int parent = girdle;
        for (int k = 0; k < 3; ++k) {
            const double parentLength = skeleton.bones[parent].extents.x();
            const double at = limb.secondOnSameGirdle && k == 0 ? 0.6 * parentLength : parentLength;
            const double l = limb.lengths[k];
            Bone bone = makeBone(kinds[k], Side::Left, parent, Vec3(at, 0.0, 0.0), Mat3::Identity(),
                                 Vec3(l, 0.15 * l, 0.12 * l));
            bone.limb = limb.kind;
            bone.attachment = limb.attachment;
            skeleton.bones.push_back(bone);
            parent = static_cast<int>(skeleton.bones.size()) - 1;
        }
    }
    return skeleton;
}

/// The unit x axis of a bone's world frame (its direction).
inline Vec3 boneDirection(const Mat4& world) { return world.block<3, 1>(0, 0); }

}  // namespace ramus::test
