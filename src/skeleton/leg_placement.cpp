// Iterative leg placement: turn the joints of a folded leg until its foot rests on the ground.
//
// Based on: seed 000 §5.5.2 (start fully folded; per iteration turn each joint a step towards
// the ground; undo turns that put a bone below the ground, past the vertical, or the instep
// below the sole; start step 40°, then 6/7 of it, halved when the iteration achieved little)
// and §7.5 (count undone turns instead of watching the distance to the ground, point 2; legs that
// cannot reach the ground or start below it point straight down, points 1 and 4).
//
// Only the side angles move (one degree of freedom per joint, §5.5.2); the shoulder/hip spread
// stays 0, so the leg is planar and a bone's side-view angle φ is the girdle's plus the joint
// angles (conventions: skeleton/limbs.hpp). Beyond the thesis (all documented at placeLeg):
// the contact point is the lowest corner of the foot box's end, so that the box, not just its
// axis, rests on the ground; a joint may also turn together with the opposite turn of the next
// joint; and dead ends of the greedy iteration (or a folded start below the ground) get a second
// run from the best valid pose of a coarse grid.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "ramus/error.hpp"
#include "skeleton/limbs.hpp"

namespace ramus::detail {
namespace {

/// A foot steeper than this to the ground is a hoof (§5.5.2 "Fußmodell").
constexpr double kHoofAngleDeg = 45.0;
/// Below this step (degrees) nothing visible changes any more.
constexpr double kMinStepDeg = 1e-9;
/// Rounding slack of the angle invariants (sums of joint angles), degrees.
constexpr double kAngleSlackDeg = 1e-9;

/// Which dof of a leg joint is the side swing: the last one (after the hip's spread).
int sideDof(const Joint& joint) { return joint.dofCount - 1; }

/// The fixed parts of one leg and its current side angles.
struct Leg {
    Mat4 upperBase = Mat4::Identity();  ///< girdle · fixed[0]: bone 0 before its side swing
    double girdleAngle = 0.0;           ///< φ of the girdle
    /// Per joint: translate(position) · rest · R(dofs before the side swing), fixed here.
    std::array<Mat4, 3> fixed{};
    std::array<double, 3> angles{};  ///< side angles (degrees), about the joints' z axes
    std::array<double, 3> minAngles{}, maxAngles{};
    std::array<Vec3, 3> extents{};  ///< bone boxes
    double ground = 0.0;
    double belowTolerance = 0.0;  ///< px
    bool heel = false;

    double& angle(int k) { return angles[k]; }
    double angle(int k) const { return angles[k]; }
    double minAngle(int k) const { return minAngles[k]; }
    double maxAngle(int k) const { return maxAngles[k]; }
};

/// cos and sin of a side angle (degrees). A candidate turn of the iteration changes one or two
/// angles; the others keep theirs, so each is computed once.
struct Turn {
    double c = 1.0, s = 0.0;
};
Turn turnOf(double angle) { return {std::cos(degToRad(angle)), std::sin(degToRad(angle))}; }

/// Bone k's world transform before its side swing: parent · fixed[k], the parent's from `world`;
/// bone 0's is the same in every pose (Leg::upperBase).
Mat4 unturned(const Leg& leg, const std::array<Mat4, 3>& world, int k) {
    if (k == 0) return leg.upperBase;
    Mat4 result;
    result.noalias() = world[k - 1] * leg.fixed[k];
    return result;
}

/// Applies the side swing: world = world · R_z(angle), in place.
void applyTurn(Mat4& world, const Turn& turn) {
    const Vec4 x = world.col(0), y = world.col(1);
    world.col(0) = turn.c * x + turn.s * y;
    world.col(1) = turn.c * y - turn.s * x;
}

/// Sets world[k] for bone k turned by `turn`, under its parent's world[k − 1] (or the girdle).
void placeBone(const Leg& leg, std::array<Mat4, 3>& world, int k, const Turn& turn) {
    if (k == 0)
        world[0] = leg.upperBase;
    else
        world[k].noalias() = world[k - 1] * leg.fixed[k];
    applyTurn(world[k], turn);
}

/// The world transforms of the three bones at the leg's angles, and the angles' Turns.
struct LegPose {
    std::array<Mat4, 3> world;
    std::array<Turn, 3> turns;
};

LegPose legPose(const Leg& leg) {
    LegPose pose;
    for (int k = 0; k < 3; ++k) {
        pose.turns[k] = turnOf(leg.angles[k]);
        placeBone(leg, pose.world, k, pose.turns[k]);
    }
    return pose;
}

/// Lowest y of the face x = `at` (0 or the length) of a box.
double lowestFacePoint(const Mat4& world, const Vec3& extents, double at) {
    return world(1, 3) + at * world(1, 0) -
           0.5 * (std::abs(world(1, 1)) * extents.y() + std::abs(world(1, 2)) * extents.z());
}

double toeHeight(const Leg& leg, const std::array<Mat4, 3>& world) {
    return lowestFacePoint(world[2], leg.extents[2], leg.extents[2].x());
}

/// The contact point: the lowest corner of the foot's distal end (toe tip) or, under heel
/// contact, of the heel region: the foot's proximal end and the middle bone's distal end (both
/// boxes overlap at the ankle/wrist, and the thicker one touches the ground first).
double contactHeight(const Leg& leg, const std::array<Mat4, 3>& world) {
    if (!leg.heel) return toeHeight(leg, world);
    return std::min(lowestFacePoint(world[2], leg.extents[2], 0.0),
                    lowestFacePoint(world[1], leg.extents[1], leg.extents[1].x()));
}

/// What joint k minimises: the contact point's height; under heel contact the ankle does not
/// move the heel, so it lays the foot flat instead (|toe − heel|, which also keeps the toe from
/// touching the ground before the heel does).
double targetHeight(const Leg& leg, const std::array<Mat4, 3>& world, int k) {
    if (leg.heel && k == 2) {
        return std::abs(toeHeight(leg, world) - lowestFacePoint(world[2], leg.extents[2], 0.0));
    }
    return contactHeight(leg, world);
}

/// The invariants of §5.5.2 for bone k with world transform `world` and side-view angle `phi`:
/// its box above the ground, not past the vertical (|φ| ≤ 180°), and for the foot the instep
/// not below the sole (the foot never points backwards: φ ≤ 0).
bool boneValid(const Leg& leg, const Mat4& world, int k, double phi) {
    if (std::abs(phi) > 180.0 + kAngleSlackDeg) return false;
    if (k == 2 && phi > kAngleSlackDeg) return false;
    return lowestBoxPoint(world, leg.extents[k]) >= leg.ground - leg.belowTolerance;
}

/// The invariants for bones `from`…2 (the bones before are known to hold them).
bool legValid(const Leg& leg, const std::array<Mat4, 3>& world, int from = 0) {
    double phi = leg.girdleAngle;
    for (int k = 0; k < 3; ++k) {
        phi += leg.angle(k);
        if (k >= from && !boneValid(leg, world[k], k, phi)) return false;
    }
    return true;
}

std::array<double, 3> legAngles(const Leg& leg) {
    return {leg.angle(0), leg.angle(1), leg.angle(2)};
}

void setLegAngles(Leg& leg, const std::array<double, 3>& angles) {
    for (int k = 0; k < 3; ++k) leg.angle(k) = angles[k];
}

/// Turns joint k by `delta` (clamped to its limits); with `keepNext` the next joint turns back
/// by the same amount, so the next bone keeps its direction. False when nothing turned.
bool turnJoint(Leg& leg, int k, double delta, bool keepNext) {
    const double old = leg.angle(k);
    leg.angle(k) = std::clamp(old + delta, leg.minAngle(k), leg.maxAngle(k));
    const double turned = leg.angle(k) - old;
    if (keepNext) {
        leg.angle(k + 1) =
            std::clamp(leg.angle(k + 1) - turned, leg.minAngle(k + 1), leg.maxAngle(k + 1));
    }
    return turned != 0.0;
}

/// Sets the side angles so that the bones point at the given world angles (clamped).
void aimLeg(Leg& leg, const std::array<double, 3>& phi) {
    double parentPhi = leg.girdleAngle;
    for (int k = 0; k < 3; ++k) {
        leg.angle(k) = std::clamp(phi[k] - parentPhi, leg.minAngle(k), leg.maxAngle(k));
        parentPhi += leg.angle(k);
    }
}

/// The folded start of §5.5.2: every joint at the limit that folds its bone against the parent
/// (front legs bend forwards at the elbow, hind legs backwards at the knee), the foot folding at
/// most to pointing straight up.
void foldLeg(Leg& leg, bool front) {
    leg.angle(0) = front ? leg.maxAngle(0) : leg.minAngle(0);
    leg.angle(1) = front ? leg.minAngle(1) : leg.maxAngle(1);
    const double middlePhi = leg.girdleAngle + leg.angle(0) + leg.angle(1);
    leg.angle(2) = std::clamp(-180.0 - middlePhi, leg.minAngle(2), leg.maxAngle(2));
}

/// One iteration: each joint in turn takes the valid turn by ±step that lowers its target
/// most. Candidates are the joint alone and, except for the last joint, the joint with the next
/// one turning back (the next bone keeps its direction; without it a nearly vertical foot, which
/// may not point backwards, locks the hip for good). A joint whose lowering turns are all
/// invalid counts as undone. Returns whether most attempted turns were undone (§7.5 point 2).
/// `current` is the leg's pose on entry and its new pose on return.
bool legIteration(Leg& leg, double step, LegPose& current) {
    int attempted = 0, undone = 0;
    for (int k = 0; k < 3; ++k) {
        const std::array<double, 3> saved = legAngles(leg);
        double best = targetHeight(leg, current.world, k);
        std::array<double, 3> bestAngles = saved;
        LegPose bestPose = current;
        bool lowering = false;
        // Bones before k do not move, and candidates 2 and 3 turn joint k as 0 and 1 do: bone k's
        // frame is computed once per direction.
        const Mat4 base = unturned(leg, current.world, k);
        std::array<Turn, 2> turnsK;
        std::array<Mat4, 2> worldsK;
        LegPose pose = current;
        for (int candidate = 0; candidate < (k < 2 ? 4 : 2); ++candidate) {
            setLegAngles(leg, saved);
            const int direction = candidate % 2;
            const bool keepNext = candidate >= 2;
            if (!turnJoint(leg, k, direction == 0 ? step : -step, keepNext)) continue;
            if (!keepNext) {
                turnsK[direction] = turnOf(leg.angle(k));
                worldsK[direction] = base;
                applyTurn(worldsK[direction], turnsK[direction]);
            }
            pose.turns[k] = turnsK[direction];
            pose.world[k] = worldsK[direction];
            if (k < 2)
                pose.turns[k + 1] = keepNext ? turnOf(leg.angle(k + 1)) : current.turns[k + 1];
            for (int j = k + 1; j < 3; ++j) placeBone(leg, pose.world, j, pose.turns[j]);
            const double height = targetHeight(leg, pose.world, k);
            if (height >= best) continue;
            lowering = true;
            if (!legValid(leg, pose.world, k)) continue;
            best = height;
            bestAngles = legAngles(leg);
            bestPose = pose;
        }
        setLegAngles(leg, bestAngles);
        current = bestPose;
        if (!lowering) continue;
        ++attempted;
        if (bestAngles == saved) ++undone;
    }
    return attempted > 0 && 2 * undone > attempted;
}

Leg makeLeg(const Skeleton& skeleton, const LimbChain& chain, const Mat4& girdleWorld,
            double ground, bool heel, double belowTolerance) {
    Leg leg;
    leg.girdleAngle = sideViewAngle(girdleWorld);
    for (int k = 0; k < 3; ++k) {
        const Bone& bone = skeleton.bones[chain.bones[k]];
        const Joint& joint = bone.joint;
        const int side = sideDof(joint);
        RAMUS_ASSERT(joint.dofs[side].axis == Vec3::UnitZ());
        Joint before = joint;  // the dofs before the side swing, without it
        before.dofCount = side;
        leg.fixed[k] = before.transform();
        leg.angles[k] = joint.dofs[side].angleDeg;
        leg.minAngles[k] = joint.dofs[side].minDeg;
        leg.maxAngles[k] = joint.dofs[side].maxDeg;
        leg.extents[k] = bone.extents;
    }
    leg.upperBase.noalias() = girdleWorld * leg.fixed[0];
    leg.ground = ground;
    leg.heel = heel;
    leg.belowTolerance = belowTolerance;
    return leg;
}

/// The §7.5 fallback: straight down; the foot too (stretched) or flat forwards.
void straightDown(Leg& leg, bool footFlat) { aimLeg(leg, {0.0, 0.0, footFlat ? -90.0 : 0.0}); }

/// Angles evenly from lo to hi, `spacing` apart at most.
std::vector<double> gridAngles(double lo, double hi, double spacing) {
    const int steps = std::max(1, static_cast<int>(std::ceil((hi - lo) / spacing)));
    std::vector<double> values;
    for (int i = 0; i <= steps; ++i) values.push_back(lo + (hi - lo) * i / steps);
    return values;
}

/// Rescue start for the iteration's dead ends (and for folded starts below the ground): the valid
/// pose with the lowest contact point on a grid of side angles `spacing` apart (limits
/// included), pruned bone by bone. False when no grid pose is valid.
bool gridStart(Leg& leg, double spacing) {
    std::array<std::vector<double>, 3> values;
    for (int k = 0; k < 3; ++k) values[k] = gridAngles(leg.minAngle(k), leg.maxAngle(k), spacing);
    double best = std::numeric_limits<double>::infinity();
    std::array<double, 3> bestAngles{};
    std::array<Mat4, 3> world;
    for (double a0 : values[0]) {
        placeBone(leg, world, 0, turnOf(a0));
        if (!boneValid(leg, world[0], 0, leg.girdleAngle + a0)) continue;
        const Mat4 base1 = unturned(leg, world, 1);
        for (double a1 : values[1]) {
            world[1] = base1;
            applyTurn(world[1], turnOf(a1));
            if (!boneValid(leg, world[1], 1, leg.girdleAngle + a0 + a1)) continue;
            const Mat4 base2 = unturned(leg, world, 2);
            for (double a2 : values[2]) {
                world[2] = base2;
                applyTurn(world[2], turnOf(a2));
                if (!boneValid(leg, world[2], 2, leg.girdleAngle + a0 + a1 + a2)) continue;
                const double height = contactHeight(leg, world);
                if (height < best) best = height, bestAngles = {a0, a1, a2};
            }
        }
    }
    if (!std::isfinite(best)) return false;
    setLegAngles(leg, bestAngles);
    return true;
}

/// The iteration of §5.5.2 from the leg's current (valid) pose; returns the iterations run.
int iterateLeg(Leg& leg, double startStep, double tolerance, const LegPlacementParams& params) {
    int iterations = 0;
    double step = startStep;
    LegPose pose = legPose(leg);  // kept up to date by each iteration
    while (iterations < params.maxIterations && step > kMinStepDeg &&
           contactHeight(leg, pose.world) - leg.ground > tolerance) {
        const bool mostUndone = legIteration(leg, step, pose);
        step *= mostUndone ? 0.5 : params.stepFactor;
        ++iterations;
    }
    return iterations;
}

double contactGap(const Leg& leg) { return contactHeight(leg, legPose(leg).world) - leg.ground; }

void storeLeg(Skeleton& skeleton, const LimbChain& chain, const Leg& leg) {
    for (int k = 0; k < 3; ++k) {
        Joint& joint = skeleton.bones[chain.bones[k]].joint;
        joint.dofs[sideDof(joint)].angleDeg = leg.angles[k];
    }
    const Mat4 foot = legPose(leg).world[2];
    const double elevation = radToDeg(std::asin(std::min(1.0, std::abs(foot(1, 0)))));
    skeleton.bones[chain.bones[2]].hoof = elevation >= kHoofAngleDeg;
}

}  // namespace

LegPlacementResult placeLeg(Skeleton& skeleton, const LimbChain& chain, const Mat4& girdleWorld,
                            double groundHeight, bool heelContact,
                            const LegPlacementParams& params) {
    std::array<double, 3> lengths{};
    for (int k = 0; k < 3; ++k) lengths[k] = skeleton.bones[chain.bones[k]].extents.x();
    const double length = lengths[0] + lengths[1] + lengths[2];
    const double jointHeight =
        (girdleWorld * skeleton.bones[chain.bones[0]].joint.position.homogeneous()).y();
    LegPlacementResult result;
    // A leg whose heel cannot reach the ground stands on its toes (§5.5.1 assumes toe contact).
    result.heelContact = heelContact && jointHeight - lengths[0] - lengths[1] <= groundHeight;
    Leg leg = makeLeg(skeleton, chain, girdleWorld, groundHeight, result.heelContact,
                      params.belowTolerance * std::max(length, 1.0));
    const bool reaches = jointHeight - length <= groundHeight;
    foldLeg(leg, chain.front);
    const double tolerance = params.tolerance * length;
    bool started = reaches && legValid(leg, legPose(leg).world);
    if (started) result.iterations = iterateLeg(leg, params.startStepDeg, tolerance, params);
    if (reaches && (!started || contactGap(leg) > tolerance)) {
        Leg rescued = leg;
        if (gridStart(rescued, params.rescueGridDeg)) {
            result.iterations += iterateLeg(rescued, params.rescueGridDeg, tolerance, params);
            if (!started || contactGap(rescued) < contactGap(leg)) leg = rescued;
            started = true;
            result.rescued = true;
        }
    }
    if (!started) {
        straightDown(leg, reaches);
        result.straightDown = true;
    }
    result.contactGap = contactGap(leg);
    storeLeg(skeleton, chain, leg);
    return result;
}

}  // namespace ramus::detail
