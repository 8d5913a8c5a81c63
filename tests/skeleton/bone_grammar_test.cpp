// The bone grammar G″ (seed 000 §5.4, §5.5.3; SPEC §F): every production's word written out by
// hand, whole words for G, G′ and G″, counts in the tree, the constraints, and a rule dictionary
// with two rules for one nonterminal.
#include <gtest/gtest.h>

#include <functional>
#include <map>

#include "ramus/error.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

// The word after replacing a lone nonterminal once.
std::string expandOnce(BoneSymbol symbol, const GrammarParams& p,
                       const BoneRuleDictionary& rules = defaultBoneRules()) {
    BoneSymbolTree tree;
    BoneSymbolTree::Node node;
    node.symbol = symbol;
    tree.nodes.push_back(node);
    tree.root = 0;
    Rng rng(1);
    EXPECT_TRUE(deriveBoneStep(tree, rules, p, rng));
    return boneWord(tree);
}

std::string wordOf(const GrammarParams& p) {
    Rng rng(1);
    return boneWord(deriveBoneTree(p, defaultBoneRules(), rng));
}

std::string repeat(const std::string& word, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += (i ? " " : "") + word;
    return out;
}

GrammarParams smallParams() {
    GrammarParams p;
    p.frontBackVertebrae = 4;
    p.frontRibs = 2;
    p.rearBackVertebrae = 2;
    p.rearRibs = 1;
    p.neck = 1;
    p.neckVertebrae = 7;
    p.tail = 1;
    p.tailVertebrae = 2;
    p.shoulder = 1;
    p.hip = 1;
    return p;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

std::string paramError(const std::function<void(GrammarParams&)>& change) {
    GrammarParams p = smallParams();
    change(p);
    return errorOf([&] { checkGrammarParams(p); });
}

// ---- productions -------------------------------------------------------------------------------

TEST(BoneGrammar, SkeletonHangsTheFrontPartInBracketsOnTheRoot) {
    EXPECT_EQ(expandOnce(BoneSymbol::Skeleton, smallParams()), "root ( FrontPart ) RearPart");
}

TEST(BoneGrammar, FrontPartWithFiveVertebraeAndThreeRibs) {
    GrammarParams p = smallParams();
    p.frontBackVertebrae = 5;
    p.frontRibs = 3;
    // W^{5−0−3} [W(R)]^0 W(Schulterpartie2) W(R^{min(1,2)}) W(Schulterpartie) Hals
    EXPECT_EQ(expandOnce(BoneSymbol::FrontPart, p),
              "vertebra vertebra vertebra ( ShoulderPart2 ) vertebra ( rib ) vertebra ( "
              "ShoulderPart ) Neck");
}

TEST(BoneGrammar, FrontPartWithThirteenVertebraeAndFiveRibs) {
    GrammarParams p = smallParams();
    p.frontBackVertebrae = 13;
    p.frontRibs = 5;
    p.rearBackVertebrae = 12;
    // W^{13−2−3} [W(R)]^2 W(Schulterpartie2) W(R) W(Schulterpartie) Hals
    EXPECT_EQ(expandOnce(BoneSymbol::FrontPart, p),
              repeat("vertebra", 8) +
                  " vertebra ( rib ) vertebra ( rib ) vertebra ( ShoulderPart2 ) vertebra ( rib "
                  ") vertebra ( ShoulderPart ) Neck");
}

TEST(BoneGrammar, FrontPartWithOneRibPutsItOnlyInTheShoulderPart) {
    GrammarParams p = smallParams();
    p.frontBackVertebrae = 3;
    p.frontRibs = 1;
    // (min(1, 0))^+ = 0: the vertebra before the shoulder has no rib.
    EXPECT_EQ(expandOnce(BoneSymbol::FrontPart, p),
              "vertebra ( ShoulderPart2 ) vertebra vertebra ( ShoulderPart ) Neck");
}

TEST(BoneGrammar, ShoulderPartIsRibThenGirdleOrWhatIsLeftOfIt) {
    GrammarParams p = smallParams();
    p.frontRibs = 1;
    p.shoulder = 1;
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderPart, p), "rib ShoulderGirdle");
    p.shoulder = 0;
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderPart, p), "rib");
    p.frontRibs = 0;
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderPart, p), "");
    p.shoulder = 1;  // no rib: the girdle hangs on the vertebra instead (§5.4)
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderPart, p), "ShoulderGirdle");
}

TEST(BoneGrammar, ShoulderPart2HasARibFromThreeFrontRibsOn) {
    GrammarParams p = smallParams();
    p.shoulder2 = 1;
    p.frontRibs = 3;  // min(1, 3 − 2) = 1
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderPart2, p), "rib ShoulderGirdle");
    p.frontRibs = 2;  // min(1, 0) = 0
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderPart2, p), "ShoulderGirdle");
    p.shoulder2 = 0;
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderPart2, p), "");
}

TEST(BoneGrammar, GirdlesAndLimbsExpandToTheirBones) {
    const GrammarParams p = smallParams();
    EXPECT_EQ(expandOnce(BoneSymbol::ShoulderGirdle, p), "scapula FrontLimb");
    EXPECT_EQ(expandOnce(BoneSymbol::FrontLimb, p), "upper_arm forearm hand");
    EXPECT_EQ(expandOnce(BoneSymbol::HindLimb, p), "thigh shank foot");
}

TEST(BoneGrammar, PelvicGirdleIsSingleDoubleOrAbsent) {
    GrammarParams p = smallParams();
    EXPECT_EQ(expandOnce(BoneSymbol::PelvicGirdle, p), "pelvis HindLimb");
    p.hip2 = 1;
    EXPECT_EQ(expandOnce(BoneSymbol::PelvicGirdle, p), "pelvis2 ( HindLimb ) HindLimb");
    p.hip2 = 0;
    p.hip = 0;
    EXPECT_EQ(expandOnce(BoneSymbol::PelvicGirdle, p), "");
}

TEST(BoneGrammar, NeckWithoutVertebraeIsTheSkullAlone) {
    GrammarParams p = smallParams();
    p.neck = 0;
    p.neckVertebrae = 0;
    EXPECT_EQ(expandOnce(BoneSymbol::Neck, p), "skull");
}

TEST(BoneGrammar, NeckWithoutNeckGirdlesIsGsNeck) {
    GrammarParams p = smallParams();
    p.neckVertebrae = 9;
    EXPECT_EQ(expandOnce(BoneSymbol::Neck, p), repeat("vertebra", 9) + " skull");
}

TEST(BoneGrammar, NeckGirdleSitsThreeVertebraeBelowTheSkull) {
    GrammarParams p = smallParams();
    p.neckShoulder = 1;
    // W^{7−5} W(SG^0) W W(SG) W² Schädel
    EXPECT_EQ(expandOnce(BoneSymbol::Neck, p),
              "vertebra vertebra vertebra vertebra vertebra ( ShoulderGirdle ) vertebra vertebra "
              "skull");
}

TEST(BoneGrammar, SecondNeckGirdleSitsTwoVertebraeFurtherDown) {
    GrammarParams p = smallParams();
    p.neckVertebrae = 8;
    p.neckShoulder = 1;
    p.neckShoulder2 = 1;
    EXPECT_EQ(expandOnce(BoneSymbol::Neck, p),
              "vertebra vertebra vertebra vertebra ( ShoulderGirdle ) vertebra vertebra ( "
              "ShoulderGirdle ) vertebra vertebra skull");
}

TEST(BoneGrammar, RearPartCarriesRibsPelvisAndTail) {
    GrammarParams p = smallParams();
    p.rearBackVertebrae = 4;
    p.rearRibs = 2;
    p.tailVertebrae = 3;
    EXPECT_EQ(expandOnce(BoneSymbol::RearPart, p),
              "vertebra ( rib ) vertebra ( rib ) vertebra vertebra ( PelvicGirdle ) vertebra "
              "vertebra vertebra");
    p.tail = 0;
    p.tailVertebrae = 0;
    EXPECT_EQ(expandOnce(BoneSymbol::RearPart, p),
              "vertebra ( rib ) vertebra ( rib ) vertebra vertebra ( PelvicGirdle )");
}

TEST(BoneGrammar, RearPartWithRibsOnEveryVertebraHangsThePelvisOnTheLast) {
    GrammarParams p = smallParams();
    p.rearRibs = 2;
    p.tail = 0;
    p.tailVertebrae = 0;
    EXPECT_EQ(expandOnce(BoneSymbol::RearPart, p),
              "vertebra ( rib ) vertebra ( rib ) ( PelvicGirdle )");
}

// ---- whole words -------------------------------------------------------------------------------

TEST(BoneGrammar, DerivationGoesProductionByProductionLeftmostFirst) {
    GrammarParams p = smallParams();
    p.frontBackVertebrae = 3;
    p.frontRibs = 0;
    p.rearBackVertebrae = 1;
    p.rearRibs = 0;
    p.neck = 0;
    p.neckVertebrae = 0;
    p.tail = 0;
    p.tailVertebrae = 0;
    p.hip = 0;
    const std::vector<std::string> expected = {
        "Skeleton",
        "root ( FrontPart ) RearPart",
        "root ( vertebra ( ShoulderPart2 ) vertebra vertebra ( ShoulderPart ) Neck ) RearPart",
        "root ( vertebra vertebra vertebra ( ShoulderPart ) Neck ) RearPart",
        "root ( vertebra vertebra vertebra ( ShoulderGirdle ) Neck ) RearPart",
        "root ( vertebra vertebra vertebra ( scapula FrontLimb ) Neck ) RearPart",
        "root ( vertebra vertebra vertebra ( scapula upper_arm forearm hand ) Neck ) RearPart",
        "root ( vertebra vertebra vertebra ( scapula upper_arm forearm hand ) skull ) RearPart",
        "root ( vertebra vertebra vertebra ( scapula upper_arm forearm hand ) skull ) vertebra ( "
        "PelvicGirdle )",
        "root ( vertebra vertebra vertebra ( scapula upper_arm forearm hand ) skull ) vertebra",
    };
    BoneSymbolTree tree = BoneSymbolTree::start();
    Rng rng(3);
    for (std::size_t step = 0; step < expected.size(); ++step) {
        EXPECT_EQ(boneWord(tree), expected[step]) << "after " << step << " steps";
        EXPECT_EQ(deriveBoneStep(tree, defaultBoneRules(), p, rng), step + 1 < expected.size());
    }
}

TEST(BoneGrammar, WordOfGMatchesTheThesisProductions) {
    // G: Vorderteil → W^{4−1−1} [W(R)]^1 W(Schulterpartie) Hals, Hals → W^7 Schädel,
    //    Hinterteil → [W(R)]^1 W^1 (Beckengürtel) W^2.
    EXPECT_EQ(wordOf(smallParams()),
              "root ( vertebra vertebra vertebra ( rib ) vertebra ( rib scapula upper_arm "
              "forearm hand ) " +
                  repeat("vertebra", 7) +
                  " skull ) vertebra ( rib ) vertebra ( pelvis thigh shank foot ) vertebra "
                  "vertebra");
}

TEST(BoneGrammar, WordOfGPrimeHasTwoShouldersAndADoublePelvis) {
    GrammarParams p;
    p.frontBackVertebrae = 5;
    p.frontRibs = 4;
    p.rearBackVertebrae = 1;
    p.neck = 0;
    p.neckVertebrae = 0;
    p.shoulder = p.shoulder2 = 1;
    p.hip = p.hip2 = 1;
    EXPECT_EQ(wordOf(p),
              "root ( vertebra vertebra ( rib ) vertebra ( rib scapula upper_arm forearm hand ) "
              "vertebra ( rib ) vertebra ( rib scapula upper_arm forearm hand ) skull ) vertebra "
              "( pelvis2 ( thigh shank foot ) thigh shank foot )");
}

TEST(BoneGrammar, WordOfGDoublePrimeHasGirdlesOnTheNeck) {
    GrammarParams p;
    p.frontBackVertebrae = 3;
    p.rearBackVertebrae = 1;
    p.neckVertebrae = 7;
    p.shoulder = 1;
    p.neckShoulder = p.neckShoulder2 = 1;
    const std::string arm = "( scapula upper_arm forearm hand )";
    EXPECT_EQ(wordOf(p), "root ( vertebra vertebra vertebra " + arm +
                             " vertebra vertebra vertebra " + arm + " vertebra vertebra " + arm +
                             " vertebra vertebra skull ) vertebra");
}

// ---- the tree ----------------------------------------------------------------------------------

struct Counts {
    std::map<SpineSection, int> vertebrae;
    int ribs = 0, scapulae = 0, pelves = 0, skulls = 0, roots = 0;
};

Counts countTree(const BoneSymbolTree& tree) {
    Counts c;
    for (const auto& node : tree.nodes) {
        EXPECT_TRUE(isTerminal(node.symbol));
        if (node.symbol == BoneSymbol::Vertebra) ++c.vertebrae[node.section];
        c.ribs += node.symbol == BoneSymbol::Rib;
        c.scapulae += node.symbol == BoneSymbol::Scapula;
        c.pelves += node.symbol == BoneSymbol::Pelvis || node.symbol == BoneSymbol::Pelvis2;
        c.skulls += node.symbol == BoneSymbol::Skull;
        c.roots += node.parent < 0;
    }
    return c;
}

TEST(BoneGrammar, TreeCountsMatchTheParametersOverManyCombinations) {
    int checked = 0;
    for (int front = 3; front <= 6; ++front)
        for (int rear = 1; rear <= 3; ++rear)
            for (int ribs = 0; ribs <= front + rear; ++ribs)
                for (int neck : {0, 7, 9})
                    for (int flags = 0; flags < 64; flags += 5) {
                        GrammarParams p;
                        p.frontBackVertebrae = front;
                        p.rearBackVertebrae = rear;
                        p.frontRibs = std::min(ribs, front);
                        p.rearRibs = ribs - p.frontRibs;
                        p.neckVertebrae = neck;
                        p.neck = neck > 0;
                        p.tailVertebrae = flags % 4;
                        p.tail = p.tailVertebrae > 0;
                        p.shoulder = (flags >> 1) & 1;
                        p.shoulder2 = p.shoulder & (flags >> 2);
                        p.hip = (flags >> 3) & 1;
                        p.hip2 = p.hip & (flags >> 4);
                        p.neckShoulder = p.neck & (flags >> 5);
                        p.neckShoulder2 = p.neckShoulder & flags;
                        Rng rng(7);
                        const BoneSymbolTree tree = deriveBoneTree(p, defaultBoneRules(), rng);
                        const Counts c = countTree(tree);
                        ASSERT_EQ(c.roots, 1);
                        EXPECT_EQ(tree.root, 0);
                        EXPECT_EQ(tree.nodes[0].symbol, BoneSymbol::Root);
                        for (std::size_t i = 1; i < tree.nodes.size(); ++i)
                            EXPECT_LT(tree.nodes[i].parent, static_cast<int>(i));
                        EXPECT_EQ(c.vertebrae.count(SpineSection::None), 0u);
                        EXPECT_EQ(c.vertebrae.at(SpineSection::FrontBack), front);
                        EXPECT_EQ(c.vertebrae.at(SpineSection::RearBack), rear);
                        EXPECT_EQ(c.vertebrae.count(SpineSection::Neck)
                                      ? c.vertebrae.at(SpineSection::Neck)
                                      : 0,
                                  neck);
                        EXPECT_EQ(c.vertebrae.count(SpineSection::Tail)
                                      ? c.vertebrae.at(SpineSection::Tail)
                                      : 0,
                                  p.tailVertebrae);
                        EXPECT_EQ(c.ribs, ribs);
                        EXPECT_EQ(c.skulls, 1);
                        EXPECT_EQ(c.scapulae,
                                  p.shoulder + p.shoulder2 + p.neckShoulder + p.neckShoulder2);
                        EXPECT_EQ(c.pelves, p.hip);
                        ++checked;
                    }
    EXPECT_GT(checked, 1000);
}

TEST(BoneGrammar, RibsSitOnTheBackVerticesNearestTheShoulder) {
    GrammarParams p = smallParams();
    p.frontBackVertebrae = 6;
    p.frontRibs = 6;
    p.rearBackVertebrae = 5;
    p.rearRibs = 2;
    Rng rng(1);
    const BoneSymbolTree tree = deriveBoneTree(p, defaultBoneRules(), rng);
    // Position of each back vertebra from the root, per half; which carry a rib.
    std::vector<int> depth(tree.nodes.size(), 0);
    std::map<SpineSection, std::vector<int>> ribbed;
    for (std::size_t i = 1; i < tree.nodes.size(); ++i) {
        const auto& node = tree.nodes[i];
        const auto& parent = tree.nodes[node.parent];
        if (node.symbol == BoneSymbol::Vertebra)
            depth[i] = parent.symbol == BoneSymbol::Vertebra ? depth[node.parent] + 1 : 1;
        if (node.symbol == BoneSymbol::Rib) ribbed[parent.section].push_back(depth[node.parent]);
    }
    EXPECT_EQ(ribbed[SpineSection::FrontBack], (std::vector<int>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(ribbed[SpineSection::RearBack], (std::vector<int>{1, 2}));
}

TEST(BoneGrammar, AttachmentsAreTaggedOnGirdlesAndLimbs) {
    GrammarParams p = smallParams();
    p.shoulder2 = p.hip2 = p.neckShoulder = p.neckShoulder2 = 1;
    p.neckVertebrae = 9;
    Rng rng(1);
    const BoneSymbolTree tree = deriveBoneTree(p, defaultBoneRules(), rng);
    std::map<Attachment, int> upperArms, thighs;
    for (const auto& node : tree.nodes) {
        if (node.symbol == BoneSymbol::UpperArm) ++upperArms[node.attachment.value()];
        if (node.symbol == BoneSymbol::Thigh) ++thighs[node.attachment.value()];
        if (node.symbol == BoneSymbol::Vertebra || node.symbol == BoneSymbol::Rib) {
            EXPECT_FALSE(node.attachment.has_value());
        }
    }
    EXPECT_EQ(upperArms, (std::map<Attachment, int>{{Attachment::Shoulder, 1},
                                                    {Attachment::Shoulder2, 1},
                                                    {Attachment::Neck, 1},
                                                    {Attachment::Neck2, 1}}));
    EXPECT_EQ(thighs, (std::map<Attachment, int>{{Attachment::Hip, 1}, {Attachment::Hip2, 1}}));
}

// ---- the dictionary ----------------------------------------------------------------------------

BoneRuleTree shortArm(const GrammarParams&) {
    BoneRuleTree t;
    t.add(BoneSymbol::Hand, t.add(BoneSymbol::UpperArm, -1));
    return t;
}

BoneRuleDictionary twoArmRules(double shortWeight) {
    BoneRuleDictionary rules = defaultBoneRules();
    rules[BoneSymbol::FrontLimb].push_back({shortArm, shortWeight});
    return rules;
}

TEST(BoneGrammar, TwoRulesForOneNonterminalArePickedByWeight) {
    const BoneRuleDictionary rules = twoArmRules(3.0);
    int shortArms = 0;
    constexpr int kSeeds = 4000;
    for (int seed = 0; seed < kSeeds; ++seed) {
        Rng rng(static_cast<std::uint64_t>(seed));
        const std::string word = boneWord(deriveBoneTree(smallParams(), rules, rng));
        const bool isShort = word.find("upper_arm hand") != std::string::npos;
        EXPECT_TRUE(isShort || word.find("upper_arm forearm hand") != std::string::npos);
        shortArms += isShort;
    }
    EXPECT_NEAR(shortArms / static_cast<double>(kSeeds), 0.75, 0.03);
}

TEST(BoneGrammar, ARuleOfWeightZeroIsNeverPicked) {
    const BoneRuleDictionary rules = twoArmRules(0.0);
    for (int seed = 0; seed < 200; ++seed) {
        Rng rng(static_cast<std::uint64_t>(seed));
        EXPECT_EQ(boneWord(deriveBoneTree(smallParams(), rules, rng)), wordOf(smallParams()));
    }
}

TEST(BoneGrammar, SameSeedSameWord) {
    const BoneRuleDictionary rules = twoArmRules(1.0);
    for (int seed = 0; seed < 20; ++seed) {
        Rng a(static_cast<std::uint64_t>(seed)), b(static_cast<std::uint64_t>(seed));
        EXPECT_EQ(boneWord(deriveBoneTree(smallParams(), rules, a)),
                  boneWord(deriveBoneTree(smallParams(), rules, b)));
    }
}

TEST(BoneGrammar, MissingRuleIsAnError) {
    BoneRuleDictionary rules = defaultBoneRules();
    rules[BoneSymbol::HindLimb].clear();
    Rng rng(1);
    EXPECT_NE(errorOf([&] {
                  deriveBoneTree(smallParams(), rules, rng);
              }).find("no rule for the nonterminal HindLimb"),
              std::string::npos);
}

TEST(BoneGrammar, ARuleGivingANonterminalAChildIsAnError) {
    BoneRuleDictionary rules = defaultBoneRules();
    rules[BoneSymbol::ShoulderGirdle] = {{[](const GrammarParams&) {
        BoneRuleTree t;
        t.add(BoneSymbol::Scapula, t.add(BoneSymbol::FrontLimb, -1));
        return t;
    }}};
    Rng rng(1);
    EXPECT_NE(errorOf([&] {
                  deriveBoneTree(smallParams(), rules, rng);
              }).find("nonterminals must be leaves"),
              std::string::npos);
}

// ---- constraints -------------------------------------------------------------------------------

TEST(BoneGrammar, SmallParamsAreValid) {
    EXPECT_EQ(paramError([](GrammarParams&) {}), "(no error)");
}

TEST(BoneGrammar, FewerThanThreeFrontBackVerticesIsAnError) {
    const std::string e = paramError([](GrammarParams& p) {
        p.frontBackVertebrae = 2;
        p.frontRibs = 2;
    });
    EXPECT_NE(e.find("w_rv"), std::string::npos) << e;
    EXPECT_NE(e.find("≥ 3"), std::string::npos) << e;
}

TEST(BoneGrammar, NoRearBackVertebraIsAnError) {
    const std::string e = paramError([](GrammarParams& p) {
        p.rearBackVertebrae = 0;
        p.rearRibs = 0;
    });
    EXPECT_NE(e.find("w_rh ≥ 1"), std::string::npos) << e;
}

TEST(BoneGrammar, MoreFrontRibsThanVertebraeIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.frontRibs = 5; });
    EXPECT_NE(e.find("w_rv^r ≤ w_rv"), std::string::npos) << e;
}

TEST(BoneGrammar, NegativeRearRibsIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.rearRibs = -1; });
    EXPECT_NE(e.find("0 ≤ w_rh^r"), std::string::npos) << e;
}

TEST(BoneGrammar, NeckFlagOutsideZeroOneIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.neck = 2; });
    EXPECT_NE(e.find("h ∈ {0, 1}"), std::string::npos) << e;
}

TEST(BoneGrammar, NeckWithFewerThanSevenVertebraeIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.neckVertebrae = 6; });
    EXPECT_NE(e.find("w_h ≥ 7"), std::string::npos) << e;
}

TEST(BoneGrammar, NeckVertebraeWithoutNeckIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.neck = 0; });
    EXPECT_NE(e.find("h = 0 ⇒ w_h = 0"), std::string::npos) << e;
}

TEST(BoneGrammar, TailVertebraeWithoutTailIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.tail = 0; });
    EXPECT_NE(e.find("s = 0 ⇒ w_s = 0"), std::string::npos) << e;
}

TEST(BoneGrammar, SecondShoulderWithoutFirstIsAnError) {
    const std::string e = paramError([](GrammarParams& p) {
        p.shoulder = 0;
        p.shoulder2 = 1;
    });
    EXPECT_NE(e.find("e_s2 = 1 needs e_s = 1"), std::string::npos) << e;
}

TEST(BoneGrammar, SecondHipWithoutFirstIsAnError) {
    const std::string e = paramError([](GrammarParams& p) {
        p.hip = 0;
        p.hip2 = 1;
    });
    EXPECT_NE(e.find("e_b2 = 1 needs e_b = 1"), std::string::npos) << e;
}

TEST(BoneGrammar, NeckGirdleWithoutNeckIsAnError) {
    const std::string e = paramError([](GrammarParams& p) {
        p.neck = 0;
        p.neckVertebrae = 0;
        p.neckShoulder = 1;
    });
    EXPECT_NE(e.find("e_h = 1 needs h = 1"), std::string::npos) << e;
}

TEST(BoneGrammar, SecondNeckGirdleWithoutFirstIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.neckShoulder2 = 1; });
    EXPECT_NE(e.find("e_h2 = 1 needs e_h = 1"), std::string::npos) << e;
}

TEST(BoneGrammar, LimbFlagOutsideZeroOneIsAnError) {
    const std::string e = paramError([](GrammarParams& p) { p.hip = 3; });
    EXPECT_NE(e.find("e_b ∈ {0, 1}"), std::string::npos) << e;
}

TEST(BoneGrammar, DerivationChecksTheParameters) {
    GrammarParams p = smallParams();
    p.frontBackVertebrae = 1;
    p.frontRibs = 0;
    Rng rng(1);
    EXPECT_NE(errorOf([&] { deriveBoneTree(p, defaultBoneRules(), rng); }).find("w_rv"),
              std::string::npos);
}

// ---- parameters from a design ------------------------------------------------------------------

Spine straightSpine(bool neck, bool tail) {
    Spine s;
    for (int i = 0; i < kSpinePointCount; ++i) s.points[i] = Vec2(100.0 * i, 500.0);
    if (!neck) s.points[0] = s.points[1] = s.points[2] = s.points[3];
    if (!tail) s.points[7] = s.points[8] = s.points[9] = s.points[6];
    s.hasNeck = neck;
    s.hasTail = tail;
    return s;
}

TEST(BoneGrammar, ParamsFromADesignSplitTheRibsAndReadTheLimbs) {
    SkeletonDesign d;
    d.frontBackVertebrae = 13;
    d.rearBackVertebrae = 12;
    d.ribs = 17;
    d.neckVertebrae = 9;
    d.tailVertebrae = 11;
    d.limbs[static_cast<int>(Attachment::Hip)] = LimbKind::Leg;
    d.limbs[static_cast<int>(Attachment::Shoulder)] = LimbKind::Wing;
    d.limbs[static_cast<int>(Attachment::Shoulder2)] = LimbKind::Arm;
    d.limbs[static_cast<int>(Attachment::Neck)] = LimbKind::Fin;
    const GrammarParams p = grammarParams(d, straightSpine(true, true));
    EXPECT_EQ(p.frontBackVertebrae, 13);
    EXPECT_EQ(p.frontRibs, 13);
    EXPECT_EQ(p.rearBackVertebrae, 12);
    EXPECT_EQ(p.rearRibs, 4);
    EXPECT_EQ(p.neck, 1);
    EXPECT_EQ(p.neckVertebrae, 9);
    EXPECT_EQ(p.tail, 1);
    EXPECT_EQ(p.tailVertebrae, 11);
    EXPECT_EQ(p.hip, 1);
    EXPECT_EQ(p.hip2, 0);
    EXPECT_EQ(p.shoulder, 1);
    EXPECT_EQ(p.shoulder2, 1);
    EXPECT_EQ(p.neckShoulder, 1);
    EXPECT_EQ(p.neckShoulder2, 0);
}

TEST(BoneGrammar, ParamsDropNeckAndTailTheSpineDoesNotHave) {
    SkeletonDesign d;
    d.tailVertebrae = 10;
    const GrammarParams p = grammarParams(d, straightSpine(false, false));
    EXPECT_EQ(p.neck, 0);
    EXPECT_EQ(p.neckVertebrae, 0);
    EXPECT_EQ(p.tail, 0);
    EXPECT_EQ(p.tailVertebrae, 0);
}

TEST(BoneGrammar, DesignWithTooManyRibsIsAnError) {
    SkeletonDesign d;
    d.ribs = 26;
    const std::string e = errorOf([&] { grammarParams(d, straightSpine(true, false)); });
    EXPECT_NE(e.find("r (ribs) = 26"), std::string::npos) << e;
}

TEST(BoneGrammar, DesignWithALegOnTheNeckIsAnError) {
    SkeletonDesign d;
    d.limbs[static_cast<int>(Attachment::Neck)] = LimbKind::Leg;
    const std::string e = errorOf([&] { grammarParams(d, straightSpine(true, false)); });
    EXPECT_NE(e.find("a leg cannot attach at neck"), std::string::npos) << e;
}

TEST(BoneGrammar, DesignWithAWingAtTheHipIsAnError) {
    SkeletonDesign d;
    d.limbs[static_cast<int>(Attachment::Hip)] = LimbKind::Wing;
    const std::string e = errorOf([&] { grammarParams(d, straightSpine(true, false)); });
    EXPECT_NE(e.find("a wing cannot attach at hip"), std::string::npos) << e;
}

TEST(BoneGrammar, DesignWithANeckGirdleButNoNeckIsAnError) {
    SkeletonDesign d;
    d.limbs[static_cast<int>(Attachment::Neck)] = LimbKind::Arm;
    const std::string e = errorOf([&] { grammarParams(d, straightSpine(false, false)); });
    EXPECT_NE(e.find("e_h = 1 needs h = 1"), std::string::npos) << e;
}

TEST(BoneGrammar, DesignWithASecondHipButNoFirstIsAnError) {
    SkeletonDesign d;
    d.limbs[static_cast<int>(Attachment::Hip2)] = LimbKind::Leg;
    const std::string e = errorOf([&] { grammarParams(d, straightSpine(true, false)); });
    EXPECT_NE(e.find("e_b2 = 1 needs e_b = 1"), std::string::npos) << e;
}

TEST(BoneGrammar, SymbolNames) {
    EXPECT_EQ(boneSymbolName(BoneSymbol::Pelvis2), "pelvis2");
    EXPECT_EQ(boneSymbolName(BoneSymbol::UpperArm), "upper_arm");
    EXPECT_EQ(boneSymbolName(BoneSymbol::ShoulderGirdle), "ShoulderGirdle");
    EXPECT_EQ(boneSymbolName(BoneSymbol::HindLimb), "HindLimb");
    for (int i = 0; i < kFirstNonterminal; ++i) {
        const auto s = static_cast<BoneSymbol>(i);
        EXPECT_TRUE(isTerminal(s));
        if (s != BoneSymbol::Pelvis2) EXPECT_EQ(boneSymbolName(s), boneKindName(boneSymbolKind(s)));
    }
    EXPECT_EQ(boneSymbolKind(BoneSymbol::Pelvis2), BoneKind::Pelvis);
    EXPECT_FALSE(isTerminal(BoneSymbol::Skeleton));
}

}  // namespace
}  // namespace ramus::detail
