// Limb kinds per attachment (seed 000 §5.5, §5.5.3, §6.1, §6.3): user counts first and exact,
// the thesis's random rules for the rest, clear errors for impossible combinations.
#include "skeleton/limb_assignment.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "ramus/error.hpp"

namespace ramus::detail {
namespace {

using A = Attachment;
constexpr int at(Attachment a) { return static_cast<int>(a); }

/// A spine with a straight neck of `neckLength` px from the shoulder (300, 500) towards the
/// head at −x, a straight back and a short tail.
Spine straightSpine(double neckLength) {
    Spine spine;
    const Vec2 shoulder(300, 500), hip(700, 500), tip(900, 500);
    for (int i = 0; i <= 3; ++i) {
        spine.points[i] = shoulder + Vec2(-neckLength * (3 - i) / 3.0, 0.0);
        spine.points[3 + i] = shoulder + (hip - shoulder) * (i / 3.0);
        spine.points[6 + i] = hip + (tip - hip) * (i / 3.0);
    }
    spine.hasNeck = neckLength > 0;
    spine.hasTail = true;
    return spine;
}

/// Features of a mammal-like animal with long limbs and no random legs, wings or fins.
SkeletonFeatures plainFeatures() {
    SkeletonFeatures features;
    features.limbs = {150, 150, 60, 180, 160, 80};
    features.legs = 0.0;
    features.wings = 0.0;
    return features;
}

int countOf(const LimbLayout& layout, LimbKind kind) {
    return static_cast<int>(std::count(layout.begin(), layout.end(), kind));
}

LimbLayout assign(const SkeletonInputs& inputs, double neckLength = 100.0,
                  SkeletonFeatures features = plainFeatures(), std::uint64_t seed = 1) {
    Rng rng(seed);
    return assignLimbs(features, straightSpine(neckLength), inputs, rng);
}

TEST(LimbAssignment, FourLegsGoToHipAndShoulder) {
    SkeletonInputs inputs;
    inputs.legs = 4;
    const LimbLayout layout = assign(inputs);
    EXPECT_EQ(layout[at(A::Hip)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Shoulder)], LimbKind::Leg);
    EXPECT_EQ(countOf(layout, LimbKind::Leg), 2);
}

TEST(LimbAssignment, BirdHasLegsAtTheHipAndWingsAtTheShoulder) {
    SkeletonInputs inputs;
    inputs.legs = 2;
    inputs.wings = 2;
    const LimbLayout layout = assign(inputs);
    EXPECT_EQ(layout[at(A::Hip)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Shoulder)], LimbKind::Wing);
}

TEST(LimbAssignment, PegasusNeedsTwoPairsPerGirdle) {
    SkeletonInputs inputs;
    inputs.legs = 4;
    inputs.wings = 2;
    inputs.neckShoulder = NeckShoulder::Forbidden;
    EXPECT_THROW(assign(inputs), Error);
    inputs.twoPerGirdle = true;
    const LimbLayout layout = assign(inputs);
    EXPECT_EQ(layout[at(A::Hip)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Shoulder)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Shoulder2)], LimbKind::Wing);
}

TEST(LimbAssignment, CentaurPutsArmsOnAForcedNeckGirdle) {
    SkeletonInputs inputs;
    inputs.legs = 4;
    inputs.arms = 2;
    inputs.neckShoulder = NeckShoulder::Forced;
    const LimbLayout layout = assign(inputs, 260.0);
    EXPECT_EQ(layout[at(A::Hip)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Shoulder)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Neck)], LimbKind::Arm);
}

TEST(LimbAssignment, ShortNeckCarriesNoGirdleWhenOnlyAllowed) {
    SkeletonInputs inputs;
    inputs.legs = 4;
    inputs.arms = 2;
    EXPECT_THROW(assign(inputs, 100.0), Error);
    const LimbLayout layout = assign(inputs, kNeckGirdleMinLength + 10.0);
    EXPECT_EQ(layout[at(A::Neck)], LimbKind::Arm);
}

TEST(LimbAssignment, ForcedNeckGirdleWithoutANeckIsAnError) {
    SkeletonInputs inputs;
    inputs.neckShoulder = NeckShoulder::Forced;
    EXPECT_THROW(assign(inputs, 0.0), Error);
}

TEST(LimbAssignment, ForcedNeckGirdleGetsArmsWhenNoCountSaysOtherwise) {
    SkeletonInputs inputs;
    inputs.legs = 4;
    inputs.neckShoulder = NeckShoulder::Forced;
    const LimbLayout layout = assign(inputs, 260.0);
    EXPECT_EQ(layout[at(A::Neck)], LimbKind::Arm);
}

TEST(LimbAssignment, EightLegsUseAllFourLegAttachments) {
    SkeletonInputs inputs;
    inputs.legs = 8;
    inputs.twoPerGirdle = true;
    const LimbLayout layout = assign(inputs);
    EXPECT_EQ(countOf(layout, LimbKind::Leg), 4);
    EXPECT_EQ(layout[at(A::Neck)], LimbKind::None);
    inputs.twoPerGirdle = false;
    EXPECT_THROW(assign(inputs), Error);
}

TEST(LimbAssignment, UserCountsAreExact) {
    SkeletonInputs inputs;
    inputs.legs = 2;
    inputs.fins = 2;
    inputs.wings = 0;
    inputs.arms = 0;
    SkeletonFeatures features = plainFeatures();
    features.legs = 2.0;   // would give front legs too
    features.wings = 1.0;  // would give wings
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const LimbLayout layout = assign(inputs, 100.0, features, seed);
        EXPECT_EQ(countOf(layout, LimbKind::Leg), 1);
        EXPECT_EQ(countOf(layout, LimbKind::Fin), 1);
        EXPECT_EQ(countOf(layout, LimbKind::Wing), 0);
        EXPECT_EQ(layout[at(A::Shoulder)], LimbKind::Fin);
    }
}

TEST(LimbAssignment, TwoLegPairsFromTheStatisticsGiveFrontAndHindLegs) {
    SkeletonFeatures features = plainFeatures();
    features.legs = 2.0;
    const LimbLayout layout = assign({}, 100.0, features);
    EXPECT_EQ(layout[at(A::Hip)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Shoulder)], LimbKind::Leg);
}

TEST(LimbAssignment, LegProbabilityFollowsVb) {
    SkeletonFeatures features = plainFeatures();
    features.legs = 0.3;
    int hind = 0, front = 0;
    const int runs = 2000;
    for (int seed = 0; seed < runs; ++seed) {
        const LimbLayout layout = assign({}, 100.0, features, static_cast<std::uint64_t>(seed));
        hind += layout[at(A::Hip)] == LimbKind::Leg;
        front += layout[at(A::Shoulder)] == LimbKind::Leg;
    }
    EXPECT_NEAR(hind / double(runs), 0.3, 0.04);
    EXPECT_EQ(front, 0);
}

TEST(LimbAssignment, ShortLimbsBecomeFinsAtFreeGirdles) {
    SkeletonFeatures features = plainFeatures();
    features.limbs = {40, 30, 20, 50, 40, 30};
    const LimbLayout layout = assign({}, 0.0, features);
    EXPECT_EQ(layout[at(A::Hip)], LimbKind::Fin);
    EXPECT_EQ(layout[at(A::Shoulder)], LimbKind::Fin);
}

TEST(LimbAssignment, NormalizeMovesSecondaryLimbsToEmptyPrimaries) {
    LimbLayout layout{};
    layout[at(A::Hip2)] = LimbKind::Leg;
    layout[at(A::Neck2)] = LimbKind::Wing;
    normalizeLimbLayout(layout);
    EXPECT_EQ(layout[at(A::Hip)], LimbKind::Leg);
    EXPECT_EQ(layout[at(A::Hip2)], LimbKind::None);
    EXPECT_EQ(layout[at(A::Neck)], LimbKind::Wing);
    EXPECT_EQ(layout[at(A::Neck2)], LimbKind::None);
}

TEST(LimbAssignment, VariationsKeepUserCountsAndChangeSomething) {
    SkeletonInputs inputs;
    inputs.legs = 4;
    inputs.twoPerGirdle = true;
    const Spine spine = straightSpine(100.0);
    Rng rng(5);
    const LimbLayout source = assignLimbs(plainFeatures(), spine, inputs, rng);
    int changed = 0;
    for (int i = 0; i < 200; ++i) {
        const LimbLayout varied = varyLimbs(source, plainFeatures(), spine, inputs, rng);
        EXPECT_EQ(countOf(varied, LimbKind::Leg), 2);
        changed += varied != source;
    }
    EXPECT_GT(changed, 20);
}

TEST(LimbAssignment, VariationChangesAtMostOneAttachmentBeforeNormalizing) {
    const Spine spine = straightSpine(100.0);
    Rng rng(9);
    LimbLayout source{};
    source[at(A::Hip)] = LimbKind::Leg;
    for (int i = 0; i < 200; ++i) {
        const LimbLayout varied = varyLimbs(source, plainFeatures(), spine, {}, rng);
        int differences = 0;
        for (int a = 0; a < kAttachmentCount; ++a) differences += varied[a] != source[a];
        EXPECT_LE(differences, 2);  // a move changes two attachments
        for (int a = 0; a < kAttachmentCount; ++a) {
            EXPECT_TRUE(attachmentAccepts(static_cast<Attachment>(a), varied[a]));
        }
    }
}

}  // namespace
}  // namespace ramus::detail
