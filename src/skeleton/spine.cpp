// The spine: three cubic Béziers, the C1 fix where they meet, arc lengths and the sample
// points the vertebrae sit on.
//
// Based on: seed 000 §5.3 (vertebrae at t = i/n, arc-length parametrization p(t) = ∫‖B'‖ as
// the wished improvement, solved numerically), §7.4.2 and fig. 7.5 (control points next to a
// joint rotated by equal and opposite angles); SPEC §F. The arc length is integrated with
// adaptive 10-point Gauss–Legendre quadrature.
#include <algorithm>
#include <cmath>

#include "ramus/error.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

// Gauss–Legendre nodes and weights on [−1, 1], 10 points (symmetric pairs).
constexpr std::array<double, 5> kGaussNodes = {
    0.1488743389816312108848260, 0.4333953941292471907992659, 0.6794095682990244062343274,
    0.8650633666889845107320967, 0.9739065285171717200779640};
constexpr std::array<double, 5> kGaussWeights = {
    0.2955242247147528701738930, 0.2692667193099963550912269, 0.2190863625159820439955349,
    0.1494513491505805931457763, 0.0666713443086881375935688};

constexpr int kMaxBisections = 48;
constexpr double kRelativeTolerance = 1e-13;

struct Cubic {
    Vec2 p0, p1, p2, p3;
};

Cubic cubicOf(const Spine& spine, SpinePart part) {
    const int first = 3 * static_cast<int>(part);
    return {spine.points[first], spine.points[first + 1], spine.points[first + 2],
            spine.points[first + 3]};
}

Vec2 derivativeOf(const Cubic& c, double t) {
    const double u = 1.0 - t;
    return 3.0 * (u * u * (c.p1 - c.p0) + 2.0 * u * t * (c.p2 - c.p1) + t * t * (c.p3 - c.p2));
}

double speedOf(const Cubic& c, double t) { return derivativeOf(c, t).norm(); }

// Upper bound of the arc length: the control polygon's length.
double polygonLength(const Cubic& c) {
    return (c.p1 - c.p0).norm() + (c.p2 - c.p1).norm() + (c.p3 - c.p2).norm();
}

double gaussLegendre(const Cubic& c, double a, double b) {
    const double mid = 0.5 * (a + b);
    const double half = 0.5 * (b - a);
    double sum = 0.0;
    for (std::size_t i = 0; i < kGaussNodes.size(); ++i) {
        const double d = half * kGaussNodes[i];
        sum += kGaussWeights[i] * (speedOf(c, mid - d) + speedOf(c, mid + d));
    }
    return sum * half;
}

// Bisects until the two halves agree with the whole; the 10-point rule is exact for
// polynomials of degree 19, so smooth pieces stop at once and only a cusp (‖B'‖ = 0 inside)
// needs deeper levels.
double adaptiveLength(const Cubic& c, double a, double b, double whole, double tolerance,
                      int depth) {
    const double mid = 0.5 * (a + b);
    const double left = gaussLegendre(c, a, mid);
    const double right = gaussLegendre(c, mid, b);
    if (depth <= 0 || std::abs(left + right - whole) <= tolerance) return left + right;
    return adaptiveLength(c, a, mid, left, 0.5 * tolerance, depth - 1) +
           adaptiveLength(c, mid, b, right, 0.5 * tolerance, depth - 1);
}

double lengthOf(const Cubic& c, double t0, double t1) {
    if (t0 == t1) return 0.0;
    if (t0 > t1) return -lengthOf(c, t1, t0);
    const double scale = polygonLength(c);
    if (scale == 0.0) return 0.0;
    const double tolerance = kRelativeTolerance * scale;
    return adaptiveLength(c, t0, t1, gaussLegendre(c, t0, t1), tolerance, kMaxBisections);
}

// The t in [t0, end] where ∫_{t0}^{t} ‖B'‖ = length, given rest = ∫_{t0}^{end} ‖B'‖: Newton's
// method with s' = ‖B'(t)‖, kept inside a shrinking bracket [lo, hi] (bisection when a step
// leaves it or the speed vanishes). The integral is advanced from the previous iterate, so
// the late (short) steps cost one quadrature each.
double parameterAtLength(const Cubic& c, double t0, double length, double end, double rest) {
    if (length <= 0.0) return t0;
    if (length >= rest) return end;
    const double tolerance = 1e-12 * std::max(polygonLength(c), 1e-300);
    double lo = t0, hi = end;
    double t = t0 + (end - t0) * (length / rest);
    double reached = lengthOf(c, t0, t);
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double excess = reached - length;
        if (std::abs(excess) <= tolerance) break;
        (excess > 0.0 ? hi : lo) = t;
        const double speed = speedOf(c, t);
        double next = speed > 0.0 ? t - excess / speed : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (next == t) break;
        reached += lengthOf(c, t, next);
        t = next;
    }
    return t;
}

// The nearest control point on one side of the joint `joint` (step −1: towards P0, +1:
// towards P9) that does not coincide with it, within the same Bézier; −1 when there is none.
int distinctNeighbour(const std::array<Vec2, kSpinePointCount>& p, int joint, int step) {
    const double tolerance = 1e-9 * (1.0 + p[joint].cwiseAbs().maxCoeff());
    for (int k = 1; k <= 3; ++k) {
        const int i = joint + step * k;
        if ((p[i] - p[joint]).norm() > tolerance) return i;
    }
    return -1;
}

Vec2 rotatedAbout(const Vec2& point, const Vec2& center, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec2 d = point - center;
    return center + Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
}

// The C1 fix at one joint (seed 000 §7.4.2): the curve arrives in direction u and leaves in
// direction v; rotating the arriving control point by +δ/2 and the leaving one by −δ/2 about
// the joint (δ = the signed angle from u to v) turns both onto the bisector. The control
// points keep their distances, so the fix moves the curves as little as a rotation can. A side
// without a distinct control point (a missing neck or tail) has no tangent: nothing to fix.
void alignTangentsAt(std::array<Vec2, kSpinePointCount>& p, int joint) {
    const int before = distinctNeighbour(p, joint, -1);
    const int after = distinctNeighbour(p, joint, +1);
    if (before < 0 || after < 0) return;
    const Vec2 u = (p[joint] - p[before]).normalized();
    const Vec2 v = (p[after] - p[joint]).normalized();
    const double delta = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
    if (delta == 0.0) return;
    p[before] = rotatedAbout(p[before], p[joint], 0.5 * delta);
    p[after] = rotatedAbout(p[after], p[joint], -0.5 * delta);
}

}  // namespace

Spine makeSpine(const SkeletonFeatures& features) {
    Spine spine;
    spine.points = features.spine;
    alignTangentsAt(spine.points, 3);
    alignTangentsAt(spine.points, 6);
    const double back = spineLength(spine, SpinePart::Back);
    const double threshold = std::max(kMinSpinePartPx, kMinSpinePartFraction * back);
    spine.hasNeck = spineLength(spine, SpinePart::Neck) >= threshold;
    spine.hasTail = spineLength(spine, SpinePart::Tail) >= threshold;
    return spine;
}

Vec2 spinePoint(const Spine& spine, SpinePart part, double t) {
    const Cubic c = cubicOf(spine, part);
    const double u = 1.0 - t;
    return u * u * u * c.p0 + 3.0 * u * u * t * c.p1 + 3.0 * u * t * t * c.p2 + t * t * t * c.p3;
}

Vec2 spineDerivative(const Spine& spine, SpinePart part, double t) {
    return derivativeOf(cubicOf(spine, part), t);
}

double spineLength(const Spine& spine, SpinePart part, double t0, double t1) {
    return lengthOf(cubicOf(spine, part), t0, t1);
}

double spineParameterAtLength(const Spine& spine, SpinePart part, double t0, double length) {
    const Cubic c = cubicOf(spine, part);
    return parameterAtLength(c, t0, length, 1.0, lengthOf(c, t0, 1.0));
}

std::vector<double> spineSamples(const Spine& spine, SpinePart part, double from, double to, int n,
                                 SpineSpacing spacing) {
    RAMUS_ASSERT(n >= 1);
    std::vector<double> t(static_cast<std::size_t>(n) + 1);
    const Cubic c = cubicOf(spine, part);
    const double lo = std::min(from, to), hi = std::max(from, to);
    const double total = lengthOf(c, lo, hi);
    if (spacing == SpineSpacing::Parameter || total <= 0.0) {
        for (int i = 0; i <= n; ++i) t[i] = from + (to - from) * (static_cast<double>(i) / n);
    } else {
        // Equal arc length is symmetric: march upwards from lo, reverse for a downward run.
        const double step = total / n;
        t[0] = lo;
        double rest = total;
        for (int i = 1; i < n; ++i) {
            t[i] = parameterAtLength(c, t[i - 1], step, hi, rest);
            rest -= step;
        }
        t[n] = hi;
        if (from > to) std::reverse(t.begin(), t.end());
    }
    t.front() = from;
    t.back() = to;
    return t;
}

double spineRootParameter(const Spine& spine, SpineSpacing spacing) {
    if (spacing == SpineSpacing::Parameter) return 0.5;
    return spineParameterAtLength(spine, SpinePart::Back, 0.0,
                                  0.5 * spineLength(spine, SpinePart::Back));
}

}  // namespace ramus::detail
