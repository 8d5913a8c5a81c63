// The bone grammar G″: its parameters and their constraints, the rule dictionary, and the
// derivation on a tree whose nonterminals are leaves.
//
// Based on: seed 000 §5.4 (G, its parameters and productions; "Darstellung als Baum": a
// nonterminal is replaced by the tree B_v of a rule, whose root hangs on the nonterminal's
// parent; a node whose parent is absent is not inserted, except the shoulder girdle, which
// hangs on the shoulder rib or, without it, on the shoulder vertebra; several rules per
// nonterminal, one picked at random), §5.5.3 (G′: Vorderteil, Schulterpartie2, Beckengürtel;
// G″: Hals); SPEC §F.
#include <algorithm>
#include <string>

#include "ramus/error.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

constexpr std::array<std::string_view, kBoneSymbolCount> kSymbolNames = {
    "root",           "vertebra",     "rib",       "skull",     "scapula",      "upper_arm",
    "forearm",        "hand",         "pelvis",    "thigh",     "shank",        "foot",
    "pelvis2",        "Skeleton",     "FrontPart", "RearPart",  "ShoulderPart", "ShoulderPart2",
    "ShoulderGirdle", "PelvicGirdle", "Neck",      "FrontLimb", "HindLimb"};

constexpr int kMaxDerivationSteps = 100000;

int positive(int x) { return x > 0 ? x : 0; }

[[noreturn]] void fail(const std::string& what) { throw Error("grammar parameters: " + what); }

void requireFlag(int value, const char* name) {
    if (value != 0 && value != 1) {
        fail(std::string(name) + " = " + std::to_string(value) + " breaks the rule " + name +
             " ∈ {0, 1} (seed 000 §5.4, §5.5.3)");
    }
}

void requireImplies(int premise, int conclusion, const char* premiseName,
                    const char* conclusionName) {
    if (premise == 1 && conclusion != 1) {
        fail(std::string(premiseName) + " = 1 needs " + conclusionName +
             " = 1 (seed 000 §5.5.3: " + conclusionName + " = 0 ⇒ " + premiseName + " = 0)");
    }
}

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

// ---- derivation ------------------------------------------------------------------------------

using Node = BoneSymbolTree::Node;

// The first nonterminal in word order (pre-order, children in list order); −1 when none.
int firstNonterminal(const BoneSymbolTree& tree) {
    std::vector<int> stack;
    if (tree.root >= 0) stack.push_back(tree.root);
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        if (!isTerminal(tree.nodes[n].symbol)) return n;
        const std::size_t mark = stack.size();
        for (int c = tree.nodes[n].firstChild; c >= 0; c = tree.nodes[c].nextSibling)
            stack.push_back(c);
        std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(mark), stack.end());
    }
    return -1;
}

const BoneRule& pickRule(const BoneRuleDictionary& rules, BoneSymbol symbol, Rng& rng) {
    const std::vector<WeightedBoneRule>& choices = rules[symbol];
    if (choices.empty()) {
        throw Error("bone grammar: no rule for the nonterminal " +
                    std::string(boneSymbolName(symbol)));
    }
    if (choices.size() == 1) return choices[0].expand;
    double total = 0.0;
    for (const WeightedBoneRule& rule : choices) total += std::max(0.0, rule.weight);
    if (!(total > 0.0)) {
        throw Error("bone grammar: the rules for " + std::string(boneSymbolName(symbol)) +
                    " have no positive weight");
    }
    const double draw = rng.uniform01() * total;
    double sum = 0.0;
    for (const WeightedBoneRule& rule : choices) {
        sum += std::max(0.0, rule.weight);
        if (draw < sum) return rule.expand;
    }
    for (auto it = choices.rbegin(); it != choices.rend(); ++it)
        if (it->weight > 0.0) return it->expand;
    return choices.back().expand;
}

// Links `child` into `parent`'s children right after `after` (−1: at the front).
void linkAfter(BoneSymbolTree& tree, int parent, int after, int child) {
    Node& c = tree.nodes[child];
    c.parent = parent;
    if (parent < 0) {
        if (tree.root >= 0) throw Error("bone grammar: a rule gives the skeleton a second root");
        tree.root = child;
        return;
    }
    Node& p = tree.nodes[parent];
    int& slot = after < 0 ? p.firstChild : tree.nodes[after].nextSibling;
    c.nextSibling = slot;
    slot = child;
    if (c.nextSibling < 0) p.lastChild = child;
}

// Removes the leaf `n` from its parent's children; returns its predecessor (−1: none).
int unlink(BoneSymbolTree& tree, int n) {
    const int parent = tree.nodes[n].parent;
    if (parent < 0) {
        tree.root = -1;
        return -1;
    }
    Node& p = tree.nodes[parent];
    int before = -1;
    for (int c = p.firstChild; c != n; c = tree.nodes[c].nextSibling) before = c;
    (before < 0 ? p.firstChild : tree.nodes[before].nextSibling) = tree.nodes[n].nextSibling;
    if (p.lastChild == n) p.lastChild = before;
    tree.nodes[n].nextSibling = -1;
    return before;
}

// Where a rule node goes: its parent in the tree (−1 = the replaced node's parent) and its
// bracket, or nullopt when it is not inserted (absent, or its parent is absent).
struct Placement {
    int ruleParent = -1;
    bool branch = false;
};

std::optional<Placement> resolveParent(const BoneRuleTree& rule, const std::vector<int>& mapped,
                                       int r, bool replacedBranch) {
    const BoneRuleNode& node = rule.nodes[r];
    Placement place{node.parent, node.branch};
    while (place.ruleParent >= 0 && mapped[place.ruleParent] < 0) {
        if (!node.fallback) return std::nullopt;
        place.branch = rule.nodes[place.ruleParent].branch;
        place.ruleParent = rule.nodes[place.ruleParent].parent;
    }
    // Hanging on the replaced node's parent, the node takes the replaced node's bracket.
    if (place.ruleParent < 0) place.branch = replacedBranch;
    return place;
}

// Replaces the nonterminal leaf `n` by the rule tree (seed 000 §5.4).
void replaceNode(BoneSymbolTree& tree, int n, const BoneRuleTree& rule) {
    const Node replaced = tree.nodes[n];
    int after = unlink(tree, n);
    tree.nodes[n].alive = false;
    std::vector<int> mapped(rule.nodes.size(), -1);
    for (std::size_t r = 0; r < rule.nodes.size(); ++r) {
        const BoneRuleNode& node = rule.nodes[r];
        RAMUS_ASSERT(node.parent < static_cast<int>(r));
        if (!node.present) continue;
        const auto place = resolveParent(rule, mapped, static_cast<int>(r), replaced.branch);
        if (!place) continue;
        if (place->ruleParent >= 0 && !isTerminal(rule.nodes[place->ruleParent].symbol)) {
            throw Error("bone grammar: a rule gives the nonterminal " +
                        std::string(boneSymbolName(rule.nodes[place->ruleParent].symbol)) +
                        " a child; nonterminals must be leaves");
        }
        Node added;
        added.symbol = node.symbol;
        added.branch = place->branch;
        added.section = node.section != SpineSection::None ? node.section : replaced.section;
        added.attachment = node.attachment ? node.attachment : replaced.attachment;
        const int index = static_cast<int>(tree.nodes.size());
        tree.nodes.push_back(added);
        mapped[r] = index;
        if (place->ruleParent < 0) {
            linkAfter(tree, replaced.parent, after, index);
            after = index;
        } else {
            const int parent = mapped[place->ruleParent];
            linkAfter(tree, parent, tree.nodes[parent].lastChild, index);
        }
    }
}

void writeWord(const BoneSymbolTree& tree, int n, std::string& out) {
    if (!out.empty()) out += ' ';
    out += boneSymbolName(tree.nodes[n].symbol);
    for (int c = tree.nodes[n].firstChild; c >= 0; c = tree.nodes[c].nextSibling) {
        const bool bracket = tree.nodes[c].branch || tree.nodes[c].nextSibling >= 0;
        if (bracket) out += " (";
        writeWord(tree, c, out);
        if (bracket) out += " )";
    }
}

// Alive nodes in word order, indices remapped.
BoneSymbolTree compacted(const BoneSymbolTree& tree) {
    BoneSymbolTree out;
    if (tree.root < 0) return out;
    std::vector<int> stack{tree.root};
    std::vector<int> newIndex(tree.nodes.size(), -1);
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        newIndex[n] = static_cast<int>(out.nodes.size());
        Node node = tree.nodes[n];
        node.parent = node.parent < 0 ? -1 : newIndex[node.parent];
        node.firstChild = node.lastChild = node.nextSibling = -1;
        out.nodes.push_back(node);
        if (node.parent >= 0)
            linkAfter(out, node.parent, out.nodes[node.parent].lastChild, newIndex[n]);
        const std::size_t mark = stack.size();
        for (int c = tree.nodes[n].firstChild; c >= 0; c = tree.nodes[c].nextSibling)
            stack.push_back(c);
        std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(mark), stack.end());
    }
    out.root = 0;
    return out;
}

}  // namespace

bool isTerminal(BoneSymbol symbol) { return static_cast<int>(symbol) < kFirstNonterminal; }

std::string_view boneSymbolName(BoneSymbol symbol) {
    return kSymbolNames[static_cast<std::size_t>(symbol)];
}

BoneKind boneSymbolKind(BoneSymbol symbol) {
    RAMUS_ASSERT(isTerminal(symbol));
    if (symbol == BoneSymbol::Pelvis2) return BoneKind::Pelvis;
    return static_cast<BoneKind>(symbol);
}

void checkGrammarParams(const GrammarParams& p) {
    auto count = [](int value, bool ok, const char* name, const char* rule) {
        if (!ok)
            fail(std::string(name) + " = " + std::to_string(value) + " breaks the rule " + rule);
    };
    count(p.frontBackVertebrae, p.frontBackVertebrae >= 3, "w_rv (front back vertebrae)",
          "w_rv ≥ 3 (seed 000 §5.4)");
    count(p.rearBackVertebrae, p.rearBackVertebrae >= 1, "w_rh (rear back vertebrae)",
          "w_rh ≥ 1 (the pelvis needs a vertebra)");
    count(p.frontRibs, p.frontRibs >= 0 && p.frontRibs <= p.frontBackVertebrae,
          "w_rv^r (front ribs)", "0 ≤ w_rv^r ≤ w_rv (seed 000 §5.4)");
    count(p.rearRibs, p.rearRibs >= 0 && p.rearRibs <= p.rearBackVertebrae, "w_rh^r (rear ribs)",
          "0 ≤ w_rh^r ≤ w_rh (seed 000 §5.4)");
    requireFlag(p.neck, "h");
    requireFlag(p.tail, "s");
    count(p.neckVertebrae, p.neck == 1 ? p.neckVertebrae >= 7 : p.neckVertebrae == 0,
          "w_h (neck vertebrae)", "h > 0 ⇒ w_h ≥ 7 and h = 0 ⇒ w_h = 0 (seed 000 §5.4)");
    count(p.tailVertebrae, p.tail == 1 ? p.tailVertebrae >= 1 : p.tailVertebrae == 0,
          "w_s (tail vertebrae)", "s = 1 ⇒ w_s ≥ 1 and s = 0 ⇒ w_s = 0 (seed 000 §5.4)");
    requireFlag(p.shoulder, "e_s");
    requireFlag(p.hip, "e_b");
    requireFlag(p.shoulder2, "e_s2");
    requireFlag(p.hip2, "e_b2");
    requireFlag(p.neckShoulder, "e_h");
    requireFlag(p.neckShoulder2, "e_h2");
    requireImplies(p.shoulder2, p.shoulder, "e_s2", "e_s");
    requireImplies(p.hip2, p.hip, "e_b2", "e_b");
    requireImplies(p.neckShoulder, p.neck, "e_h", "h");
    requireImplies(p.neckShoulder2, p.neckShoulder, "e_h2", "e_h");
}

GrammarParams grammarParams(const SkeletonDesign& design, const Spine& spine) {
    GrammarParams p;
    p.frontBackVertebrae = design.frontBackVertebrae;
    p.rearBackVertebrae = design.rearBackVertebrae;
    const int backVertebrae = design.frontBackVertebrae + design.rearBackVertebrae;
    if (design.ribs < 0 || design.ribs > backVertebrae) {
        fail("r (ribs) = " + std::to_string(design.ribs) +
             " breaks the rule 0 ≤ r ≤ w_rv + w_rh = " + std::to_string(backVertebrae) +
             " (seed 000 §5.3)");
    }
    p.frontRibs = std::min(design.ribs, std::max(design.frontBackVertebrae, 0));
    p.rearRibs = design.ribs - p.frontRibs;
    p.neckVertebrae = spine.hasNeck ? design.neckVertebrae : 0;
    p.neck = p.neckVertebrae > 0 ? 1 : 0;
    p.tailVertebrae = spine.hasTail ? design.tailVertebrae : 0;
    p.tail = p.tailVertebrae > 0 ? 1 : 0;
    for (int a = 0; a < kAttachmentCount; ++a) {
        const auto attachment = static_cast<Attachment>(a);
        if (!attachmentAccepts(attachment, design.limbs[a])) {
            fail("a " + std::string(limbKindName(design.limbs[a])) + " cannot attach at " +
                 std::string(attachmentName(attachment)) +
                 " (seed 000 §5.5.3: no legs on the neck; wings and arms only at shoulders)");
        }
    }
    auto has = [&](Attachment a) { return design.limb(a) != LimbKind::None ? 1 : 0; };
    p.shoulder = has(Attachment::Shoulder);
    p.hip = has(Attachment::Hip);
    p.shoulder2 = has(Attachment::Shoulder2);
    p.hip2 = has(Attachment::Hip2);
    p.neckShoulder = has(Attachment::Neck);
    p.neckShoulder2 = has(Attachment::Neck2);
    checkGrammarParams(p);
    return p;
}

int BoneRuleTree::add(BoneSymbol symbol, int parent, bool branch, bool present) {
    BoneRuleNode node;
    node.symbol = symbol;
    node.parent = parent;
    node.branch = branch;
    node.present = present;
    nodes.push_back(node);
    return static_cast<int>(nodes.size()) - 1;
}

int BoneRuleTree::chain(BoneSymbol symbol, int count, int parent, bool branch,
                        SpineSection section) {
    for (int i = 0; i < count; ++i) {
        parent = add(symbol, parent, i == 0 && branch);
        nodes[parent].section = section;
    }
    return parent;
}

std::vector<WeightedBoneRule>& BoneRuleDictionary::operator[](BoneSymbol nonterminal) {
    RAMUS_ASSERT(!isTerminal(nonterminal));
    return rules[static_cast<std::size_t>(static_cast<int>(nonterminal) - kFirstNonterminal)];
}

const std::vector<WeightedBoneRule>& BoneRuleDictionary::operator[](BoneSymbol nonterminal) const {
    RAMUS_ASSERT(!isTerminal(nonterminal));
    return rules[static_cast<std::size_t>(static_cast<int>(nonterminal) - kFirstNonterminal)];
}

const BoneRuleDictionary& defaultBoneRules() {
    static const BoneRuleDictionary rules = makeDefaultRules();
    return rules;
}

BoneSymbolTree BoneSymbolTree::start() {
    BoneSymbolTree tree;
    tree.nodes.push_back(Node{});
    tree.root = 0;
    return tree;
}

bool deriveBoneStep(BoneSymbolTree& tree, const BoneRuleDictionary& rules,
                    const GrammarParams& params, Rng& rng) {
    const int n = firstNonterminal(tree);
    if (n < 0) return false;
    const BoneRuleTree rule = pickRule(rules, tree.nodes[n].symbol, rng)(params);
    replaceNode(tree, n, rule);
    return true;
}

BoneSymbolTree deriveBoneTree(const GrammarParams& params, const BoneRuleDictionary& rules,
                              Rng& rng) {
    checkGrammarParams(params);
    BoneSymbolTree tree = BoneSymbolTree::start();
    int steps = 0;
    while (deriveBoneStep(tree, rules, params, rng)) {
        if (++steps > kMaxDerivationSteps) {
            throw Error("bone grammar: the derivation did not end after " +
                        std::to_string(kMaxDerivationSteps) + " steps (recursive rules?)");
        }
    }
    return compacted(tree);
}

std::string boneWord(const BoneSymbolTree& tree) {
    std::string out;
    if (tree.root >= 0) writeWord(tree, tree.root, out);
    return out;
}

}  // namespace ramus::detail
