// Limb bone models: long bones, paired forearm/shank bones, hands, hooves, wings, fins
// (seed 000 §5.6).
//
// Based on: seed 000 §5.6 (one model per bone kind in the unit cube; long bones keep their
// thickness from the height, third bullet); blends of Quilez's signed-distance primitives.
#include <cmath>

#include "bones/bone_shapes.hpp"
#include "bones/sdf.hpp"

namespace ramus {
namespace {

using namespace sdf;

/// Humerus / femur: ball head and trochanter at x = 0, shaft, two condyles at x = 1.
double longBone(const Vec3& p, bool femur) {
    const double shaftR = femur ? 0.17 : 0.19;
    double d = roundCone(p, Vec3(0.12, 0.0, 0.0), Vec3(0.88, 0.0, 0.0), shaftR * 1.2, shaftR);
    const Vec3 headC = femur ? Vec3(0.1, 0.16, -0.14) : Vec3(0.08, 0.16, 0.0);
    d = smoothUnion(d, sphere(p, headC, 0.24), 0.1);
    d = smoothUnion(d, sphere(p, Vec3(0.1, -0.16, femur ? 0.12 : 0.1), 0.18), 0.1);  // trochanter
    for (double side : {-1.0, 1.0}) {
        d = smoothUnion(d, sphere(p, Vec3(0.88, -0.03, 0.17 * side), 0.19), 0.1);
    }
    return d;
}

/// Radius and ulna / tibia and fibula: two shafts side by side, joined at the ends.
double pairedBone(const Vec3& p, bool shank) {
    const double mainR = shank ? 0.2 : 0.16;
    const double thinR = shank ? 0.09 : 0.13;
    double d = roundCone(p, Vec3(0.08, 0.0, -0.18), Vec3(0.92, 0.0, -0.15), mainR * 1.3, mainR);
    d = smoothUnion(
        d, roundCone(p, Vec3(0.05, 0.0, 0.2), Vec3(0.94, 0.0, 0.18), thinR * 1.2, thinR), 0.06);
    d = smoothUnion(d, ellipsoid(p, Vec3(0.06, 0.0, 0.0), Vec3(0.1, 0.26, 0.4)), 0.1);
    d = smoothUnion(d, ellipsoid(p, Vec3(0.95, 0.0, 0.0), Vec3(0.08, 0.24, 0.38)), 0.1);
    if (!shank) {  // olecranon: the ulna's elbow process sticks out past the joint
        d = smoothUnion(d, roundCone(p, Vec3(0.1, 0.05, 0.2), Vec3(-0.06, 0.1, 0.2), 0.12, 0.07),
                        0.05);
    }
    return d;
}

/// Palm (x ∈ [0, palmEnd]) and `digits` digit chains spread in z, flat in y.
double hand(const Vec3& p, double palmEnd, int digits, double digitR, double spread) {
    double d = roundBox(p, Vec3(palmEnd * 0.5, 0.0, 0.0), Vec3(palmEnd * 0.5, 0.18, 0.36), 0.1);
    for (int i = 0; i < digits; ++i) {
        const double z = spread * (2.0 * i / (digits - 1) - 1.0);
        const double tip = 1.0 - 0.12 * std::abs(z) / spread;
        const Vec3 a(palmEnd - 0.05, 0.0, z * 0.8);
        const Vec3 b(palmEnd + (tip - palmEnd) * 0.5, 0.0, z);
        const Vec3 c(tip - digitR, -0.04, z * 1.05);
        d = smoothUnion(d, roundCone(p, a, b, digitR * 1.2, digitR), 0.04);
        d = smoothUnion(d, roundCone(p, b, c, digitR, digitR * 0.75), 0.03);
    }
    return d;
}

double hoof(const Vec3& p) {
    double d = roundCone(p, Vec3(0.05, 0.0, 0.0), Vec3(0.55, 0.0, 0.0), 0.26, 0.2);
    // The hoof capsule widens towards the sole at x = 1.
    d = smoothUnion(d, roundCone(p, Vec3(0.55, 0.0, 0.0), Vec3(0.88, -0.02, 0.0), 0.24, 0.4), 0.08);
    return std::max(d, p.x() - 1.0);
}

double wingHand(const Vec3& p) {
    double d = roundCone(p, Vec3(0.05, 0.0, 0.0), Vec3(0.35, 0.0, 0.02), 0.16, 0.1);
    const Vec3 base(0.33, 0.0, 0.0);
    const Vec3 tips[3] = {Vec3(1.0, 0.0, 0.0), Vec3(0.82, 0.0, 0.3), Vec3(0.55, 0.0, -0.28)};
    const double radii[3] = {0.15, 0.13, 0.12};
    for (int i = 0; i < 3; ++i) {
        const Vec3 tip = tips[i] - (tips[i] - base).normalized() * radii[i] * 0.4;
        const Vec3 knuckle = base + (tip - base) * 0.45;
        d = smoothUnion(d, roundCone(p, base, knuckle, radii[i], radii[i] * 0.8), 0.05);
        d = smoothUnion(d, roundCone(p, knuckle, tip, radii[i] * 0.8, radii[i] * 0.4), 0.03);
    }
    return d;
}

double fin(const Vec3& p) {
    // A flat, rounded paddle (thin in y) with digit ridges.
    const Vec3 q(p.x(), p.y() * 1.5, p.z());
    double d = roundCone(q, Vec3(0.15, 0.0, 0.0), Vec3(0.75, 0.0, 0.0), 0.32, 0.24) / 1.5;
    for (double z : {-0.25, 0.0, 0.25}) {
        d = smoothUnion(d, capsule(p, Vec3(0.1, 0.0, z * 0.5), Vec3(0.95, 0.0, z), 0.1), 0.05);
    }
    return d;
}

}  // namespace

BoneShape longBoneShape(BoneModelKind kind) {
    BoneShape shape;
    const bool femur = kind == BoneModelKind::Thigh;
    if (kind == BoneModelKind::Forearm || kind == BoneModelKind::Shank) {
        const bool shank = kind == BoneModelKind::Shank;
        shape.distance = [shank](const Vec3& p) { return pairedBone(p, shank); };
        shape.lo = Vec3(-0.15, -0.35, -0.5);
        shape.hi = Vec3(1.05, 0.35, 0.5);
        return shape;
    }
    shape.distance = [femur](const Vec3& p) { return longBone(p, femur); };
    shape.lo = Vec3(-0.2, -0.5, -0.5);
    shape.hi = Vec3(1.1, 0.5, 0.5);
    shape.widthFromHeight = 1.0;
    return shape;
}

BoneShape handShape(BoneModelKind kind) {
    BoneShape shape;
    switch (kind) {
        case BoneModelKind::Hoof:
            shape.distance = hoof;
            break;
        case BoneModelKind::WingHand:
            shape.distance = wingHand;
            break;
        case BoneModelKind::Fin:
            shape.distance = fin;
            break;
        default:
            shape.distance = [](const Vec3& p) { return hand(p, 0.42, 4, 0.1, 0.28); };
            break;
    }
    shape.lo = Vec3(-0.1, -0.5, -0.55);
    shape.hi = Vec3(1.05, 0.5, 0.55);
    return shape;
}

BoneShape boneShape(BoneModelKind kind) {
    switch (kind) {
        case BoneModelKind::Vertebra:
            return vertebraShape();
        case BoneModelKind::TailTip:
            return tailTipShape();
        case BoneModelKind::Rib:
            return ribShape();
        case BoneModelKind::SkullHerbivore:
        case BoneModelKind::SkullCarnivore:
        case BoneModelKind::SkullBird:
        case BoneModelKind::SkullReptile:
            return skullShape(kind);
        case BoneModelKind::Scapula:
            return scapulaShape();
        case BoneModelKind::Pelvis:
            return pelvisShape(false);
        case BoneModelKind::PelvisDouble:
            return pelvisShape(true);
        case BoneModelKind::UpperArm:
        case BoneModelKind::Forearm:
        case BoneModelKind::Thigh:
        case BoneModelKind::Shank:
            return longBoneShape(kind);
        case BoneModelKind::Hand:
        case BoneModelKind::Hoof:
        case BoneModelKind::WingHand:
        case BoneModelKind::Fin:
            return handShape(kind);
    }
    return vertebraShape();
}

}  // namespace ramus
