// Signed-distance primitives and smooth blends (include: src/bones/sdf.hpp).
//
// Based on: seed 000 §5.6 (bone models); Inigo Quilez, "Distance functions" (sphere, ellipsoid
// bound, capsule, round cone, rounded box) and "Smooth minimum" (polynomial smin).
#include "bones/sdf.hpp"

#include <algorithm>
#include <cmath>

namespace ramus::sdf {

double sphere(const Vec3& p, const Vec3& c, double r) { return (p - c).norm() - r; }

double ellipsoid(const Vec3& p, const Vec3& c, const Vec3& r) {
    const Vec3 q = p - c;
    const double k0 = q.cwiseQuotient(r).norm();
    const double k1 = q.cwiseQuotient(r.cwiseProduct(r)).norm();
    if (k1 == 0.0) return -r.minCoeff();
    return k0 * (k0 - 1.0) / k1;
}

double capsule(const Vec3& p, const Vec3& a, const Vec3& b, double r) {
    const Vec3 pa = p - a;
    const Vec3 ba = b - a;
    const double len2 = ba.squaredNorm();
    const double h = len2 > 0.0 ? std::clamp(pa.dot(ba) / len2, 0.0, 1.0) : 0.0;
    return (pa - ba * h).norm() - r;
}

double roundCone(const Vec3& p, const Vec3& a, const Vec3& b, double ra, double rb) {
    // Quilez's exact round cone (sphere-swept, tangent spheres at a and b).
    const Vec3 ba = b - a;
    const double l2 = ba.squaredNorm();
    const double rr = ra - rb;
    const double a2 = l2 - rr * rr;
    if (a2 <= 0.0) return std::min(sphere(p, a, ra), sphere(p, b, rb));
    const double il2 = 1.0 / l2;
    const Vec3 pa = p - a;
    const double y = pa.dot(ba);
    const double z = y - l2;
    const double x2 = (pa * l2 - ba * y).squaredNorm();
    const double y2 = y * y * l2;
    const double z2 = z * z * l2;
    const double k = (rr >= 0.0 ? 1.0 : -1.0) * rr * rr * x2;
    if ((z >= 0.0 ? 1.0 : -1.0) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - rb;
    if ((y >= 0.0 ? 1.0 : -1.0) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - ra;
    return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - ra;
}

double roundBox(const Vec3& p, const Vec3& c, const Vec3& h, double r) {
    const Vec3 q = (p - c).cwiseAbs() - h + Vec3::Constant(r);
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0) - r;
}

double smoothUnion(double a, double b, double k) {
    if (k <= 0.0) return std::min(a, b);
    const double h = std::max(k - std::abs(a - b), 0.0) / k;
    return std::min(a, b) - h * h * k * 0.25;
}

double smoothSubtract(double a, double b, double k) { return -smoothUnion(-a, b, k); }

}  // namespace ramus::sdf
