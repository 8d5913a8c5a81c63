// Axial bone models: vertebra, tail tip, rib, scapula, pelvis (seed 000 §5.6).
//
// Based on: seed 000 §5.6 (one model per bone kind in the unit cube, the 3-vertebra tail tip and
// the double pelvis); shapes are blends of Quilez's signed-distance primitives (bones/sdf.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "bones/bone_shapes.hpp"
#include "bones/sdf.hpp"

namespace ramus {
namespace {

using namespace sdf;

/// One vertebra in the slab x ∈ [x0, x0 + len], scaled by s in y and z: the centrum spans the
/// slab exactly; the neural arch and spinous process sit on the −y side, transverse processes at
/// the sides. (The trunk and neck vertebrae run head-wards with bone +y pointing down in the
/// world, so the spine points up there; tail vertebrae run the other way and show it below,
/// where real tails carry their chevrons.)
double vertebra(const Vec3& pIn, double x0, double len, double s) {
    const Vec3 p(pIn.x(), -pIn.y(), pIn.z());  // arch and spine on −y (see vertebraShape)
    const double cx = x0 + len * 0.5;
    double d = roundBox(p, Vec3(cx, -0.2 * s, 0.0), Vec3(len * 0.5, 0.2 * s, 0.2 * s), 0.08 * s);
    const double arch =
        roundBox(p, Vec3(cx, 0.08 * s, 0.0), Vec3(len * 0.32, 0.14 * s, 0.17 * s), 0.05 * s);
    d = smoothUnion(d, arch, 0.06 * s);
    const double spine = roundCone(p, Vec3(cx, 0.12 * s, 0.0), Vec3(cx - len * 0.15, 0.5 * s, 0.0),
                                   0.09 * s, 0.045 * s);
    d = smoothUnion(d, spine, 0.08 * s);
    for (double side : {-1.0, 1.0}) {
        const double transverse =
            roundCone(p, Vec3(cx, 0.0, 0.12 * s * side), Vec3(cx, -0.06 * s, 0.5 * s * side),
                      0.07 * s, 0.04 * s);
        d = smoothUnion(d, transverse, 0.06 * s);
    }
    const double canal =
        capsule(p, Vec3(x0 - 0.2, 0.08 * s, 0.0), Vec3(x0 + len + 0.2, 0.08 * s, 0.0), 0.075 * s);
    return smoothSubtract(d, canal, 0.02 * s);
}

/// Rib centre line: leaves the vertebra at the origin and bulges outwards (+z: in a standing
/// animal the rib's x runs down and out, its z points away from the body).
Vec3 ribPoint(double t) {
    return Vec3(0.05 + 0.8 * t, 0.05 * std::sin(std::numbers::pi * t),
                0.45 * std::sin(std::numbers::pi * t));
}

}  // namespace

BoneShape vertebraShape() {
    BoneShape shape;
    shape.distance = [](const Vec3& p) { return vertebra(p, 0.0, 1.0, 1.0); };
    shape.lo = Vec3(-0.05, -0.5, -0.55);
    shape.hi = Vec3(1.05, 0.6, 0.55);
    return shape;
}

BoneShape tailTipShape() {
    BoneShape shape;
    shape.distance = [](const Vec3& p) {
        constexpr double kLen = 1.0 / 3.0;
        double d = vertebra(p, 0.0, kLen, 1.0);
        d = std::min(d, vertebra(p, kLen, kLen, 0.8));
        return std::min(d, vertebra(p, 2.0 * kLen, kLen, 0.6));
    };
    shape.lo = Vec3(-0.05, -0.5, -0.55);
    shape.hi = Vec3(1.05, 0.6, 0.55);
    return shape;
}

BoneShape ribShape() {
    BoneShape shape;
    shape.distance = [](const Vec3& p) {
        constexpr int kSegments = 8;
        double d = sphere(p, Vec3(0.1, 0.0, 0.0), 0.28);  // rib head at the vertebra
        for (int i = 0; i < kSegments; ++i) {
            const double t0 = static_cast<double>(i) / kSegments;
            const double t1 = static_cast<double>(i + 1) / kSegments;
            const double r0 = 0.3 - 0.12 * t0, r1 = 0.3 - 0.12 * t1;
            d = std::min(d, roundCone(p, ribPoint(t0), ribPoint(t1), r0, r1));
        }
        // Cut flat at the cube's ends: a rib box is ~20× longer than thick, so rounded ends
        // would stick far past the joint (above the spine) once fitted.
        return std::max({d, -p.x(), p.x() - 1.0});
    };
    shape.lo = Vec3(-0.3, -0.4, -0.4);
    shape.hi = Vec3(1.1, 0.4, 0.8);
    return shape;
}

BoneShape scapulaShape() {
    BoneShape shape;
    shape.distance = [](const Vec3& p) {
        // Flat blade (thin in z) narrowing from the top (x = 0) to the neck at the socket.
        const Vec3 flat(p.x(), p.y(), 0.0);
        const double outline =
            roundCone(flat, Vec3(0.25, 0.0, 0.0), Vec3(0.78, 0.0, 0.0), 0.38, 0.12);
        double d = std::max(outline, std::abs(p.z()) - 0.2);
        // The spine: a ridge on the outer face, highest in the middle.
        const double ridge = roundCone(p, Vec3(0.05, 0.02, 0.2), Vec3(0.7, 0.0, 0.35), 0.1, 0.16);
        d = smoothUnion(d, ridge, 0.05);
        // The socket (glenoid) at x = 1: a cup that opens towards +x.
        const double head = sphere(p, Vec3(0.85, 0.0, 0.0), 0.25);
        d = smoothUnion(d, head, 0.08);
        return smoothSubtract(d, sphere(p, Vec3(1.12, 0.0, 0.0), 0.2), 0.03);
    };
    shape.lo = Vec3(-0.2, -0.6, -0.35);
    shape.hi = Vec3(1.1, 0.6, 0.6);
    return shape;
}

BoneShape pelvisShape(bool doubleSockets) {
    // One hip bone per side: x runs from the sacrum (x = 0) down to the hip socket(s) at x = 1,
    // y points towards the tail, z outwards (thin). The double pelvis carries a second socket:
    // the skeleton puts the two hip joints side by side along y.
    BoneShape shape;
    const std::vector<double> socketY =
        doubleSockets ? std::vector<double>{-0.35, 0.35} : std::vector<double>{0.0};
    shape.distance = [socketY](const Vec3& p) {
        const Vec3 flat(p.x(), p.y(), 0.0);
        // Ilium: a wide blade at the sacrum narrowing towards the socket(s).
        const double blade = roundCone(flat, Vec3(0.22, 0.0, 0.0), Vec3(0.7, 0.0, 0.0), 0.4, 0.18);
        double d = std::max(blade, std::abs(p.z()) - 0.25);
        for (double sy : socketY) {
            const Vec3 socket(0.88, sy, 0.05);
            double cup = sphere(p, socket, 0.27);
            cup = smoothSubtract(cup, sphere(p, socket + Vec3(0.1, 0.0, 0.3), 0.2), 0.03);
            d = smoothUnion(d, cup, 0.08);
        }
        // Ischium: a bar from the socket(s) back along +y.
        const double ischium = roundCone(p, Vec3(0.9, socketY.back(), 0.0),
                                         Vec3(0.7, socketY.back() + 0.5, -0.05), 0.16, 0.1);
        return smoothUnion(d, ischium, 0.06);
    };
    if (doubleSockets) {
        for (double sy : socketY) shape.childJoints.emplace_back(1.0, sy, 0.0);
    }
    shape.lo = Vec3(-0.25, -0.7, -0.4);
    shape.hi = Vec3(1.25, 1.0, 0.45);
    return shape;
}

}  // namespace ramus
