// The productions of the bone grammar G″ as the default rule dictionary.
//
// Based on: seed 000 §5.4 (the productions P of G; A^x = x copies in a row, (x)^+ = max(0, x);
// parentheses = children; the shoulder girdle hangs on the shoulder rib, or on the shoulder
// vertebra without it), §5.5.3 (G′'s Vorderteil, Schulterpartie2 and Beckengürtel, G″'s Hals);
// SPEC §F.
#include <algorithm>

#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

int positive(int x) { return x > 0 ? x : 0; }

// ---- the productions of G″ (SPEC §F) -------------------------------------------------------

// Skelett → Wurzelknochen (Vorderteil) Hinterteil
BoneRuleTree skeletonRule(const GrammarParams&) {
    BoneRuleTree t;
    const int root = t.add(BoneSymbol::Root, -1);
    t.add(BoneSymbol::FrontPart, root, true);
    t.add(BoneSymbol::RearPart, root, false);
    return t;
}

// [Wirbel (Rippe)]^count, the first hanging on `parent`; returns the last vertebra.
int ribbedChain(BoneRuleTree& t, int count, int parent, SpineSection section) {
    for (int i = 0; i < count; ++i) {
        parent = t.chain(BoneSymbol::Vertebra, 1, parent, false, section);
        t.add(BoneSymbol::Rib, parent, true);
    }
    return parent;
}

// G′: Vorderteil → Wirbel^{w_rv − (w_rv^r − 3)^+ − 3} [Wirbel (Rippe)]^{(w_rv^r − 3)^+}
//                  Wirbel (Schulterpartie2) Wirbel (Rippe^{(min(1, w_rv^r − 1))^+})
//                  Wirbel (Schulterpartie) Hals
// With e_s2 = 0 this is G's Vorderteil: the same vertebrae, ribs on the last w_rv^r of them.
BoneRuleTree frontPartRule(const GrammarParams& p) {
    constexpr SpineSection kBack = SpineSection::FrontBack;
    BoneRuleTree t;
    const int ribbed = positive(p.frontRibs - 3);
    int last = t.chain(BoneSymbol::Vertebra, p.frontBackVertebrae - ribbed - 3, -1, false, kBack);
    last = ribbedChain(t, ribbed, last, kBack);
    last = t.chain(BoneSymbol::Vertebra, 1, last, false, kBack);
    t.add(BoneSymbol::ShoulderPart2, last, true);
    last = t.chain(BoneSymbol::Vertebra, 1, last, false, kBack);
    t.add(BoneSymbol::Rib, last, true, positive(std::min(1, p.frontRibs - 1)) > 0);
    last = t.chain(BoneSymbol::Vertebra, 1, last, false, kBack);
    t.add(BoneSymbol::ShoulderPart, last, true);
    t.add(BoneSymbol::Neck, last, false);
    return t;
}

// Schulterpartie → Rippe^{min(1, w_rv^r)} Schultergürtel^{e_s}, and G′'s
// Schulterpartie2 → Rippe^{min(1, w_rv^r − 2)} Schultergürtel^{e_s2}. The girdle hangs on the
// rib, or on the shoulder vertebra when the rib is absent.
BoneRuleTree shoulderPartTree(int ribs, int girdle, Attachment attachment) {
    BoneRuleTree t;
    const int rib = t.add(BoneSymbol::Rib, -1, false, ribs > 0);
    const int g = t.add(BoneSymbol::ShoulderGirdle, rib, false, girdle == 1);
    t.nodes[g].fallback = true;
    t.nodes[g].attachment = attachment;
    return t;
}

BoneRuleTree shoulderPartRule(const GrammarParams& p) {
    return shoulderPartTree(std::min(1, p.frontRibs), p.shoulder, Attachment::Shoulder);
}

BoneRuleTree shoulderPart2Rule(const GrammarParams& p) {
    return shoulderPartTree(std::min(1, p.frontRibs - 2), p.shoulder2, Attachment::Shoulder2);
}

// Schultergürtel → Schulterblatt Vorderextremität
BoneRuleTree shoulderGirdleRule(const GrammarParams&) {
    BoneRuleTree t;
    t.add(BoneSymbol::FrontLimb, t.add(BoneSymbol::Scapula, -1));
    return t;
}

// Vorderextremität → Oberarm Unterarm Hand
BoneRuleTree frontLimbRule(const GrammarParams&) {
    BoneRuleTree t;
    t.add(BoneSymbol::Hand, t.add(BoneSymbol::Forearm, t.add(BoneSymbol::UpperArm, -1)));
    return t;
}

// G″: Hals → Wirbel^{w_h − 5} Wirbel (Schultergürtel^{e_h2}) Wirbel Wirbel (Schultergürtel^{e_h})
//            Wirbel² Schädel
// written as Wirbel^{w_h − 5h} [Wirbel (SG^{e_h2}) Wirbel Wirbel (SG^{e_h}) Wirbel²]^h Schädel:
// without a neck (h = 0, w_h = 0) it is G's Hals → Schädel, as "G″ behaves like G′ when
// e_h = e_h2 = 0" requires (the literal rule would make 5 vertebrae out of none).
BoneRuleTree neckRule(const GrammarParams& p) {
    constexpr SpineSection kNeck = SpineSection::Neck;
    BoneRuleTree t;
    int last = t.chain(BoneSymbol::Vertebra, p.neckVertebrae - 5 * p.neck, -1, false, kNeck);
    if (p.neck == 1) {
        last = t.chain(BoneSymbol::Vertebra, 1, last, false, kNeck);
        const int second = t.add(BoneSymbol::ShoulderGirdle, last, true, p.neckShoulder2 == 1);
        t.nodes[second].attachment = Attachment::Neck2;
        last = t.chain(BoneSymbol::Vertebra, 2, last, false, kNeck);
        const int first = t.add(BoneSymbol::ShoulderGirdle, last, true, p.neckShoulder == 1);
        t.nodes[first].attachment = Attachment::Neck;
        last = t.chain(BoneSymbol::Vertebra, 2, last, false, kNeck);
    }
    t.add(BoneSymbol::Skull, last);
    return t;
}

// Hinterteil → [Wirbel (Rippe)]^{w_rh^r} Wirbel^{w_rh − w_rh^r} (Beckengürtel) Wirbel^{w_s}
BoneRuleTree rearPartRule(const GrammarParams& p) {
    BoneRuleTree t;
    int last = ribbedChain(t, p.rearRibs, -1, SpineSection::RearBack);
    last = t.chain(BoneSymbol::Vertebra, p.rearBackVertebrae - p.rearRibs, last, false,
                   SpineSection::RearBack);
    const int girdle = t.add(BoneSymbol::PelvicGirdle, last, true);
    t.nodes[girdle].attachment = Attachment::Hip;
    t.chain(BoneSymbol::Vertebra, p.tailVertebrae, last, false, SpineSection::Tail);
    return t;
}

// G′: Beckengürtel → [Beckenknochen Hinterextremität]^{e_b − e_b2}
//                    [Beckenknochen2 (Hinterextremität) Hinterextremität]^{e_b2}
// The bracketed limb of the double pelvis is the second pair (Hip2).
BoneRuleTree pelvicGirdleRule(const GrammarParams& p) {
    BoneRuleTree t;
    const int single = t.add(BoneSymbol::Pelvis, -1, false, p.hip - p.hip2 > 0);
    t.add(BoneSymbol::HindLimb, single);
    const int twin = t.add(BoneSymbol::Pelvis2, -1, false, p.hip2 == 1);
    const int second = t.add(BoneSymbol::HindLimb, twin, true);
    t.nodes[second].attachment = Attachment::Hip2;
    t.add(BoneSymbol::HindLimb, twin, false);
    return t;
}

// Hinterextremität → Oberschenkel Unterschenkel Fuß
BoneRuleTree hindLimbRule(const GrammarParams&) {
    BoneRuleTree t;
    t.add(BoneSymbol::Foot, t.add(BoneSymbol::Shank, t.add(BoneSymbol::Thigh, -1)));
    return t;
}

BoneRuleDictionary makeDefaultRules() {
    BoneRuleDictionary d;
    d[BoneSymbol::Skeleton].push_back({skeletonRule});
    d[BoneSymbol::FrontPart].push_back({frontPartRule});
    d[BoneSymbol::RearPart].push_back({rearPartRule});
    d[BoneSymbol::ShoulderPart].push_back({shoulderPartRule});
    d[BoneSymbol::ShoulderPart2].push_back({shoulderPart2Rule});
    d[BoneSymbol::ShoulderGirdle].push_back({shoulderGirdleRule});
    d[BoneSymbol::PelvicGirdle].push_back({pelvicGirdleRule});
    d[BoneSymbol::Neck].push_back({neckRule});
    d[BoneSymbol::FrontLimb].push_back({frontLimbRule});
    d[BoneSymbol::HindLimb].push_back({hindLimbRule});
    return d;
}

}  // namespace

const BoneRuleDictionary& defaultBoneRules() {
    static const BoneRuleDictionary rules = makeDefaultRules();
    return rules;
}

}  // namespace ramus::detail
