// The internal stages of buildSkeleton (seed 000 §5.1 steps 3–4), in the order they run:
//   makeSpine → placeBones (grammar G″ + positions) → poseLimbs (limb poses, ground, legs)
//   → mirrorSkeleton.
// Each stage is a pure function of its inputs; see include/ramus/skeleton.hpp for the frames.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/skeleton.hpp"

namespace ramus::detail {

// ---- spine (spine.cpp) -------------------------------------------------------------------------

/// The three spine Béziers neck (P0..P3, head → shoulder), back (P3..P6, shoulder → hip) and
/// tail (P6..P9, hip → tip), in px, after the C1 fix at the shoulder and the hip (seed 000
/// §7.4.2).
struct Spine {
    std::array<Vec2, kSpinePointCount> points{};
    bool hasNeck = false;  ///< the neck is long enough to carry vertebrae
    bool hasTail = false;  ///< the tail is long enough to carry vertebrae
};
enum class SpinePart { Neck = 0, Back = 1, Tail = 2 };

/// The spine of a feature set with the C1 fix applied where the curves meet at an angle.
Spine makeSpine(const SkeletonFeatures& features);
/// Point of one spine Bézier at parameter t ∈ [0, 1].
Vec2 spinePoint(const Spine& spine, SpinePart part, double t);
/// Arc length of one spine Bézier between parameters t0 ≤ t1 (adaptive Gauss–Kronrod,
/// relative error ≤ ~1e-10). t0 > t1 gives the negative length.
double spineLength(const Spine& spine, SpinePart part, double t0 = 0.0, double t1 = 1.0);

/// A neck or tail carries vertebrae only when its arc length is at least this fraction of the
/// back's arc length (and at least kMinSpinePartPx): shorter parts are the noise a sampled
/// feature point leaves where the species has no neck or tail. 0.05 of the back is about one
/// back vertebra (25 on the back) — the blue whale's short neck (0.07) still counts.
inline constexpr double kMinSpinePartFraction = 0.05;
inline constexpr double kMinSpinePartPx = 2.0;

/// Derivative dB/dt of one spine Bézier at t ∈ [0, 1] (px per unit parameter).
Vec2 spineDerivative(const Spine& spine, SpinePart part, double t);
/// The parameter t ≥ t0 where the arc length from t0 reaches `length` px (Newton's method on
/// the arc length, safeguarded by bisection). Clamped to 1 when the rest of the curve is
/// shorter; t0 for length ≤ 0.
double spineParameterAtLength(const Spine& spine, SpinePart part, double t0, double length);
/// The n + 1 parameters of the sample points that split one spine Bézier between `from` and
/// `to` (either order; the first is `from`, the last `to`, exactly) into n ≥ 1 pieces: of equal
/// arc length (ArcLength) or of equal parameter steps t = from + (to − from)·i/n (Parameter,
/// seed 000 §5.3). A part of zero length falls back to equal parameter steps.
std::vector<double> spineSamples(const Spine& spine, SpinePart part, double from, double to, int n,
                                 SpineSpacing spacing);
/// Parameter of the root bone on the back (seed 000 §5.2): 0.5 (Parameter, the thesis) or the
/// point at half the back's arc length (ArcLength).
double spineRootParameter(const Spine& spine, SpineSpacing spacing);

// ---- grammar and placement (bone_grammar.cpp, bone_placement.cpp) ----------------------------

/// The parameters p″ of the grammar G″ (seed 000 §5.4, §5.5.3), derived from a design.
struct GrammarParams {
    int frontBackVertebrae = 13;  ///< w_rv ≥ 3
    int frontRibs = 0;            ///< w_rv^r ≤ w_rv
    int rearBackVertebrae = 12;   ///< w_rh ≥ 1
    int rearRibs = 0;             ///< w_rh^r ≤ w_rh
    int neck = 1;                 ///< h ∈ {0, 1}
    int tail = 0;                 ///< s ∈ {0, 1}
    int neckVertebrae = 7;        ///< w_h: h = 1 ⇒ ≥ 7, h = 0 ⇒ 0
    int tailVertebrae = 0;        ///< w_s: s = 0 ⇒ 0
    int shoulder = 0;             ///< e_s ∈ {0, 1}
    int hip = 0;                  ///< e_b ∈ {0, 1}
    int shoulder2 = 0;            ///< e_s2 ∈ {0, 1}, e_s = 0 ⇒ 0
    int hip2 = 0;                 ///< e_b2 ∈ {0, 1}, e_b = 0 ⇒ 0
    int neckShoulder = 0;         ///< e_h ∈ {0, 1}, needs a neck
    int neckShoulder2 = 0;        ///< e_h2 ∈ {0, 1}, e_h = 0 ⇒ 0
};
/// The grammar parameters of a design on its spine. Throws Error when a constraint of seed 000
/// §5.4/§5.5.3 does not hold (e.g. a neck girdle without a neck).
GrammarParams grammarParams(const SkeletonDesign& design, const Spine& spine);
/// Throws Error naming the parameter and the rule when `params` break a constraint of seed 000
/// §5.4/§5.5.3 (w_rv ≥ 3, w_rh ≥ 1, 0 ≤ w_rv^r ≤ w_rv, 0 ≤ w_rh^r ≤ w_rh, flags in {0, 1},
/// h = 1 ⇔ w_h ≥ 7 and h = 0 ⇔ w_h = 0, s = 0 ⇔ w_s = 0, e_s2 ⇒ e_s, e_b2 ⇒ e_b, e_h ⇒ h,
/// e_h2 ⇒ e_h).
void checkGrammarParams(const GrammarParams& params);

/// The symbols of the grammar G″ (seed 000 §5.4, §5.5.3): the terminals (BoneKind order, then
/// Beckenknochen2) and the nonterminals.
enum class BoneSymbol : std::uint8_t {
    Root,
    Vertebra,
    Rib,
    Skull,
    Scapula,
    UpperArm,
    Forearm,
    Hand,
    Pelvis,
    Thigh,
    Shank,
    Foot,
    Pelvis2,         ///< Beckenknochen2: a pelvis with two hip joints (G′)
    Skeleton,        ///< Skelett (the start symbol)
    FrontPart,       ///< Vorderteil
    RearPart,        ///< Hinterteil
    ShoulderPart,    ///< Schulterpartie
    ShoulderPart2,   ///< Schulterpartie2 (G′)
    ShoulderGirdle,  ///< Schultergürtel
    PelvicGirdle,    ///< Beckengürtel
    Neck,            ///< Hals
    FrontLimb,       ///< Vorderextremität
    HindLimb,        ///< Hinterextremität
};
inline constexpr int kBoneSymbolCount = 23;
inline constexpr int kFirstNonterminal = static_cast<int>(BoneSymbol::Skeleton);
inline constexpr int kNonterminalCount = kBoneSymbolCount - kFirstNonterminal;
bool isTerminal(BoneSymbol symbol);
/// Terminals: boneKindName, "pelvis2" for Pelvis2; nonterminals in UpperCamelCase ("Skeleton",
/// "FrontPart", …, "HindLimb").
std::string_view boneSymbolName(BoneSymbol symbol);
/// The bone kind of a terminal (Pelvis2 → Pelvis). `symbol` must be a terminal.
BoneKind boneSymbolKind(BoneSymbol symbol);

/// Which run of vertebrae a vertebra belongs to (the back split at the root).
enum class SpineSection : std::uint8_t { None, Neck, FrontBack, RearBack, Tail };

/// One node of a rule's tree B_v (seed 000 §5.4 "Darstellung als Baum").
struct BoneRuleNode {
    BoneSymbol symbol = BoneSymbol::Root;
    /// Index of the parent within the rule tree (smaller than this node's), or −1: the node
    /// hangs on the parent of the nonterminal being replaced.
    int parent = -1;
    /// Written in brackets after its parent ("A ( B )") instead of following it ("A B"). A node
    /// with parent −1 takes the replaced nonterminal's bracket instead.
    bool branch = false;
    /// False for A^0: the node is not inserted. Its descendants are not inserted either (their
    /// parent is absent), except a node with `fallback`.
    bool present = true;
    /// When the parent is absent, hang on the nearest present ancestor instead (the shoulder
    /// girdle: on the shoulder rib, or on the shoulder vertebra when there is no rib).
    bool fallback = false;
    SpineSection section = SpineSection::None;  ///< vertebrae: None = the replaced node's
    /// Girdles and limbs: the attachment they serve; empty = the replaced node's.
    std::optional<Attachment> attachment;
};

/// The tree a rule replaces a nonterminal with; nodes are listed parents first.
struct BoneRuleTree {
    std::vector<BoneRuleNode> nodes;

    /// Appends a node and returns its index.
    int add(BoneSymbol symbol, int parent, bool branch = false, bool present = true);
    /// Appends `count` copies of `symbol` (count ≤ 0: none), each following the previous, the
    /// first hanging on `parent` (with `branch`); returns the last one, or `parent` for none,
    /// so that A^0 B reads as B (seed 000 §5.4: A^x is x copies in a row).
    int chain(BoneSymbol symbol, int count, int parent, bool branch = false,
              SpineSection section = SpineSection::None);
};

/// A rule: expands a nonterminal into a tree, given the grammar parameters.
using BoneRule = std::function<BoneRuleTree(const GrammarParams&)>;
struct WeightedBoneRule {
    BoneRule expand;
    double weight = 1.0;  ///< relative probability of being picked, ≥ 0
};
/// The rules of every nonterminal (seed 000 §5.4: "aus mehreren passenden Produktionen [wird]
/// zufällig eine ausgewählt").
struct BoneRuleDictionary {
    std::array<std::vector<WeightedBoneRule>, kNonterminalCount> rules;

    std::vector<WeightedBoneRule>& operator[](BoneSymbol nonterminal);
    const std::vector<WeightedBoneRule>& operator[](BoneSymbol nonterminal) const;
};
/// G″ as SPEC §F lists it: one rule per nonterminal (G's rules with G′'s Vorderteil,
/// Schulterpartie2 and Beckengürtel and G″'s Hals). Behaves like G when e_s2 = e_b2 = 0 and
/// like G′ when e_h = e_h2 = 0.
const BoneRuleDictionary& defaultBoneRules();

/// The derivation tree: terminals and nonterminals, nonterminals always leaves.
struct BoneSymbolTree {
    struct Node {
        BoneSymbol symbol = BoneSymbol::Skeleton;
        int parent = -1;  ///< −1 for the root
        bool branch = false;
        SpineSection section = SpineSection::None;
        std::optional<Attachment> attachment;
        int firstChild = -1;  ///< children in word order, linked through nextSibling
        int lastChild = -1;
        int nextSibling = -1;
        bool alive = true;  ///< false once replaced (derivation steps leave holes)
    };
    std::vector<Node> nodes;
    int root = -1;

    /// The tree of the start symbol alone.
    static BoneSymbolTree start();
};
/// One derivation step: replaces the first nonterminal in word order by the tree of a rule
/// drawn from the dictionary (by weight; no draw when there is a single rule) and returns true;
/// false when only terminals are left. Throws Error when a nonterminal has no rule.
bool deriveBoneStep(BoneSymbolTree& tree, const BoneRuleDictionary& rules,
                    const GrammarParams& params, Rng& rng);
/// Derives from the start symbol until only terminals are left (checkGrammarParams first) and
/// returns the terminal tree compacted: alive nodes only, in word order (parents before
/// children), nodes[0] the root.
BoneSymbolTree deriveBoneTree(const GrammarParams& params, const BoneRuleDictionary& rules,
                              Rng& rng);
/// The bracketed word of a tree (Skeleton::word format; nonterminals by boneSymbolName):
/// symbols separated by single spaces, each branch child in "( … )".
std::string boneWord(const BoneSymbolTree& tree);

/// Derives the grammar (its rule dictionary may hold several rules per nonterminal; `design`'s
/// grammarSeed picks among them) and positions every terminal: the root, vertebrae, ribs,
/// skull, girdles and the limb bones with their lengths, all on the center and left side.
/// Limb joints get their positions (at the parent's distal end) and rest = identity with no
/// degrees of freedom yet; poseLimbs sets those. Girdle bones (scapula, pelvis) are turned only
/// about z (they stay in a plane parallel to the mid-plane), at z > 0.
Skeleton placeBones(const SkeletonDesign& design, const Spine& spine);
/// placeBones with another rule dictionary (a custom one may leave out or add bones; every
/// terminal is placed by its kind).
Skeleton placeBones(const SkeletonDesign& design, const Spine& spine,
                    const BoneRuleDictionary& rules);

// ---- limbs (limb_pose.cpp, leg_placement.cpp) ------------------------------------------------

/// Gives every limb its joints (degrees of freedom and limits, SPEC §F table) and pose: fins
/// straight back, arms down with a 90° elbow, wings from design.wingAngles, legs by the
/// ground-height rule (§5.5.1) and the iterative placement (§5.5.2 with the §7.5 fixes). Sets
/// groundHeight, heelProbability and heelContact (design.heelDraw < heelProbability).
void poseLimbs(Skeleton& skeleton, const SkeletonDesign& design);

// ---- mirror (mirror.cpp) ----------------------------------------------------------------------

/// Appends the right twin of every Left bone (seed 000 §5.1 step 4, §7.3): mirrored across the
/// xy-plane into a right-handed frame (det +1), joint axes and limits carried over, `twin`
/// linked both ways. Parents still come before children.
void mirrorSkeleton(Skeleton& skeleton);

}  // namespace ramus::detail
