// The internal stages of buildSkeleton (seed 000 §5.1 steps 3–4), in the order they run:
//   makeSpine → placeBones (grammar G″ + positions) → poseLimbs (limb poses, ground, legs)
//   → mirrorSkeleton.
// Each stage is a pure function of its inputs; see include/ramus/skeleton.hpp for the frames.
#pragma once

#include <array>
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
/// Arc length of one spine Bézier between parameters t0 ≤ t1.
double spineLength(const Spine& spine, SpinePart part, double t0 = 0.0, double t1 = 1.0);

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

/// Derives the grammar (its rule dictionary may hold several rules per nonterminal; `design`'s
/// grammarSeed picks among them) and positions every terminal: the root, vertebrae, ribs,
/// skull, girdles and the limb bones with their lengths, all on the center and left side.
/// Limb joints get their positions (at the parent's distal end) and rest = identity with no
/// degrees of freedom yet; poseLimbs sets those. Girdle bones (scapula, pelvis) are turned only
/// about z (they stay in a plane parallel to the mid-plane), at z > 0.
Skeleton placeBones(const SkeletonDesign& design, const Spine& spine);

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
