// The spine: three cubic Béziers, the C1 fix where they meet, arc lengths and the sample
// points the vertebrae sit on.
//
// Based on: seed 000 §5.3 (vertebrae at t = i/n, arc-length parametrization p(t) = ∫‖B'‖ as
// the wished improvement, solved numerically), §7.4.2 and fig. 7.5 (control points next to a
// joint rotated by equal and opposite angles); SPEC §F. The arc length is integrated with
// adaptive Gauss–Kronrod G7–K15 quadrature (Piessens et al., QUADPACK, 1983); samples invert
// it with Newton's method from a table of 8 pieces.
#include <algorithm>
#include <cmath>

#include "ramus/error.hpp"
#include "skeleton/skeleton_build.hpp"

namespace ramus::detail {
namespace {

// Gauss–Kronrod G7–K15 on [−1, 1] (QUADPACK qk15): Kronrod nodes ±kNodes[i] and the centre;
// the 7-point Gauss rule uses the odd entries and the centre.
constexpr std::array<double, 7> kNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

constexpr int kMaxBisections = 48;
constexpr double kRelativeTolerance = 1e-11;
constexpr int kTablePieces = 8;

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

// ‖B'(t)‖ with B'(t) = 3 (a + t (b + t c)), a = P1 − P0, b = 2 (P2 − 2 P1 + P0),
// c = P3 − 3 P2 + 3 P1 − P0; plus the control polygon's length, an upper bound of the arc
// length that scales the tolerances.
struct Speed {
    explicit Speed(const Cubic& q)
        : a(q.p1 - q.p0),
          b(2.0 * (q.p2 - 2.0 * q.p1 + q.p0)),
          c(q.p3 - 3.0 * q.p2 + 3.0 * q.p1 - q.p0),
          scale((q.p1 - q.p0).norm() + (q.p2 - q.p1).norm() + (q.p3 - q.p2).norm()) {}
    double operator()(double t) const {
        const double x = a.x() + t * (b.x() + t * c.x());
        const double y = a.y() + t * (b.y() + t * c.y());
        return 3.0 * std::sqrt(x * x + y * y);
    }
    Vec2 a, b, c;
    double scale;
};

struct Estimate {
    double kronrod = 0.0, gauss = 0.0;
};

// The 15 Kronrod nodes as offsets from the centre: −kNodes[i] at i, +kNodes[i] at 7 + i, the
// centre at 14 (and 15, padding for whole packets).
constexpr std::array<double, 16> kNodeOffsets = {
    -kNodes[0], -kNodes[1], -kNodes[2], -kNodes[3], -kNodes[4], -kNodes[5], -kNodes[6], kNodes[0],
    kNodes[1],  kNodes[2],  kNodes[3],  kNodes[4],  kNodes[5],  kNodes[6],  0.0,        0.0};

Estimate gaussKronrod(const Speed& speed, double lo, double hi) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    // All 15 speeds at once as Eigen arrays (packed sqrt), with the same IEEE operations per node
    // as Speed::operator(): mid + half·(−k) is mid − half·k exactly, and mid + half·0 is mid
    // (mid is not −0, as lo < hi).
    using Nodes = Eigen::Array<double, 16, 1>;
    const Nodes t = mid + half * Eigen::Map<const Nodes>(kNodeOffsets.data());
    const Nodes x = speed.a.x() + t * (speed.b.x() + t * speed.c.x());
    const Nodes y = speed.a.y() + t * (speed.b.y() + t * speed.c.y());
    const Nodes v = 3.0 * (x * x + y * y).sqrt();
    const double centre = v[14];
    Estimate e{kKronrodWeights[7] * centre, kGaussWeights[3] * centre};
    for (std::size_t i = 0; i < kNodes.size(); ++i) {
        const auto minus = static_cast<Eigen::Index>(i);
        const double pair = v[minus] + v[minus + 7];
        e.kronrod += kKronrodWeights[i] * pair;
        if (i % 2 == 1) e.gauss += kGaussWeights[i / 2] * pair;
    }
    e.kronrod *= half;
    e.gauss *= half;
    return e;
}

// Bisects while the Gauss and Kronrod estimates disagree; smooth pieces stop at once, only a
// cusp (‖B'‖ = 0 inside, a kink in the integrand) needs deeper levels.
double adaptiveLength(const Speed& speed, double lo, double hi, double tolerance, int depth) {
    const Estimate e = gaussKronrod(speed, lo, hi);
    if (depth <= 0 || std::abs(e.kronrod - e.gauss) <= tolerance) return e.kronrod;
    const double mid = 0.5 * (lo + hi);
    return adaptiveLength(speed, lo, mid, 0.5 * tolerance, depth - 1) +
           adaptiveLength(speed, mid, hi, 0.5 * tolerance, depth - 1);
}

double lengthOf(const Speed& speed, double t0, double t1) {
    if (t0 == t1 || speed.scale == 0.0) return 0.0;
    if (t0 > t1) return -lengthOf(speed, t1, t0);
    return adaptiveLength(speed, t0, t1, kRelativeTolerance * speed.scale, kMaxBisections);
}

// Arc length over a short step of Newton's method: where ‖B'‖ is smooth, the 3-point
// Gauss–Legendre rule's error shrinks as the step's 6th power, far below the tolerance for steps
// under 1e-3 of the parameter range; longer steps take the adaptive rule.
double stepLength(const Speed& speed, double t0, double t1) {
    if (std::abs(t1 - t0) > 1e-3) return lengthOf(speed, t0, t1);
    const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
    const double offset = half * 0.774596669241483377035853079956480;  // √(3/5)
    return half *
           (8.0 / 9.0 * speed(mid) + 5.0 / 9.0 * (speed(mid - offset) + speed(mid + offset)));
}

// Cumulative arc lengths at kTablePieces + 1 evenly spaced parameters of [lo, hi].
struct ArcTable {
    std::array<double, kTablePieces + 1> t{}, s{};
    double total() const { return s.back(); }
};

ArcTable arcTable(const Speed& speed, double lo, double hi) {
    ArcTable table;
    for (int k = 0; k <= kTablePieces; ++k)
        table.t[k] = lo + (hi - lo) * (static_cast<double>(k) / kTablePieces);
    table.t.back() = hi;
    for (int k = 0; k < kTablePieces; ++k)
        table.s[k + 1] = table.s[k] + lengthOf(speed, table.t[k], table.t[k + 1]);
    return table;
}

// The t where the arc length from the table's start reaches `target` ∈ (0, total): the piece
// from the table, then Newton's method on s(t) with s' = ‖B'(t)‖ from a linear guess, kept
// inside the piece (bisection when a step leaves it or the speed vanishes). The integral is
// advanced from the previous iterate, so each step integrates only the correction.
double invert(const Speed& speed, const ArcTable& table, double target) {
    int k = 0;
    while (k + 1 < kTablePieces && table.s[k + 1] <= target) ++k;
    double lo = table.t[k], hi = table.t[k + 1];
    const double piece = table.s[k + 1] - table.s[k];
    double t = piece > 0.0 ? lo + (hi - lo) * ((target - table.s[k]) / piece) : lo;
    double reached = table.s[k] + lengthOf(speed, lo, t);
    const double tolerance = 1e-12 * std::max(speed.scale, 1e-300);
    for (int iteration = 0; iteration < 60; ++iteration) {
        const double excess = reached - target;
        if (std::abs(excess) <= tolerance) break;
        (excess > 0.0 ? hi : lo) = t;
        const double v = speed(t);
        double next = v > 0.0 ? t - excess / v : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (next == t) break;
        reached += stepLength(speed, t, next);
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
    return lengthOf(Speed(cubicOf(spine, part)), t0, t1);
}

double spineParameterAtLength(const Spine& spine, SpinePart part, double t0, double length) {
    if (length <= 0.0) return t0;
    const Speed speed(cubicOf(spine, part));
    const ArcTable table = arcTable(speed, t0, 1.0);
    return length >= table.total() ? 1.0 : invert(speed, table, length);
}

std::vector<double> spineSamples(const Spine& spine, SpinePart part, double from, double to, int n,
                                 SpineSpacing spacing) {
    RAMUS_ASSERT(n >= 1);
    std::vector<double> t(static_cast<std::size_t>(n) + 1);
    const Speed speed(cubicOf(spine, part));
    const double lo = std::min(from, to), hi = std::max(from, to);
    const ArcTable table =
        spacing == SpineSpacing::ArcLength ? arcTable(speed, lo, hi) : ArcTable{};
    if (spacing == SpineSpacing::Parameter || !(table.total() > 0.0)) {
        for (int i = 0; i <= n; ++i) t[i] = from + (to - from) * (static_cast<double>(i) / n);
    } else {
        // Equal arc length is symmetric: cut upwards from lo, reverse for a downward run.
        for (int i = 1; i < n; ++i) t[i] = invert(speed, table, table.total() * i / n);
        t[0] = lo;
        t[n] = hi;
        if (from > to) std::reverse(t.begin(), t.end());
    }
    t.front() = from;
    t.back() = to;
    return t;
}

double spineRootParameter(const Spine& spine, SpineSpacing spacing) {
    if (spacing == SpineSpacing::Parameter) return 0.5;
    const Speed speed(cubicOf(spine, SpinePart::Back));
    const ArcTable table = arcTable(speed, 0.0, 1.0);
    return table.total() > 0.0 ? invert(speed, table, 0.5 * table.total()) : 0.5;
}

}  // namespace ramus::detail
