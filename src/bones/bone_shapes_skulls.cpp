// Skull models: herbivore, carnivore, bird, crocodilian (seed 000 §5.6 "Spezielle Knochen").
//
// Based on: seed 000 §5.6 (skulls by head kind; x runs from the joint to the neck at x = 0 to
// the snout tip at x = 1, y up); blends of Quilez's signed-distance primitives (bones/sdf.hpp).
#include <algorithm>
#include <cmath>

#include "bones/bone_shapes.hpp"
#include "bones/sdf.hpp"

namespace ramus {
namespace {

using namespace sdf;

/// Eye sockets: spheres carved into both sides at (x, y, ±z).
double carveEyes(double d, const Vec3& p, double x, double y, double z, double r) {
    for (double side : {-1.0, 1.0}) d = smoothSubtract(d, sphere(p, Vec3(x, y, z * side), r), 0.03);
    return d;
}

/// A row of `count` conical teeth from x0 to x1 at height y, both sides at ±z, pointing along
/// `dir` (±1 in y), `length` long.
double teethRow(double d, const Vec3& p, double x0, double x1, double y, double z, double dir,
                double length, int count) {
    for (int i = 0; i < count; ++i) {
        const double x = x0 + (x1 - x0) * (count == 1 ? 0.0 : static_cast<double>(i) / (count - 1));
        for (double side : {-1.0, 1.0}) {
            const Vec3 base(x, y, z * side);
            d = std::min(d, roundCone(p, base, base + Vec3(0, dir * length, 0), 0.03, 0.008));
        }
    }
    return d;
}

double herbivore(const Vec3& p) {
    double d = ellipsoid(p, Vec3(0.22, 0.08, 0.0), Vec3(0.22, 0.3, 0.32));
    d = smoothUnion(d, roundCone(p, Vec3(0.35, 0.05, 0.0), Vec3(0.94, -0.08, 0.0), 0.22, 0.1),
                    0.12);
    for (double side : {-1.0, 1.0}) {  // lower jaw: two rami meeting at the chin
        d = smoothUnion(
            d,
            roundCone(p, Vec3(0.18, -0.24, 0.2 * side), Vec3(0.92, -0.22, 0.02 * side), 0.08, 0.06),
            0.08);
    }
    d = carveEyes(d, p, 0.36, 0.2, 0.3, 0.1);
    return smoothSubtract(d, sphere(p, Vec3(1.0, -0.02, 0.0), 0.07), 0.02);  // nostrils
}

double carnivore(const Vec3& p) {
    double d = ellipsoid(p, Vec3(0.3, 0.1, 0.0), Vec3(0.3, 0.3, 0.34));
    d = smoothUnion(d, roundCone(p, Vec3(0.5, 0.02, 0.0), Vec3(0.92, -0.04, 0.0), 0.2, 0.12), 0.1);
    for (double side : {-1.0, 1.0}) {  // zygomatic arches and the lower jaw
        d = smoothUnion(
            d, capsule(p, Vec3(0.22, -0.02, 0.34 * side), Vec3(0.55, 0.0, 0.2 * side), 0.045),
            0.05);
        d = smoothUnion(d,
                        roundCone(p, Vec3(0.14, -0.26, 0.22 * side), Vec3(0.9, -0.27, 0.08 * side),
                                  0.08, 0.055),
                        0.06);
    }
    d = teethRow(d, p, 0.55, 0.92, -0.13, 0.1, -1.0, 0.12, 5);  // upper teeth down
    d = teethRow(d, p, 0.55, 0.88, -0.22, 0.09, 1.0, 0.08, 4);  // lower teeth up
    // Canines.
    d = teethRow(d, p, 0.93, 0.93, -0.12, 0.1, -1.0, 0.22, 1);
    return carveEyes(d, p, 0.5, 0.2, 0.26, 0.1);
}

double bird(const Vec3& p) {
    double d = sphere(p, Vec3(0.3, 0.08, 0.0), 0.3);
    const Vec3 q(p.x(), p.y(), p.z() * 1.3);  // beak a little narrower than tall
    const double beak = roundCone(q, Vec3(0.5, 0.0, 0.0), Vec3(1.0, -0.12, 0.0), 0.17, 0.015);
    d = smoothUnion(d, beak, 0.1);
    return carveEyes(d, p, 0.4, 0.12, 0.3, 0.13);
}

double reptile(const Vec3& p) {
    const Vec3 q(p.x(), p.y() * 1.8, p.z());  // flat: half as tall as wide
    double d = roundBox(q, Vec3(0.18, 0.0, 0.0), Vec3(0.18, 0.45, 0.42), 0.1) / 1.8;
    d = smoothUnion(d, roundCone(q, Vec3(0.3, 0.0, 0.0), Vec3(0.96, -0.1, 0.0), 0.32, 0.12) / 1.8,
                    0.1);
    d = teethRow(d, p, 0.35, 0.92, -0.12, 0.12, -1.0, 0.1, 7);
    d = carveEyes(d, p, 0.3, 0.2, 0.2, 0.08);
    return smoothSubtract(d, sphere(p, Vec3(0.12, 0.1, 0.0), 0.06), 0.02);  // skull table hole
}

}  // namespace

BoneShape skullShape(BoneModelKind kind) {
    BoneShape shape;
    switch (kind) {
        case BoneModelKind::SkullCarnivore:
            shape.distance = carnivore;
            break;
        case BoneModelKind::SkullBird:
            shape.distance = bird;
            break;
        case BoneModelKind::SkullReptile:
            shape.distance = reptile;
            break;
        default:
            shape.distance = herbivore;
            break;
    }
    // The skull's bone frame has +y pointing down in a standing animal (it continues the neck,
    // which runs head-wards upside down), so the shapes, drawn with y up, are turned over.
    shape.distance = [inner = std::move(shape.distance)](const Vec3& p) {
        return inner(Vec3(p.x(), -p.y(), p.z()));
    };
    shape.lo = Vec3(-0.1, -0.5, -0.5);
    shape.hi = Vec3(1.1, 0.5, 0.5);
    return shape;
}

}  // namespace ramus
