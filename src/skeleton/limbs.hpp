// Internal pieces of the limb stage (poseLimbs, skeleton_build.hpp): the limb chains of a placed
// skeleton, the ground height rule and the iterative leg placement (seed 000 §5.5–5.5.2, §7.5).
//
// Angles of the limb joints (all in degrees, left side, internal frame of skeleton.hpp):
// placeBones turns girdles only about z, so every limb frame's z is world +z. The side-view
// angle of a bone is φ = the angle of its x axis from straight down, positive towards +x (the
// tail): direction (sin φ, −cos φ, 0). A "side" swing about the joint's z axis adds to φ. The
// upper joint (shoulder/hip) has two degrees of freedom, applied as rest · R(dofs[0]) ·
// R(dofs[1]):
//   dofs[0] "front": axis −y; positive angles spread the limb away from the body, towards +z
//                    (seed 000 §5.5.2's "seitlich abspreizen").
//   dofs[1] "side":  axis +z of the spread frame; positive angles swing the limb's tip
//                    backwards (towards the parent's +y).
// Elbow/knee and wrist/ankle have one "side" degree of freedom about +z.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "ramus/skeleton.hpp"

namespace ramus::detail {

/// A limb of the grammar's side: its girdle bone and the three limb bones (upper arm/thigh,
/// forearm/shank, hand/foot), indices into Skeleton::bones.
struct LimbChain {
    int girdle = -1;
    std::array<int, 3> bones{-1, -1, -1};
    LimbKind kind = LimbKind::None;
    Attachment attachment = Attachment::Hip;
    bool front = false;  ///< a front limb (on a scapula): upper arm, forearm, hand
};

/// Every complete Left limb chain (an UpperArm or Thigh whose parent is a girdle bone, with a
/// Forearm/Shank child that has a Hand/Foot child), in bone order. Chains with a missing bone
/// or LimbKind::None are skipped. An empty skeleton gives none.
std::vector<LimbChain> findLimbChains(const Skeleton& skeleton);

/// Side-view angle φ (degrees, see the file comment) of a frame's x axis, from its world
/// transform: atan2(x.x, −x.y) ∈ (−180, 180].
double sideViewAngle(const Mat4& world);

/// Lowest world y over the boxes of the bones (box corners, skeleton.hpp's centred boxes);
/// +infinity for an empty list. `world` are the bones' world transforms.
double lowestBonePoint(std::span<const Bone> bones, std::span<const Mat4> world);
/// Lowest world y of one bone's box under the world transform `world`.
double lowestBoxPoint(const Mat4& world, const Vec3& extents);

// ---- ground height (ground_height.cpp) -------------------------------------------------------

/// What the ground rule needs of one leg.
struct LegReach {
    double jointHeight = 0.0;  ///< world y of the shoulder/hip joint (the girdle's distal end), px
    double length = 0.0;       ///< upper + middle + foot bone lengths, px, ≥ 0
    double footLength = 0.0;   ///< length of the foot (or hand) bone, px, ≥ 0
    bool front = false;        ///< a front leg (on a scapula)
};

/// Result of the ground rule.
struct GroundHeight {
    double height = 0.0;           ///< y of the ground plane, px
    double heelProbability = 0.0;  ///< in [0, 1]
    bool raised = false;           ///< the ground was raised above 0 because the legs are short
};

/// The fraction of each leg's length the ground rule uses, so that standing legs stay bent
/// (seed 000 §5.5.1, footnote 2).
inline constexpr double kGroundLegFraction = 0.8;

/// The ground height of seed 000 §5.5.1. The ground starts at y = 0 (the bottom of the annotated
/// images, §7.4.1) and is raised just enough that every leg reaches it with 0.8 of its length:
/// height = max(0, maxᵢ(jointHeightᵢ − 0.8·lengthᵢ)) (the lowest height every leg reaches;
/// "the shortest leg, stretched" of §5.5.1 with the 0.8 factor). Heel/wrist probability: 0 when
/// the ground was raised; otherwise, per leg, (length − jointHeight) / footLength clamped to
/// [0, 1] (1 when the heel already reaches y = 0), averaged over the front legs and over the
/// hind legs, and the mean of those two averages (of the one present). A zero foot length gives
/// 1 when the leg reaches y = 0, else 0. With no legs the ground is `lowestPoint` (the skeleton
/// rests on it; probability 0).
GroundHeight computeGroundHeight(std::span<const LegReach> legs, double lowestPoint);

// ---- leg placement (leg_placement.cpp) -------------------------------------------------------

/// Settings of the iterative leg placement (seed 000 §5.5.2; the thesis's numbers).
struct LegPlacementParams {
    double startStepDeg = 40.0;     ///< first turn per joint and iteration
    double stepFactor = 6.0 / 7.0;  ///< step shrink per iteration
    int maxIterations = 200;        ///< iteration cap
    double tolerance = 1e-3;        ///< stop when the contact point is within this · leg length
    double belowTolerance = 1e-9;   ///< how far (· leg length) a box may dip below the ground
    double rescueGridDeg = 10.0;    ///< grid spacing of the rescue start (see placeLeg)
};

/// What happened to one leg.
struct LegPlacementResult {
    int iterations = 0;         ///< iterations run (0 for the straight-down fallbacks)
    bool straightDown = false;  ///< a §7.5 fallback: the leg points straight down
    bool rescued = false;       ///< the grid-searched start was used (see placeLeg)
    bool heelContact = false;   ///< the leg stands on its heel/wrist (else on its toe tip)
    double contactGap = 0.0;    ///< contact point height above the ground at the end, px
};

/// Sets the three side angles of a Left leg chain whose joints poseLimbs has set up (limits)
/// so that its contact point rests on the ground: the lowest corner of the foot's distal end (toe
/// tip) or, with `heelContact`, of the heel region (the foot's proximal end and the middle bone's
/// distal end); a leg whose heel cannot reach the ground (joint height − upper − middle length
/// above it) stands on its toe tip instead. Iterative (seed 000 §5.5.2 with the §7.5 fixes):
/// start fully folded; in each iteration turn each joint by ±step so that the contact point gets
/// lower (the ankle under heel contact, which cannot move the heel, turns the foot towards lying
/// flat instead); a turn is not taken if it puts a box corner below the ground, turns a bone past
/// the vertical (|φ| > 180°) or the instep below the sole (the foot pointing backwards, φ > 0);
/// shrink the step by 6/7, or halve it when most turns of the iteration were refused (§7.5
/// point 2). Stops at the tolerance or after maxIterations. Beyond the thesis: each joint may
/// also turn together with the opposite turn of the next joint, and when the folded start lies
/// below the ground or the iteration ends above the tolerance, the valid pose with the lowest
/// contact point on a rescueGridDeg grid is the start of a second run (the better result is
/// kept). A leg that cannot reach the ground points straight down, stretched; a reachable leg
/// without any valid pose points straight down with its foot flat (§7.5). Also sets the foot
/// bone's `hoof` (foot steeper than 45° to the ground). `girdleWorld` is the girdle's world
/// transform. Deterministic.
LegPlacementResult placeLeg(Skeleton& skeleton, const LimbChain& chain, const Mat4& girdleWorld,
                            double groundHeight, bool heelContact,
                            const LegPlacementParams& params = {});

}  // namespace ramus::detail

// ---- the body against the ground (body_ground.cpp) -------------------------------------------

namespace ramus::detail {

/// Shortens every Left rib whose box would dip below `groundHeight` so that its lowest corner
/// rests on it (rib lengths are a free choice of the placement, seed 000 §5.4; the ground is
/// not). A rib whose root already lies below keeps a length of 1 px. `world` are the current
/// world transforms (ribs are leaves, so they stay valid).
void fitRibsAboveGround(Skeleton& skeleton, std::span<const Mat4> world, double groundHeight);

/// Lowest world y over all bones except the limb bones of legs (girdles count as body).
/// +infinity when there are none.
double lowestBodyPoint(const Skeleton& skeleton, std::span<const Mat4> world,
                       std::span<const LimbChain> chains);

/// Scales the three bones of a leg chain along their length (extents.x and the joint positions
/// that sit at a parent's distal end) by `factor` ≥ 1.
void lengthenLeg(Skeleton& skeleton, const LimbChain& chain, double factor);

}  // namespace ramus::detail
