// Assembly of bone models into skeletons (src/bones/bone_fit.cpp): model choice per bone,
// fitting to the box, mirrored twins, the tail tip, whole skeletons at low and high resolution.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "bones/mesh_checks.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus {
namespace {

Skeleton skeletonFor(std::uint64_t seed, SkeletonInputs inputs = {}) {
    Rng rng = Rng::forStream(seed, 0);
    return buildSkeleton(designSkeleton(SkeletonStats::builtin(), inputs, rng));
}

/// A skeleton with a tail of at least three vertebrae.
Skeleton skeletonWithTail() {
    for (std::uint64_t seed = 1; seed < 200; ++seed) {
        Skeleton s = skeletonFor(seed);
        int tail = 0;
        for (const Bone& b : s.bones) tail += b.region == SpineRegion::Tail ? 1 : 0;
        if (tail >= 5) return s;
    }
    return {};
}

Bone boneOf(BoneKind kind, Side side, Vec3 extents) {
    Bone bone;
    bone.kind = kind;
    bone.side = side;
    bone.extents = extents;
    return bone;
}

TEST(BoneFit, FittedModelsSpanTheBoneLengthAndKeepTheirOrientation) {
    const BoneModel& model = BoneLibrary::builtin(BoneResolution::Low)
                                 .model(BoneModelKind::Vertebra, BoneResolution::Low);
    const Mesh mesh =
        fitBoneModel(model, boneOf(BoneKind::Vertebra, Side::Center, Vec3(20, 10, 8)));
    const Aabb box = mesh.bounds();
    EXPECT_NEAR(box.min.x(), 0.0, 0.05 * 20);
    EXPECT_NEAR(box.max.x(), 20.0, 0.05 * 20);
    EXPECT_TRUE(isClosedManifold(mesh));
    EXPECT_GT(signedVolume(mesh), 0.0);
}

TEST(BoneFit, RightTwinsAreMirroredAndStillFaceOutwards) {
    const BoneModel& model = BoneLibrary::builtin(BoneResolution::High)
                                 .model(BoneModelKind::Thigh, BoneResolution::High);
    const Mesh left = fitBoneModel(model, boneOf(BoneKind::Thigh, Side::Left, Vec3(50, 8, 8)));
    const Mesh right = fitBoneModel(model, boneOf(BoneKind::Thigh, Side::Right, Vec3(50, 8, 8)));
    ASSERT_EQ(left.positions.size(), right.positions.size());
    for (std::size_t i = 0; i < left.positions.size(); ++i) {
        EXPECT_FLOAT_EQ(right.positions[i].x(), left.positions[i].x());
        EXPECT_FLOAT_EQ(right.positions[i].z(), -left.positions[i].z());
        EXPECT_FLOAT_EQ(right.normals[i].z(), -left.normals[i].z());
    }
    EXPECT_TRUE(isClosedManifold(right));
    EXPECT_NEAR(signedVolume(right), signedVolume(left), 1e-3 * signedVolume(left));
    EXPECT_GT(signedVolume(right), 0.0);
}

TEST(BoneFit, WidthFromHeightScalesThicknessWithTheHeight) {
    BoneModel model = BoneLibrary::builtin(BoneResolution::Low)
                          .model(BoneModelKind::UpperArm, BoneResolution::Low);
    model.widthFromHeight = 2.0;
    const Mesh mesh = fitBoneModel(model, boneOf(BoneKind::UpperArm, Side::Left, Vec3(40, 5, 99)));
    const Aabb box = mesh.bounds();
    EXPECT_LT(box.max.z() - box.min.z(), 2.0 * 5.0 * 1.5);  // not the box width of 99
}

TEST(BoneFit, HandsAndFeetFollowTheLimbKindAndTheHoofRule) {
    Skeleton s;
    auto add = [&](BoneKind kind, LimbKind limb, bool hoof) {
        Bone b = boneOf(kind, Side::Left, Vec3(10, 4, 4));
        b.limb = limb;
        b.hoof = hoof;
        s.bones.push_back(b);
        return static_cast<int>(s.bones.size() - 1);
    };
    EXPECT_EQ(modelForBone(s, add(BoneKind::Foot, LimbKind::Leg, true), ""), BoneModelKind::Hoof);
    EXPECT_EQ(modelForBone(s, add(BoneKind::Foot, LimbKind::Leg, false), ""), BoneModelKind::Hand);
    EXPECT_EQ(modelForBone(s, add(BoneKind::Hand, LimbKind::Wing, false), ""),
              BoneModelKind::WingHand);
    EXPECT_EQ(modelForBone(s, add(BoneKind::Hand, LimbKind::Fin, false), ""), BoneModelKind::Fin);
    EXPECT_EQ(modelForBone(s, add(BoneKind::Hand, LimbKind::Arm, false), ""), BoneModelKind::Hand);
    const int skull = add(BoneKind::Skull, LimbKind::None, false);
    EXPECT_EQ(modelForBone(s, skull, ""), BoneModelKind::SkullHerbivore);
    EXPECT_EQ(modelForBone(s, skull, "bird"), BoneModelKind::SkullBird);
    EXPECT_EQ(modelForBone(s, skull, "reptile"), BoneModelKind::SkullReptile);
    EXPECT_THROW(modelForBone(s, skull, "unicorn"), Error);
    Bone pelvis = boneOf(BoneKind::Pelvis, Side::Left, Vec3(10, 4, 4));
    pelvis.doubleJoint = true;
    s.bones.push_back(pelvis);
    EXPECT_EQ(modelForBone(s, static_cast<int>(s.bones.size() - 1), ""),
              BoneModelKind::PelvisDouble);
    EXPECT_EQ(modelForBone(s, add(BoneKind::Root, LimbKind::None, false), ""), std::nullopt);
}

TEST(BoneFit, TheTailTipReplacesTheLastThreeTailVertebrae) {
    const Skeleton s = skeletonWithTail();
    ASSERT_FALSE(s.bones.empty());
    int count = 0;
    for (const Bone& b : s.bones) count += b.region == SpineRegion::Tail ? 1 : 0;
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        const Bone& b = s.bones[i];
        if (b.kind != BoneKind::Vertebra || b.region != SpineRegion::Tail) continue;
        const auto model = modelForBone(s, static_cast<int>(i), "");
        if (b.index < count - 2) {
            EXPECT_EQ(model, BoneModelKind::Vertebra) << b.name();
        } else if (b.index == count - 2) {
            EXPECT_EQ(model, BoneModelKind::TailTip) << b.name();
        } else {
            EXPECT_EQ(model, std::nullopt) << b.name();
        }
    }
    // The tip spans the three vertebrae: longer than the one bone it is fitted to.
    const Scene scene = skeletonSceneAt(s, BoneResolution::Low, "");
    EXPECT_FALSE(scene.meshes.empty());
}

TEST(BoneFit, WholeSkeletonsAtLowAndHighAreValidDeterministicAndWithinBudget) {
    SkeletonInputs inputs;
    inputs.legs = 4;
    inputs.wings = 2;
    const Skeleton s = skeletonFor(11, inputs);
    for (BoneResolution resolution : {BoneResolution::Low, BoneResolution::High}) {
        const Scene scene = skeletonSceneAt(s, resolution, "carnivore");
        // One mesh per bone with a model, in bone order, each within its model's budget.
        std::size_t budget = 0, triangles = 0, m = 0;
        for (std::size_t i = 0; i < s.bones.size(); ++i) {
            const auto kind = modelForBone(s, static_cast<int>(i), "carnivore");
            if (!kind) continue;
            const auto boneBudget = static_cast<std::size_t>(boneTriangleBudget(*kind, resolution));
            budget += boneBudget;
            ASSERT_LT(m, scene.meshes.size());
            EXPECT_EQ(scene.meshes[m].name, s.bones[i].name());
            EXPECT_LE(scene.meshes[m].triangleCount(), boneBudget) << s.bones[i].name();
            triangles += scene.meshes[m++].triangleCount();
        }
        EXPECT_EQ(m, scene.meshes.size());
        EXPECT_LE(triangles, budget);
        EXPECT_GT(triangles, budget / 4);
        const std::string glb = encodeGlb(scene);
        EXPECT_EQ(glb, encodeGlb(skeletonSceneAt(s, resolution, "carnivore")));
        if (const char* dir = std::getenv("RAMUS_TEST_OUTPUT"); dir && *dir) {
            writeFileAtomic(
                (std::filesystem::path(dir) /
                 ("bones_skeleton_" + std::string(boneResolutionName(resolution)) + ".glb"))
                    .string(),
                glb);
        }
    }
}

}  // namespace
}  // namespace ramus
