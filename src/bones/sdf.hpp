// Signed-distance primitives and blends for the procedural bone models (seed 000 §5.6).
//
// Based on: Inigo Quilez, "Distance functions" and "Smooth minimum" (polynomial smin), 2013–2019.
// All functions are pure; distances are in the caller's units, negative inside.
#pragma once

#include "ramus/math.hpp"

namespace ramus::sdf {

/// Sphere of radius r around c.
double sphere(const Vec3& p, const Vec3& c, double r);
/// Axis-aligned ellipsoid with centre c and semi-axes r (all > 0); approximate distance
/// (Quilez's bound), exact on the axes.
double ellipsoid(const Vec3& p, const Vec3& c, const Vec3& r);
/// Capsule: segment a–b thickened by radius r.
double capsule(const Vec3& p, const Vec3& a, const Vec3& b, double r);
/// Round cone: segment a–b with radius ra at a and rb at b (linear in between).
double roundCone(const Vec3& p, const Vec3& a, const Vec3& b, double ra, double rb);
/// Axis-aligned box with centre c, half sizes h, edges rounded by radius r (r < min(h)).
double roundBox(const Vec3& p, const Vec3& c, const Vec3& h, double r);
/// Polynomial smooth union of two distances with blend width k ≥ 0 (k = 0: plain min).
double smoothUnion(double a, double b, double k);
/// Smooth subtraction: a with b carved out, blend width k ≥ 0.
double smoothSubtract(double a, double b, double k);

}  // namespace ramus::sdf
