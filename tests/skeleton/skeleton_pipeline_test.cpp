// The whole skeleton pipeline (seed 000 ch. 5–6; issue 5's checks): inputs → design →
// bones, with the invariants every generated skeleton must keep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ramus/error.hpp"
#include "ramus/skeleton.hpp"

namespace ramus {
namespace {

const SkeletonStats& stats() {
    static const SkeletonStats model = SkeletonStats::builtin();
    return model;
}

Skeleton generate(const SkeletonInputs& inputs, std::uint64_t seed,
                  SkeletonDesign* designOut = nullptr) {
    Rng rng = Rng::forStream(seed, 0);
    const SkeletonDesign design = designSkeleton(stats(), inputs, rng);
    if (designOut) *designOut = design;
    return buildSkeleton(design);
}

int countBones(const Skeleton& s, BoneKind kind, LimbKind limb = LimbKind::None) {
    return static_cast<int>(std::count_if(s.bones.begin(), s.bones.end(), [&](const Bone& b) {
        return b.kind == kind && (limb == LimbKind::None || b.limb == limb);
    }));
}

/// The 8 corners of a bone's box in world coordinates.
std::array<Vec3, 8> boxCorners(const Bone& bone, const Mat4& world) {
    std::array<Vec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        const Vec3 local((i & 1) ? bone.extents.x() : 0.0,
                         ((i & 2) ? 0.5 : -0.5) * bone.extents.y(),
                         ((i & 4) ? 0.5 : -0.5) * bone.extents.z());
        corners[i] = (world * local.homogeneous()).head<3>();
    }
    return corners;
}

double lowestY(const Bone& bone, const Mat4& world) {
    double lowest = std::numeric_limits<double>::infinity();
    for (const Vec3& c : boxCorners(bone, world)) lowest = std::min(lowest, c.y());
    return lowest;
}

/// Checks every invariant of a generated skeleton; `what` names it in failures.
void expectValidSkeleton(const Skeleton& s, const std::string& what) {
    SCOPED_TRACE(what);
    ASSERT_FALSE(s.bones.empty());
    EXPECT_EQ(s.bones[0].parent, -1);
    EXPECT_EQ(s.bones[0].kind, BoneKind::Root);
    const std::vector<Mat4> world = s.worldTransforms();
    double scale = 0.0;
    for (const Bone& b : s.bones) scale = std::max(scale, b.extents.maxCoeff());
    const double tolerance = 1e-6 * std::max(1.0, scale);
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        const Bone& b = s.bones[i];
        if (i > 0) {
            ASSERT_GE(b.parent, 0);
            ASSERT_LT(b.parent, static_cast<int>(i));
        }
        EXPECT_TRUE(world[i].allFinite()) << b.name();
        EXPECT_TRUE(b.extents.allFinite()) << b.name();
        EXPECT_NEAR((world[i].topLeftCorner<3, 3>().determinant()), 1.0, 1e-9) << b.name();
        EXPECT_GE(lowestY(b, world[i]), s.groundHeight - tolerance) << b.name() << " below ground";
        for (int d = 0; d < b.joint.dofCount; ++d) {
            const JointDof& dof = b.joint.dofs[d];
            EXPECT_GE(dof.angleDeg, dof.minDeg - 1e-9) << b.name();
            EXPECT_LE(dof.angleDeg, dof.maxDeg + 1e-9) << b.name();
        }
        if (b.side == Side::Center) {
            EXPECT_EQ(b.twin, -1) << b.name();
            continue;
        }
        ASSERT_GE(b.twin, 0) << b.name();
        const Bone& twin = s.bones[b.twin];
        EXPECT_EQ(twin.twin, static_cast<int>(i));
        EXPECT_NE(twin.side, b.side);
        EXPECT_EQ(twin.kind, b.kind);
        const Mat4 reflect = Vec4(1, 1, -1, 1).asDiagonal();
        EXPECT_TRUE((reflect * world[i] * reflect).isApprox(world[b.twin], 1e-9))
            << b.name() << " is not the mirror image of " << twin.name();
    }
}

/// Every leg's foot touches the ground within 1 % of the leg length.
void expectFeetOnGround(const Skeleton& s) {
    const std::vector<Mat4> world = s.worldTransforms();
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        const Bone& foot = s.bones[i];
        const bool legEnd = (foot.kind == BoneKind::Foot || foot.kind == BoneKind::Hand) &&
                            foot.limb == LimbKind::Leg;
        if (!legEnd) continue;
        const Bone& middle = s.bones[foot.parent];
        const Bone& upper = s.bones[middle.parent];
        const double legLength = foot.extents.x() + middle.extents.x() + upper.extents.x();
        // The foot, or for a tiny foot under a thick shank the ankle end (seed 000 §7.5 point 5),
        // rests on the ground.
        const double lowest =
            std::min(lowestY(foot, world[i]), lowestY(middle, world[foot.parent]));
        EXPECT_NEAR(lowest, s.groundHeight, 0.01 * legLength) << foot.name();
    }
}

TEST(SkeletonPipeline, RandomSkeletonsKeepEveryInvariant) {
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        // Half with the default spread, half with the wider model spread.
        SkeletonInputs inputs;
        inputs.spread = seed % 2 == 0 ? SampleSpread::Thesis : SampleSpread::Model;
        const Skeleton s = generate(inputs, seed);
        expectValidSkeleton(s, "seed " + std::to_string(seed));
        expectFeetOnGround(s);
        if (HasFatalFailure()) return;
    }
}

TEST(SkeletonPipeline, LegInputGivesThatManyLegsOnTheGround) {
    for (int legs : {0, 2, 4}) {
        SkeletonInputs inputs;
        inputs.legs = legs;
        for (std::uint64_t seed = 0; seed < 10; ++seed) {
            const Skeleton s = generate(inputs, seed);
            EXPECT_EQ(countBones(s, BoneKind::Thigh, LimbKind::Leg) +
                          countBones(s, BoneKind::UpperArm, LimbKind::Leg),
                      legs);
            expectFeetOnGround(s);
        }
    }
}

TEST(SkeletonPipeline, EightLegsWithTwoPairsPerGirdle) {
    SkeletonInputs inputs;
    inputs.legs = 8;
    inputs.twoPerGirdle = true;
    const Skeleton s = generate(inputs, 3);
    EXPECT_EQ(countBones(s, BoneKind::Thigh, LimbKind::Leg) +
                  countBones(s, BoneKind::UpperArm, LimbKind::Leg),
              8);
    expectValidSkeleton(s, "8 legs");
    expectFeetOnGround(s);
}

TEST(SkeletonPipeline, EveryLimbInputGivesThatManyLimbs) {
    struct Case {
        SkeletonInputs inputs;
        LimbKind kind;
        int count;
    };
    std::vector<Case> cases;
    SkeletonInputs bird;
    bird.legs = 2;
    bird.wings = 2;
    cases.push_back({bird, LimbKind::Wing, 2});
    SkeletonInputs kangaroo;
    kangaroo.legs = 2;
    kangaroo.arms = 2;
    cases.push_back({kangaroo, LimbKind::Arm, 2});
    SkeletonInputs fish;
    fish.legs = 0;
    fish.fins = 4;
    cases.push_back({fish, LimbKind::Fin, 4});
    SkeletonInputs pegasus;
    pegasus.legs = 4;
    pegasus.wings = 2;
    pegasus.twoPerGirdle = true;
    cases.push_back({pegasus, LimbKind::Wing, 2});
    SkeletonInputs centaur;
    centaur.legs = 4;
    centaur.arms = 2;
    centaur.neckShoulder = NeckShoulder::Forced;
    cases.push_back({centaur, LimbKind::Arm, 2});
    for (const Case& c : cases) {
        for (std::uint64_t seed = 0; seed < 5; ++seed) {
            const Skeleton s = generate(c.inputs, seed);
            const int limbs =
                countBones(s, BoneKind::UpperArm, c.kind) + countBones(s, BoneKind::Thigh, c.kind);
            EXPECT_EQ(limbs, c.count) << limbKindName(c.kind) << " seed " << seed;
            expectValidSkeleton(s, std::string(limbKindName(c.kind)));
        }
    }
}

TEST(SkeletonPipeline, CentaurHasItsArmsOnTheNeck) {
    SkeletonInputs centaur;
    centaur.legs = 4;
    centaur.arms = 2;
    centaur.neckShoulder = NeckShoulder::Forced;
    const Skeleton s = generate(centaur, 11);
    for (const Bone& b : s.bones) {
        if (b.kind == BoneKind::UpperArm && b.limb == LimbKind::Arm) {
            EXPECT_EQ(b.attachment, Attachment::Neck);
        }
    }
}

TEST(SkeletonPipeline, ImpossibleInputsAreErrors) {
    SkeletonInputs odd;
    odd.legs = 3;
    EXPECT_THROW(generate(odd, 1), Error);
    SkeletonInputs tooMany;
    tooMany.legs = 10;
    EXPECT_THROW(generate(tooMany, 1), Error);
    SkeletonInputs noRoom;
    noRoom.legs = 6;
    EXPECT_THROW(generate(noRoom, 1), Error);
}

TEST(SkeletonPipeline, SameSeedGivesTheSameSkeleton) {
    SkeletonDesign a, b;
    const Skeleton first = generate({}, 42, &a);
    const Skeleton second = generate({}, 42, &b);
    EXPECT_EQ(a.featurePoint, b.featurePoint);
    EXPECT_EQ(first.word, second.word);
    ASSERT_EQ(first.bones.size(), second.bones.size());
    const std::vector<Mat4> wa = first.worldTransforms(), wb = second.worldTransforms();
    for (std::size_t i = 0; i < wa.size(); ++i) EXPECT_EQ(wa[i], wb[i]);
}

TEST(SkeletonPipeline, ExampleUsesTheSpeciesPoint) {
    SkeletonInputs inputs;
    inputs.example = "African elephant";
    SkeletonDesign design;
    const Skeleton s = generate(inputs, 1, &design);
    EXPECT_EQ(design.featurePoint, stats().fromExample("African elephant"));
    EXPECT_EQ(countBones(s, BoneKind::Thigh, LimbKind::Leg) +
                  countBones(s, BoneKind::UpperArm, LimbKind::Leg),
              4);
    expectFeetOnGround(s);
    // An elephant is metres tall.
    EXPECT_GT(design.metresPerPixel * 1000.0, 2.0);
}

TEST(SkeletonPipeline, VariationsAreCloseButNotEqual) {
    SkeletonInputs inputs;
    inputs.example = "Horse (warmblood)";
    Rng rng(3);
    const SkeletonDesign source = designSkeleton(stats(), inputs, rng);
    const Eigen::VectorXd sourceQ = stats().project(source.featurePoint);
    double meanDistance = 0.0, meanRandomDistance = 0.0;
    const int runs = 50;
    for (int i = 0; i < runs; ++i) {
        const SkeletonDesign varied = varySkeletonDesign(stats(), source, inputs, rng);
        EXPECT_NE(varied.featurePoint, source.featurePoint);
        meanDistance += (stats().project(varied.featurePoint) - sourceQ).norm() / runs;
        meanRandomDistance += (stats().project(stats().sample(rng)) - sourceQ).norm() / runs;
        expectValidSkeleton(buildSkeleton(varied), "variation " + std::to_string(i));
    }
    EXPECT_LT(meanDistance, meanRandomDistance);
}

}  // namespace
}  // namespace ramus
