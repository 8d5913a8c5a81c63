// The bone grammar G″: its parameters and their constraints, the rule dictionary's choice by
// weight, and the derivation on a tree whose nonterminals are leaves (the productions
// themselves are in bone_rules.cpp).
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

// ---- derivation ------------------------------------------------------------------------------

using Node = BoneSymbolTree::Node;

// Reusable buffers of a derivation (no allocations per step once they have grown).
struct Scratch {
    std::vector<int> mapped;    // rule node → tree node, −1 when not inserted
    std::vector<int> topLevel;  // inserted nodes hanging on the replaced node's parent
    std::vector<int> stack;
    std::vector<int> found;
};

// Appends the nonterminals of the subtrees rooted at `roots` (siblings, in order) to `out`,
// in word order (pre-order, children in list order).
void collectNonterminals(const BoneSymbolTree& tree, const std::vector<int>& roots,
                         std::vector<int>& stack, std::vector<int>& out) {
    stack.assign(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        if (!isTerminal(tree.nodes[n].symbol)) out.push_back(n);
        const std::size_t mark = stack.size();
        for (int c = tree.nodes[n].firstChild; c >= 0; c = tree.nodes[c].nextSibling)
            stack.push_back(c);
        std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(mark), stack.end());
    }
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

// Replaces the nonterminal leaf `n` by the rule tree (seed 000 §5.4); the inserted nodes that
// hang on n's parent are left in scratch.topLevel.
void replaceNode(BoneSymbolTree& tree, int n, const BoneRuleTree& rule, Scratch& scratch) {
    const Node replaced = tree.nodes[n];
    int after = unlink(tree, n);
    tree.nodes[n].alive = false;
    scratch.mapped.assign(rule.nodes.size(), -1);
    scratch.topLevel.clear();
    for (std::size_t r = 0; r < rule.nodes.size(); ++r) {
        const BoneRuleNode& node = rule.nodes[r];
        RAMUS_ASSERT(node.parent < static_cast<int>(r));
        if (!node.present) continue;
        const auto place =
            resolveParent(rule, scratch.mapped, static_cast<int>(r), replaced.branch);
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
        scratch.mapped[r] = index;
        if (place->ruleParent < 0) {
            linkAfter(tree, replaced.parent, after, index);
            after = index;
            scratch.topLevel.push_back(index);
        } else {
            const int parent = scratch.mapped[place->ruleParent];
            linkAfter(tree, parent, tree.nodes[parent].lastChild, index);
        }
    }
}

void expand(BoneSymbolTree& tree, int n, const BoneRuleDictionary& rules,
            const GrammarParams& params, Rng& rng, Scratch& scratch) {
    replaceNode(tree, n, pickRule(rules, tree.nodes[n].symbol, rng)(params), scratch);
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
    out.nodes.reserve(tree.nodes.size());  // at least the alive nodes
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
    if (nodes.empty()) nodes.reserve(64);  // the longest default rules (back, tail) fit
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

BoneSymbolTree BoneSymbolTree::start() {
    BoneSymbolTree tree;
    tree.nodes.push_back(Node{});
    tree.root = 0;
    return tree;
}

bool deriveBoneStep(BoneSymbolTree& tree, const BoneRuleDictionary& rules,
                    const GrammarParams& params, Rng& rng) {
    Scratch scratch;
    if (tree.root >= 0) collectNonterminals(tree, {tree.root}, scratch.stack, scratch.found);
    if (scratch.found.empty()) return false;
    expand(tree, scratch.found.front(), rules, params, rng, scratch);
    return true;
}

BoneSymbolTree deriveBoneTree(const GrammarParams& params, const BoneRuleDictionary& rules,
                              Rng& rng) {
    checkGrammarParams(params);
    BoneSymbolTree tree = BoneSymbolTree::start();
    tree.nodes.reserve(256);
    Scratch scratch;  // room for the default rules' trees, so that the buffers rarely grow
    for (std::vector<int>* buffer :
         {&scratch.mapped, &scratch.topLevel, &scratch.stack, &scratch.found})
        buffer->reserve(64);
    // The pending nonterminals in word order, reversed: the top is the leftmost. Replacing it
    // puts its rule's nonterminals where it stood, before all the others.
    std::vector<int> pending{tree.root};
    pending.reserve(64);
    int steps = 0;
    while (!pending.empty()) {
        if (++steps > kMaxDerivationSteps) {
            throw Error("bone grammar: the derivation did not end after " +
                        std::to_string(kMaxDerivationSteps) + " steps (recursive rules?)");
        }
        const int n = pending.back();
        pending.pop_back();
        expand(tree, n, rules, params, rng, scratch);
        scratch.found.clear();
        collectNonterminals(tree, scratch.topLevel, scratch.stack, scratch.found);
        pending.insert(pending.end(), scratch.found.rbegin(), scratch.found.rend());
    }
    return compacted(tree);
}

std::string boneWord(const BoneSymbolTree& tree) {
    std::string out;
    out.reserve(12 * tree.nodes.size());  // names average ~9 characters with spaces and brackets
    if (tree.root >= 0) writeWord(tree, tree.root, out);
    return out;
}

}  // namespace ramus::detail
