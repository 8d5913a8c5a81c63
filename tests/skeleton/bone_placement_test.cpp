// Placement of the grammar's terminals (seed 000 §5.2–5.4; SPEC §F) on real species: the spine
// chain is continuous and lies in the mid-plane, the left side is at z > 0, every frame is
// right-handed, the skull is at the head, the girdles sit on their vertebrae and the limb bones
// are as long as the feature point says.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "ramus/skeleton_stats.hpp"
#include "skeleton/skeleton_build.hpp"
#include "skeleton/thesis_model.hpp"

namespace ramus::detail {
namespace {

using test::thesisModel;

SkeletonDesign designOf(const std::string& species) {
    SkeletonDesign d;
    d.featurePoint = thesisModel().fromExample(species);
    d.neckVertebrae = 7;
    d.frontBackVertebrae = 13;
    d.rearBackVertebrae = 12;
    d.tailVertebrae = 10;
    d.ribs = 15;
    d.limbs[static_cast<int>(Attachment::Hip)] = LimbKind::Leg;
    d.limbs[static_cast<int>(Attachment::Shoulder)] = LimbKind::Leg;
    d.metresPerPixel = 0.004;
    return d;
}

void setLimb(SkeletonDesign& d, Attachment a, LimbKind kind) {
    d.limbs[static_cast<int>(a)] = kind;
}

Vec3 origin(const Mat4& m) { return m.topRightCorner<3, 1>(); }
Vec3 distalEnd(const Mat4& m, const Bone& b) {
    return (m * Vec4(b.extents.x(), 0.0, 0.0, 1.0)).head<3>();
}

bool isSpineBone(BoneKind k) {
    return k == BoneKind::Root || k == BoneKind::Vertebra || k == BoneKind::Skull;
}

struct Placed {
    SkeletonDesign design;
    Spine spine;
    Skeleton skeleton;
    std::vector<Mat4> world;
};

Placed place(const SkeletonDesign& d) {
    Placed p{d, makeSpine(d.features()), {}, {}};
    p.skeleton = placeBones(d, p.spine);
    p.world = p.skeleton.worldTransforms();
    return p;
}

// Every property that must hold for any design.
void checkInvariants(const Placed& p, const std::string& what) {
    const auto& bones = p.skeleton.bones;
    ASSERT_FALSE(bones.empty()) << what;
    EXPECT_EQ(bones[0].kind, BoneKind::Root) << what;
    EXPECT_EQ(bones[0].parent, -1) << what;
    EXPECT_EQ(bones[0].extents, Vec3::Zero()) << what;
    std::set<std::string> names;
    for (std::size_t i = 0; i < bones.size(); ++i) {
        const Bone& b = bones[i];
        const Mat4& w = p.world[i];
        const std::string tag = what + " " + b.name();
        EXPECT_TRUE(names.insert(b.name()).second) << tag << " twice";
        if (i > 0) {
            EXPECT_GE(b.parent, 0) << tag;
            EXPECT_LT(b.parent, static_cast<int>(i)) << tag;
        }
        EXPECT_TRUE(w.allFinite()) << tag;
        EXPECT_TRUE(b.extents.allFinite()) << tag;
        const Mat3 r = w.topLeftCorner<3, 3>();
        EXPECT_NEAR(r.determinant(), 1.0, 1e-12) << tag;
        EXPECT_NEAR((r.transpose() * r - Mat3::Identity()).norm(), 0.0, 1e-12) << tag;
        EXPECT_EQ(b.twin, -1) << tag;
        if (isSpineBone(b.kind)) {
            EXPECT_EQ(b.side, Side::Center) << tag;
            EXPECT_NEAR(origin(w).z(), 0.0, 1e-9) << tag;
            EXPECT_NEAR((r.col(2) - Vec3::UnitZ()).norm(), 0.0, 1e-12) << tag;  // about z only
        } else {
            EXPECT_EQ(b.side, Side::Left) << tag;
            EXPECT_GT(origin(w).z(), 0.0) << tag;
            EXPECT_GT((w * Vec4(0.5 * b.extents.x(), 0, 0, 1)).z(), 0.0) << tag;  // box centre
        }
        if (b.kind == BoneKind::Scapula || b.kind == BoneKind::Pelvis) {
            EXPECT_NEAR((r.col(2) - Vec3::UnitZ()).norm(), 0.0, 1e-12) << tag;
            EXPECT_LT(r(1, 0), -0.4) << tag;  // x points roughly down
            EXPECT_NE(b.limb, LimbKind::None) << tag;
        }
        if (b.kind != BoneKind::Root) {
            EXPECT_GT(b.extents.x(), 0.0) << tag;
            EXPECT_GT(b.extents.y(), 0.0) << tag;
            EXPECT_GT(b.extents.z(), 0.0) << tag;
        }
    }
}

TEST(BonePlacement, ElephantSatisfiesTheInvariants) {
    checkInvariants(place(designOf("African elephant")), "elephant");
}

TEST(BonePlacement, EverySpeciesWithEveryAttachmentSatisfiesTheInvariants) {
    for (const SpeciesRecord& species : thesisModel().species()) {
        SkeletonDesign d = designOf(species.name);
        setLimb(d, Attachment::Hip2, LimbKind::Leg);
        setLimb(d, Attachment::Shoulder2, LimbKind::Wing);
        const Spine spine = makeSpine(d.features());
        if (spine.hasNeck) {
            setLimb(d, Attachment::Neck, LimbKind::Arm);
            setLimb(d, Attachment::Neck2, LimbKind::Fin);
        }
        for (SpineSpacing spacing : {SpineSpacing::ArcLength, SpineSpacing::Parameter}) {
            d.spacing = spacing;
            checkInvariants(place(d), species.name);
        }
    }
}

TEST(BonePlacement, RandomDesignsFromThePcaSatisfyTheInvariants) {
    // Sampled feature points have odd spines (short or missing parts, points below the ground,
    // negative limb lengths); counts from the thesis's ranges (§5.3), limbs at random.
    Rng rng(2024);
    for (int i = 0; i < 300; ++i) {
        SkeletonDesign d;
        d.featurePoint = thesisModel().sample(rng);
        d.neckVertebrae = 7 + static_cast<int>(rng.uniformInt(24));
        d.frontBackVertebrae = 3 + static_cast<int>(rng.uniformInt(12));
        d.rearBackVertebrae = 1 + static_cast<int>(rng.uniformInt(12));
        d.tailVertebrae = 5 + static_cast<int>(rng.uniformInt(16));
        d.ribs = static_cast<int>(rng.uniformInt(
            static_cast<std::uint32_t>(d.frontBackVertebrae + d.rearBackVertebrae + 1)));
        d.spacing = rng.uniform01() < 0.5 ? SpineSpacing::ArcLength : SpineSpacing::Parameter;
        d.grammarSeed = rng.nextU32();
        const bool neck = makeSpine(d.features()).hasNeck;
        using A = Attachment;
        for (auto [first, second] :
             {std::pair{A::Hip, A::Hip2}, std::pair{A::Shoulder, A::Shoulder2},
              std::pair{A::Neck, A::Neck2}}) {
            if (first == A::Neck && !neck) continue;
            for (A at : {first, second}) {
                const auto kind = static_cast<LimbKind>(rng.uniformInt(5));
                if (attachmentAccepts(at, kind)) d.limbs[static_cast<int>(at)] = kind;
            }
            if (d.limb(first) == LimbKind::None) d.limbs[static_cast<int>(second)] = LimbKind::None;
        }
        checkInvariants(place(d), "sample " + std::to_string(i));
        if (HasFailure()) break;
    }
}

TEST(BonePlacement, VertebraeChainContinuouslyFromTheRootToHeadAndTail) {
    const Placed p = place(designOf("Giraffe"));
    const auto& bones = p.skeleton.bones;
    int vertebrae = 0;
    for (std::size_t i = 1; i < bones.size(); ++i) {
        if (bones[i].kind != BoneKind::Vertebra && bones[i].kind != BoneKind::Skull) continue;
        const int parent = bones[i].parent;
        const Vec3 expected =
            parent == 0 ? origin(p.world[0]) : distalEnd(p.world[parent], bones[parent]);
        EXPECT_NEAR((origin(p.world[i]) - expected).norm(), 0.0, 1e-9) << bones[i].name();
        if (bones[i].kind == BoneKind::Vertebra) {
            ++vertebrae;
            EXPECT_TRUE(parent == 0 || bones[parent].kind == BoneKind::Vertebra);
        }
    }
    EXPECT_EQ(vertebrae, 7 + 13 + 12 + 10);
}

const Bone* findBone(const Skeleton& s, const std::string& name, int* index = nullptr) {
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        if (s.bones[i].name() == name) {
            if (index) *index = static_cast<int>(i);
            return &s.bones[i];
        }
    }
    return nullptr;
}

Vec3 endOf(const Placed& p, const std::string& name) {
    int i = -1;
    const Bone* b = findBone(p.skeleton, name, &i);
    EXPECT_NE(b, nullptr) << name;
    return b ? distalEnd(p.world[i], *b) : Vec3::Constant(NAN);
}

Vec3 lifted(const Vec2& v) { return {v.x(), v.y(), 0.0}; }

TEST(BonePlacement, SpineRunsEndAtShoulderHipHeadAndTailTip) {
    const Placed p = place(designOf("Giraffe"));
    const auto& pts = p.spine.points;
    EXPECT_NEAR((endOf(p, "vertebra_back_13") - lifted(pts[3])).norm(), 0.0, 1e-9);
    EXPECT_NEAR((endOf(p, "vertebra_back_25") - lifted(pts[6])).norm(), 0.0, 1e-9);
    EXPECT_NEAR((endOf(p, "vertebra_neck_07") - lifted(pts[0])).norm(), 0.0, 1e-9);
    EXPECT_NEAR((endOf(p, "vertebra_tail_10") - lifted(pts[9])).norm(), 0.0, 1e-9);
    int skull = -1;
    ASSERT_NE(findBone(p.skeleton, "skull", &skull), nullptr);
    EXPECT_NEAR((origin(p.world[skull]) - lifted(pts[0])).norm(), 0.0, 1e-9);
    EXPECT_EQ(p.skeleton.bones[p.skeleton.bones[skull].parent].name(), "vertebra_neck_07");
}

TEST(BonePlacement, RootSitsAtHalfTheBackWithArcLengthSpacing) {
    const Placed p = place(designOf("African elephant"));
    const double t = spineRootParameter(p.spine, SpineSpacing::ArcLength);
    EXPECT_NEAR((origin(p.world[0]) - lifted(spinePoint(p.spine, SpinePart::Back, t))).norm(), 0.0,
                1e-9);
    // Equal arc length: the vertebrae of each half are nearly equally long (chords of equal
    // arcs), 13 in front and 12 behind, each half being half the back.
    const double back = spineLength(p.spine, SpinePart::Back);
    for (const Bone& b : p.skeleton.bones) {
        if (b.kind != BoneKind::Vertebra || b.region != SpineRegion::Back) continue;
        const double arc = 0.5 * back / (b.index <= 13 ? 13 : 12);
        EXPECT_LE(b.extents.x(), arc * (1 + 1e-12)) << b.name();
        EXPECT_GT(b.extents.x(), 0.99 * arc) << b.name();
    }
}

TEST(BonePlacement, ParameterSpacingPutsTheRootAtHalfTheParameter) {
    SkeletonDesign d = designOf("African elephant");
    d.spacing = SpineSpacing::Parameter;
    const Placed p = place(d);
    EXPECT_NEAR((origin(p.world[0]) - lifted(spinePoint(p.spine, SpinePart::Back, 0.5))).norm(),
                0.0, 1e-12);
    // Vertebra 1 of the rear half ends at t = 0.5 + 0.5/12.
    const Vec3 end = endOf(p, "vertebra_back_14");
    EXPECT_NEAR((end - lifted(spinePoint(p.spine, SpinePart::Back, 0.5 + 0.5 / 12))).norm(), 0.0,
                1e-9);
}

TEST(BonePlacement, FrameOfAVertebraPointsAlongItsChord) {
    const Placed p = place(designOf("African elephant"));
    for (std::size_t i = 0; i < p.skeleton.bones.size(); ++i) {
        const Bone& b = p.skeleton.bones[i];
        if (b.kind != BoneKind::Vertebra) continue;
        EXPECT_NEAR(b.joint.rest(2, 2), 1.0, 1e-12) << b.name();  // rest turns about z only
        EXPECT_EQ(b.joint.dofCount, 0);
    }
    // Front vertebrae run towards the head (−x), rear ones towards the tail (+x).
    int front = -1, rear = -1;
    findBone(p.skeleton, "vertebra_back_01", &front);
    findBone(p.skeleton, "vertebra_back_14", &rear);
    EXPECT_LT(p.world[front](0, 0), 0.0);
    EXPECT_GT(p.world[rear](0, 0), 0.0);
}

TEST(BonePlacement, CountsAndIndicesFollowTheDesign) {
    SkeletonDesign d = designOf("African elephant");
    d.ribs = 16;  // 13 in front, 3 behind the root
    const Placed p = place(d);
    std::set<int> ribIndices, neck, back, tail;
    for (const Bone& b : p.skeleton.bones) {
        if (b.kind == BoneKind::Rib) {
            EXPECT_EQ(b.region, SpineRegion::Back);
            EXPECT_EQ(p.skeleton.bones[b.parent].index, b.index);
            ribIndices.insert(b.index);
        }
        if (b.kind != BoneKind::Vertebra) continue;
        (b.region == SpineRegion::Neck   ? neck
         : b.region == SpineRegion::Back ? back
                                         : tail)
            .insert(b.index);
    }
    EXPECT_EQ(neck.size(), 7u);
    EXPECT_EQ(*neck.rbegin(), 7);
    EXPECT_EQ(back.size(), 25u);
    EXPECT_EQ(*back.rbegin(), 25);
    EXPECT_EQ(tail.size(), 10u);
    std::set<int> expectedRibs;
    for (int i = 1; i <= 16; ++i) expectedRibs.insert(i);
    EXPECT_EQ(ribIndices, expectedRibs);
}

TEST(BonePlacement, LimbBonesAreAsLongAsTheFeatures) {
    SkeletonDesign d = designOf("Kangaroo");
    setLimb(d, Attachment::Shoulder, LimbKind::Arm);
    const Placed p = place(d);
    const SkeletonFeatures f = d.features();
    const std::vector<std::pair<std::string, Limb>> limbs = {
        {"upper_arm_L", Limb::UpperArm}, {"forearm_L", Limb::Forearm}, {"hand_L", Limb::Hand},
        {"thigh_L", Limb::Thigh},        {"shank_L", Limb::Shank},     {"foot_L", Limb::Foot}};
    for (const auto& [name, limb] : limbs) {
        const Bone* b = findBone(p.skeleton, name);
        ASSERT_NE(b, nullptr) << name;
        EXPECT_DOUBLE_EQ(b->extents.x(), f.limb(limb)) << name;
        EXPECT_EQ(b->joint.rest, Mat3::Identity()) << name;
        EXPECT_EQ(b->joint.dofCount, 0) << name;
        EXPECT_EQ(b->joint.position, Vec3(p.skeleton.bones[b->parent].extents.x(), 0, 0)) << name;
    }
    EXPECT_EQ(findBone(p.skeleton, "hand_L")->limb, LimbKind::Arm);
    EXPECT_EQ(findBone(p.skeleton, "hand_L")->attachment, Attachment::Shoulder);
    EXPECT_EQ(findBone(p.skeleton, "foot_L")->limb, LimbKind::Leg);
    EXPECT_EQ(findBone(p.skeleton, "foot_L")->attachment, Attachment::Hip);
}

TEST(BonePlacement, NonPositiveLimbLengthsAreClampedToOnePixel) {
    SkeletonDesign d = designOf("Trout");  // no upper arm, forearm, thigh, shank
    setLimb(d, Attachment::Shoulder, LimbKind::Fin);
    setLimb(d, Attachment::Hip, LimbKind::Fin);
    d.featurePoint[kFeatureFirstLimb + static_cast<int>(Limb::Forearm)] = -0.02;
    const Placed p = place(d);
    EXPECT_EQ(findBone(p.skeleton, "upper_arm_L")->extents.x(), 1.0);
    EXPECT_EQ(findBone(p.skeleton, "forearm_L")->extents.x(), 1.0);
    EXPECT_DOUBLE_EQ(findBone(p.skeleton, "hand_L")->extents.x(), d.features().limb(Limb::Hand));
}

TEST(BonePlacement, GirdlesSitOnTheShoulderRibAndTheLastBackVertebra) {
    const Placed p = place(designOf("African elephant"));
    const Skeleton& s = p.skeleton;
    int scapula = -1, pelvis = -1;
    ASSERT_NE(findBone(s, "scapula_L", &scapula), nullptr);
    ASSERT_NE(findBone(s, "pelvis_L", &pelvis), nullptr);
    EXPECT_EQ(s.bones[s.bones[scapula].parent].name(), "rib_back_13_L");
    int hipVertebra = -1;
    ASSERT_NE(findBone(s, "vertebra_back_25", &hipVertebra), nullptr);
    EXPECT_EQ(s.bones[pelvis].parent, hipVertebra);
    // Above the shoulder point P3 and the hip point P6, to the side.
    const Vec3 shoulder = origin(p.world[scapula]);
    EXPECT_NEAR(shoulder.x(), p.spine.points[3].x(), 1e-9);
    EXPECT_NEAR(shoulder.y(), p.spine.points[3].y(), 1e-9);
    const Vec3 hip = origin(p.world[pelvis]);
    EXPECT_NEAR(hip.x(), p.spine.points[6].x(), 1e-9);
    EXPECT_NEAR(hip.y(), p.spine.points[6].y(), 1e-9);
    // The upper arm starts at the scapula's far end.
    int upperArm = -1;
    findBone(s, "upper_arm_L", &upperArm);
    EXPECT_NEAR((origin(p.world[upperArm]) - distalEnd(p.world[scapula], s.bones[scapula])).norm(),
                0.0, 1e-9);
}

TEST(BonePlacement, ShoulderGirdleHangsOnTheVertebraWithoutRibs) {
    SkeletonDesign d = designOf("African elephant");
    d.ribs = 0;
    const Placed p = place(d);
    const Bone* scapula = findBone(p.skeleton, "scapula_L");
    ASSERT_NE(scapula, nullptr);
    EXPECT_EQ(p.skeleton.bones[scapula->parent].name(), "vertebra_back_13");
}

TEST(BonePlacement, DoublePelvisCarriesTwoThighsAtTwoJoints) {
    SkeletonDesign d = designOf("Horse (warmblood)");
    setLimb(d, Attachment::Hip2, LimbKind::Leg);
    const Placed p = place(d);
    int pelvis = -1;
    const Bone* pelvis2 = findBone(p.skeleton, "pelvis_L", &pelvis);
    ASSERT_NE(pelvis2, nullptr);
    EXPECT_TRUE(pelvis2->doubleJoint);
    const Bone* hip = findBone(p.skeleton, "thigh_L");
    const Bone* hip2 = findBone(p.skeleton, "thigh_hip2_L");
    ASSERT_NE(hip, nullptr);
    ASSERT_NE(hip2, nullptr);
    EXPECT_EQ(hip->parent, pelvis);
    EXPECT_EQ(hip2->parent, pelvis);
    EXPECT_EQ(hip2->attachment, Attachment::Hip2);
    EXPECT_GT((hip->joint.position - hip2->joint.position).norm(), 1.0);
    EXPECT_NE(p.skeleton.word.find("pelvis2 ( thigh shank foot ) thigh shank foot"),
              std::string::npos);
}

TEST(BonePlacement, SecondShoulderSitsTwoVertebraeBehindTheFirst) {
    SkeletonDesign d = designOf("Horse (warmblood)");
    setLimb(d, Attachment::Shoulder2, LimbKind::Wing);
    const Placed p = place(d);
    const Bone* scapula = findBone(p.skeleton, "scapula_L");
    const Bone* scapula2 = findBone(p.skeleton, "scapula_shoulder2_L");
    ASSERT_NE(scapula, nullptr);
    ASSERT_NE(scapula2, nullptr);
    EXPECT_EQ(scapula2->limb, LimbKind::Wing);
    EXPECT_EQ(p.skeleton.bones[scapula2->parent].name(), "rib_back_11_L");
    EXPECT_EQ(p.skeleton.bones[scapula->parent].name(), "rib_back_13_L");
}

TEST(BonePlacement, NeckGirdlesSitOnTheNeck) {
    SkeletonDesign d = designOf("Giraffe");
    d.neckVertebrae = 12;
    setLimb(d, Attachment::Neck, LimbKind::Arm);
    setLimb(d, Attachment::Neck2, LimbKind::Arm);
    const Placed p = place(d);
    const Bone* neck = findBone(p.skeleton, "scapula_neck_L");
    const Bone* neck2 = findBone(p.skeleton, "scapula_neck2_L");
    ASSERT_NE(neck, nullptr);
    ASSERT_NE(neck2, nullptr);
    EXPECT_EQ(p.skeleton.bones[neck->parent].name(), "vertebra_neck_10");  // 3 below the skull
    EXPECT_EQ(p.skeleton.bones[neck2->parent].name(), "vertebra_neck_08");
    EXPECT_EQ(findBone(p.skeleton, "hand_neck2_L")->limb, LimbKind::Arm);
}

TEST(BonePlacement, WithoutANeckTheSkullSitsAtTheFrontOfTheBack) {
    const Placed p = place(designOf("Trout"));
    int skull = -1;
    ASSERT_NE(findBone(p.skeleton, "skull", &skull), nullptr);
    EXPECT_EQ(p.skeleton.bones[p.skeleton.bones[skull].parent].name(), "vertebra_back_13");
    EXPECT_NEAR((origin(p.world[skull]) - lifted(p.spine.points[3])).norm(), 0.0, 1e-9);
    for (const Bone& b : p.skeleton.bones) EXPECT_NE(b.region, SpineRegion::Neck);
}

TEST(BonePlacement, RibsHangDownAndOutwards) {
    const Placed p = place(designOf("African elephant"));
    for (std::size_t i = 0; i < p.skeleton.bones.size(); ++i) {
        const Bone& b = p.skeleton.bones[i];
        if (b.kind != BoneKind::Rib) continue;
        const Vec3 x = p.world[i].block<3, 1>(0, 0);
        EXPECT_LT(x.y(), -0.8) << b.name();
        EXPECT_GT(x.z(), 0.2) << b.name();
        EXPECT_GT(b.extents.x(), 10.0) << b.name();
        EXPECT_LE(b.extents.x(), 0.4 * spineLength(p.spine, SpinePart::Back) + 1e-9);
    }
}

TEST(BonePlacement, WordAndScaleComeWithTheSkeleton) {
    const SkeletonDesign d = designOf("African elephant");
    const Placed p = place(d);
    EXPECT_EQ(p.skeleton.metresPerPixel, 0.004);
    EXPECT_EQ(p.skeleton.word.rfind("root ( vertebra", 0), 0u);
    const GrammarParams params = grammarParams(d, p.spine);
    Rng rng(1);
    EXPECT_EQ(p.skeleton.word, boneWord(deriveBoneTree(params, defaultBoneRules(), rng)));
    // One bone per terminal of the word.
    std::size_t terminals = 0;
    for (std::size_t i = 0; i < p.skeleton.word.size(); ++i) {
        const bool start = i == 0 || p.skeleton.word[i - 1] == ' ';
        terminals += start && p.skeleton.word[i] != '(' && p.skeleton.word[i] != ')';
    }
    EXPECT_EQ(terminals, p.skeleton.bones.size());
}

TEST(BonePlacement, PlacementIsDeterministic) {
    const SkeletonDesign d = designOf("Pigeon");
    const Placed a = place(d), b = place(d);
    ASSERT_EQ(a.skeleton.bones.size(), b.skeleton.bones.size());
    for (std::size_t i = 0; i < a.world.size(); ++i) EXPECT_EQ(a.world[i], b.world[i]);
}

TEST(BonePlacement, CustomDictionaryPlacesEveryTerminalByItsKind) {
    BoneRuleDictionary rules = defaultBoneRules();
    rules[BoneSymbol::FrontLimb] = {{[](const GrammarParams&) {
        BoneRuleTree t;
        t.add(BoneSymbol::Hand, t.add(BoneSymbol::UpperArm, -1));
        return t;
    }}};
    const SkeletonDesign d = designOf("African elephant");
    const Spine spine = makeSpine(d.features());
    const Skeleton s = placeBones(d, spine, rules);
    EXPECT_EQ(findBone(s, "forearm_L"), nullptr);
    const Bone* hand = findBone(s, "hand_L");
    ASSERT_NE(hand, nullptr);
    EXPECT_EQ(s.bones[hand->parent].kind, BoneKind::UpperArm);
    EXPECT_EQ(hand->joint.position.x(), s.bones[hand->parent].extents.x());
}

}  // namespace
}  // namespace ramus::detail
