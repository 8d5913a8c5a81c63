// Limb poses: joints, limits and angles of every limb, the ground height, and the legs.
//
// Based on: seed 000 §5.2 (joints with 0–2 degrees of freedom, all angles 0 = the parent's
// orientation), §5.5 (fins straight back along world x; arms: upper arm straight down along
// world y, a 90° elbow, the hand extending the forearm forwards; wings: each joint a random angle
// in a fixed interval), fig. 5.3 and §5.5.2 (leg joint limits: forearm, shank and foot from
// folded against their parent to its straight extension; upper arm and thigh limited relative
// to the world y axis, never past the vertical), §5.5.1 (ground height) and SPEC §F's joint
// table. Angle conventions: skeleton/limbs.hpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "skeleton/limbs.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

/// Largest bend of a leg joint from its straight extension (fig. 5.3, SPEC §F: ±170°).
constexpr double kFoldDeg = 170.0;
/// Largest sideways spread of a leg's shoulder/hip (SPEC §F: front 0…45); kept at 0 (§5.5.2).
constexpr double kLegSpreadDeg = 45.0;

// Wing intervals (SPEC §F).
constexpr double kWingFrontMin = 130.0, kWingFrontMax = 170.0;
constexpr double kWingSideMin = 0.0, kWingSideMax = 45.0;
constexpr double kWingElbowMin = -45.0, kWingElbowMax = 0.0;
constexpr double kWingWristMin = 0.0, kWingWristMax = 90.0;
/// Arm elbow (SPEC §F: fixed −90°, the forearm pointing forwards, towards −x).
constexpr double kArmElbowDeg = -90.0;

const Vec3 kFrontAxis = -Vec3::UnitY();
const Vec3 kSideAxis = Vec3::UnitZ();

JointDof makeDof(const Vec3& axis, double angle, double minDeg, double maxDeg) {
    JointDof dof;
    dof.axis = axis;
    dof.minDeg = minDeg;
    dof.maxDeg = maxDeg;
    dof.angleDeg = std::clamp(angle, minDeg, maxDeg);
    return dof;
}

/// Shoulder/hip: dofs[0] front spread (axis −y), dofs[1] side swing (axis z).
void setUpperJoint(Joint& joint, const JointDof& front, const JointDof& side) {
    joint.rest = Mat3::Identity();
    joint.dofCount = 2;
    joint.dofs = {front, side};
}

/// Elbow/knee, wrist/ankle: one side swing about z.
void setHingeJoint(Joint& joint, double angle, double minDeg, double maxDeg) {
    joint.rest = Mat3::Identity();
    joint.dofCount = 1;
    joint.dofs = {makeDof(kSideAxis, angle, minDeg, maxDeg), JointDof{}};
}

/// A locked joint angle: limits equal to the angle.
JointDof fixedDof(const Vec3& axis, double angle) { return makeDof(axis, angle, angle, angle); }

/// Fins: straight back along world +x (φ = 90°), elbow and wrist straight.
void poseFin(Skeleton& skeleton, const LimbChain& chain, double girdleAngle) {
    Bone* bone[3] = {&skeleton.bones[chain.bones[0]], &skeleton.bones[chain.bones[1]],
                     &skeleton.bones[chain.bones[2]]};
    setUpperJoint(bone[0]->joint, fixedDof(kFrontAxis, 0.0),
                  fixedDof(kSideAxis, 90.0 - girdleAngle));
    setHingeJoint(bone[1]->joint, 0.0, 0.0, 0.0);
    setHingeJoint(bone[2]->joint, 0.0, 0.0, 0.0);
}

/// Arms: upper arm along world −y (φ = 0°), elbow −90° (forearm towards the head), hand 0°.
void poseArm(Skeleton& skeleton, const LimbChain& chain, double girdleAngle) {
    setUpperJoint(skeleton.bones[chain.bones[0]].joint, fixedDof(kFrontAxis, 0.0),
                  fixedDof(kSideAxis, -girdleAngle));
    setHingeJoint(skeleton.bones[chain.bones[1]].joint, kArmElbowDeg, kArmElbowDeg, kArmElbowDeg);
    setHingeJoint(skeleton.bones[chain.bones[2]].joint, 0.0, 0.0, 0.0);
}

/// Wings: the design's angles (clamped into the wing intervals).
void poseWing(Skeleton& skeleton, const LimbChain& chain, const WingAngles& angles) {
    setUpperJoint(skeleton.bones[chain.bones[0]].joint,
                  makeDof(kFrontAxis, angles.shoulderFront, kWingFrontMin, kWingFrontMax),
                  makeDof(kSideAxis, angles.shoulderSide, kWingSideMin, kWingSideMax));
    setHingeJoint(skeleton.bones[chain.bones[1]].joint, angles.elbow, kWingElbowMin, kWingElbowMax);
    setHingeJoint(skeleton.bones[chain.bones[2]].joint, angles.wrist, kWingWristMin, kWingWristMax);
}

/// Legs: limits of fig. 5.3, every joint at its folding limit (the start of §5.5.2). Front legs
/// bend forwards at the elbow (upper arm behind the vertical, φ ∈ [0, 170]); hind legs bend
/// backwards at the knee (thigh in front of the vertical, φ ∈ [−170, 0]); hands and feet fold
/// forwards. The upper joint's world range becomes a joint range through the girdle's angle,
/// intersected with the table's ±170°.
void setUpLeg(Skeleton& skeleton, const LimbChain& chain, double girdleAngle) {
    const double g = std::clamp(girdleAngle, -kFoldDeg, kFoldDeg);
    const double worldMin = chain.front ? 0.0 : -kFoldDeg;
    const double worldMax = chain.front ? kFoldDeg : 0.0;
    const double sideMin = std::max(-kFoldDeg, worldMin - g);
    const double sideMax = std::min(kFoldDeg, worldMax - g);
    const double upperFolded = chain.front ? sideMax : sideMin;
    setUpperJoint(skeleton.bones[chain.bones[0]].joint,
                  makeDof(kFrontAxis, 0.0, 0.0, kLegSpreadDeg),
                  makeDof(kSideAxis, upperFolded, sideMin, sideMax));
    if (chain.front)
        setHingeJoint(skeleton.bones[chain.bones[1]].joint, -kFoldDeg, -kFoldDeg, 0.0);
    else
        setHingeJoint(skeleton.bones[chain.bones[1]].joint, kFoldDeg, 0.0, kFoldDeg);
    setHingeJoint(skeleton.bones[chain.bones[2]].joint, -kFoldDeg, -kFoldDeg, 0.0);
}

bool isGirdle(BoneKind kind) { return kind == BoneKind::Scapula || kind == BoneKind::Pelvis; }

/// The limb child of each bone of kind `childKind`, per parent index.
void linkChildren(const Skeleton& skeleton, BoneKind childKind, std::vector<int>& childOf) {
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {
        const Bone& bone = skeleton.bones[i];
        if (bone.kind == childKind && bone.parent >= 0 && childOf[bone.parent] < 0)
            childOf[bone.parent] = static_cast<int>(i);
    }
}

}  // namespace

std::vector<LimbChain> findLimbChains(const Skeleton& skeleton) {
    const std::size_t n = skeleton.bones.size();
    std::vector<int> middle(n, -1), distal(n, -1);
    linkChildren(skeleton, BoneKind::Forearm, middle);
    linkChildren(skeleton, BoneKind::Shank, middle);
    linkChildren(skeleton, BoneKind::Hand, distal);
    linkChildren(skeleton, BoneKind::Foot, distal);
    std::vector<LimbChain> chains;
    chains.reserve(kAttachmentCount);  // one per attachment with the default grammar
    for (std::size_t i = 0; i < n; ++i) {
        const Bone& upper = skeleton.bones[i];
        if (upper.side != Side::Left || upper.limb == LimbKind::None) continue;
        if (upper.kind != BoneKind::UpperArm && upper.kind != BoneKind::Thigh) continue;
        if (upper.parent < 0 || !isGirdle(skeleton.bones[upper.parent].kind)) continue;
        const int mid = middle[i];
        const int end = mid < 0 ? -1 : distal[mid];
        if (end < 0) continue;
        LimbChain chain;
        chain.girdle = upper.parent;
        chain.bones = {static_cast<int>(i), mid, end};
        chain.kind = upper.limb;
        chain.attachment = upper.attachment;
        chain.front = upper.kind == BoneKind::UpperArm;
        chains.push_back(chain);
    }
    return chains;
}

double sideViewAngle(const Mat4& world) { return radToDeg(std::atan2(world(0, 0), -world(1, 0))); }

double lowestBoxPoint(const Mat4& world, const Vec3& extents) {
    // y of the box's corners: origin + x·R(1,0) + y·R(1,1) + z·R(1,2) over the box's ranges.
    return world(1, 3) + std::min(0.0, extents.x() * world(1, 0)) -
           0.5 * (std::abs(world(1, 1)) * extents.y() + std::abs(world(1, 2)) * extents.z());
}

double lowestBonePoint(std::span<const Bone> bones, std::span<const Mat4> world) {
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < bones.size(); ++i)
        lowest = std::min(lowest, lowestBoxPoint(world[i], bones[i].extents));
    return lowest;
}

namespace {

/// The ground rule's view of the legs (joint heights from the placed girdles, §7.5 point 1).
std::vector<LegReach> legReaches(const Skeleton& skeleton, const std::vector<LimbChain>& chains,
                                 const std::vector<Mat4>& world) {
    std::vector<LegReach> legs;
    legs.reserve(chains.size());
    for (const LimbChain& chain : chains) {
        if (chain.kind != LimbKind::Leg) continue;
        LegReach leg;
        leg.jointHeight = world[chain.bones[0]](1, 3);
        for (int b : chain.bones) leg.length += skeleton.bones[b].extents.x();
        leg.footLength = skeleton.bones[chain.bones[2]].extents.x();
        leg.front = chain.front;
        legs.push_back(leg);
    }
    return legs;
}

/// The highest ground every leg can stand on folded: a leg folds at most to its longest bone
/// plus its thickness below the joint. A long leg on a high girdle next to a short one on a low
/// girdle otherwise gets a ground it cannot fold under.
double highestGroundForFolding(const Skeleton& skeleton, const std::vector<LimbChain>& chains,
                               const std::vector<LegReach>& legs) {
    double highest = std::numeric_limits<double>::infinity();
    std::size_t legIndex = 0;
    for (const LimbChain& chain : chains) {
        if (chain.kind != LimbKind::Leg) continue;
        double longest = 0.0, thickest = 0.0;
        for (int b : chain.bones) {
            const Vec3& e = skeleton.bones[static_cast<std::size_t>(b)].extents;
            longest = std::max(longest, e.x());
            thickest = std::max(thickest, std::max(e.y(), e.z()));
        }
        highest = std::min(highest, legs[legIndex++].jointHeight - longest - thickest);
    }
    return highest;
}

/// The ground rule of §5.5.1 can put the body below the ground when the legs are short (§7.5):
/// ribs are shortened to stay above it; if the body still reaches lower, the ground moves down
/// to the body's lowest point and legs that cannot reach it with 0.8 of their length are
/// lengthened until they can (body_ground.cpp). The heel probability then follows the formula
/// for a ground that was not raised.
/// `world` are the posed bones' world transforms (rib lengths move no frame).
GroundHeight groundUnderBody(Skeleton& skeleton, const std::vector<LimbChain>& chains,
                             std::span<const Mat4> world, std::vector<LegReach> legs,
                             const GroundHeight& legGround) {
    fitRibsAboveGround(skeleton, world, legGround.height);
    const double body = std::min(lowestBodyPoint(skeleton, world, chains),
                                 highestGroundForFolding(skeleton, chains, legs));
    if (body >= legGround.height) return legGround;
    std::size_t legIndex = 0;
    for (const LimbChain& chain : chains) {
        if (chain.kind != LimbKind::Leg) continue;
        LegReach& leg = legs[legIndex++];
        leg.jointHeight -= body;
        const double needed = leg.jointHeight / kGroundLegFraction;
        if (leg.length > 0.0 && needed > leg.length) {
            const double factor = needed / leg.length;
            lengthenLeg(skeleton, chain, factor);
            leg.length *= factor;
            leg.footLength *= factor;
        }
    }
    GroundHeight ground = computeGroundHeight(legs, 0.0);
    ground.height += body;
    return ground;
}

/// Recomputes the world transforms of the limb chains' bones, whose joints the poses set, and of
/// their descendants, as Skeleton::worldTransforms would; the other bones keep theirs.
void updateLimbWorlds(const Skeleton& skeleton, const std::vector<LimbChain>& chains,
                      std::vector<Mat4>& world) {
    std::vector<char> moved(skeleton.bones.size(), 0);
    for (const LimbChain& chain : chains)
        for (int b : chain.bones) moved[static_cast<std::size_t>(b)] = 1;
    for (std::size_t i = 0; i < skeleton.bones.size(); ++i) {  // parents come before children
        const int parent = skeleton.bones[i].parent;
        if (parent >= 0 && moved[static_cast<std::size_t>(parent)]) moved[i] = 1;
        if (!moved[i]) continue;
        const Mat4 local = skeleton.bones[i].joint.transform();
        world[i] = parent < 0 ? local : Mat4(world[static_cast<std::size_t>(parent)] * local);
    }
}

}  // namespace

void poseLimbs(Skeleton& skeleton, const SkeletonDesign& design) {
    const std::vector<LimbChain> chains = findLimbChains(skeleton);
    std::vector<Mat4> world = skeleton.worldTransforms();  // girdles do not depend on limbs
    for (const LimbChain& chain : chains) {
        const double girdleAngle = sideViewAngle(world[chain.girdle]);
        switch (chain.kind) {
            case LimbKind::Fin:
                poseFin(skeleton, chain, girdleAngle);
                break;
            case LimbKind::Arm:
                poseArm(skeleton, chain, girdleAngle);
                break;
            case LimbKind::Wing:
                poseWing(skeleton, chain, design.wingAngles[static_cast<int>(chain.attachment)]);
                break;
            case LimbKind::Leg:
                setUpLeg(skeleton, chain, girdleAngle);
                break;
            case LimbKind::None:
                break;
        }
    }
    const std::vector<LegReach> legs = legReaches(skeleton, chains, world);
    updateLimbWorlds(skeleton, chains, world);
    double lowest = 0.0;
    if (legs.empty()) {
        lowest = lowestBonePoint(skeleton.bones, world);
        if (!std::isfinite(lowest)) lowest = 0.0;
    }
    GroundHeight ground = computeGroundHeight(legs, lowest);
    if (!legs.empty()) ground = groundUnderBody(skeleton, chains, world, legs, ground);
    skeleton.groundHeight = ground.height;
    skeleton.heelProbability = ground.heelProbability;
    skeleton.heelContact = !legs.empty() && design.heelDraw < ground.heelProbability;
    for (const LimbChain& chain : chains) {
        if (chain.kind != LimbKind::Leg) continue;
        placeLeg(skeleton, chain, world[chain.girdle], skeleton.groundHeight, skeleton.heelContact);
    }
}

}  // namespace ramus::detail
