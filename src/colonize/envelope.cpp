// Based on: seed 002 §3.3 and §4.3.2 (envelopes filled with N random points, each with its own
// seed; sphere and cylinder), SPEC §C (box, ellipsoid, cone, hemisphere, obstacles); uniform
// volume sampling by inverse transform (e.g. Pharr, Jakob, Humphreys, "Physically Based
// Rendering", 4th ed., §A.5: uniform sphere and disc sampling); rejection sampling in the
// bounding box for closed meshes (MeshVolume, mesh_volume.cpp).
#include "ramus/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ramus/mesh_volume.hpp"
#include "ramus/rng.hpp"

namespace ramus {

const char* shapeKindName(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::Sphere:
            return "sphere";
        case ShapeKind::Ellipsoid:
            return "ellipsoid";
        case ShapeKind::Box:
            return "box";
        case ShapeKind::Cylinder:
            return "cylinder";
        case ShapeKind::Cone:
            return "cone";
        case ShapeKind::Hemisphere:
            return "hemisphere";
        case ShapeKind::Disc:
            return "disc";
        case ShapeKind::Mesh:
            return "mesh";
    }
    return "?";
}

namespace {

std::string positiveMessage(const char* field, double value) {
    std::ostringstream out;
    out << field << " must be a finite number > 0 (model units); got " << value;
    return out.str();
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

bool usesRadius(ShapeKind k) {
    return k == ShapeKind::Sphere || k == ShapeKind::Cylinder || k == ShapeKind::Cone ||
           k == ShapeKind::Hemisphere || k == ShapeKind::Disc;
}

bool usesHeight(ShapeKind k) { return k == ShapeKind::Cylinder || k == ShapeKind::Cone; }

// Horizontal (xz) distance of p from the vertical axis through c.
double axisDistance(const Vec3& p, const Vec3& c) {
    return std::hypot(p.x() - c.x(), p.z() - c.z());
}

// A point of the world in the mesh file's coordinates.
Vec3 toMeshCoordinates(const Shape& s, const Vec3& p) { return (p - s.offset) / s.scale; }

}  // namespace

std::string validateShape(const Shape& s) {
    if (!s.offset.allFinite()) return "offset must be three finite numbers";
    if (s.kind == ShapeKind::Mesh) {
        if (!s.mesh) return "mesh is missing (a closed triangle mesh is required)";
        if (!positive(s.scale)) {
            std::ostringstream out;
            out << "scale must be a finite number > 0 (factor); got " << s.scale;
            return out.str();
        }
    }
    if (usesRadius(s.kind) && !positive(s.radius)) return positiveMessage("radius", s.radius);
    if (usesHeight(s.kind) && !positive(s.height)) return positiveMessage("height", s.height);
    if (s.kind == ShapeKind::Ellipsoid) {
        for (int i = 0; i < 3; ++i) {
            if (!positive(s.radii[i])) return positiveMessage("each of radii", s.radii[i]);
        }
    }
    if (s.kind == ShapeKind::Box) {
        for (int i = 0; i < 3; ++i) {
            if (!positive(s.size[i])) return positiveMessage("each of size", s.size[i]);
        }
    }
    if (s.kind == ShapeKind::Disc &&
        !(std::isfinite(s.innerRadius) && s.innerRadius >= 0.0 && s.innerRadius < s.radius)) {
        std::ostringstream out;
        out << "inner_radius must be >= 0 and < radius " << s.radius << " (model units); got "
            << s.innerRadius;
        return out.str();
    }
    return {};
}

Aabb shapeBounds(const Shape& s) {
    Aabb box;
    const Vec3& c = s.offset;
    switch (s.kind) {
        case ShapeKind::Sphere:
            box.add(c - Vec3::Constant(s.radius));
            box.add(c + Vec3::Constant(s.radius));
            break;
        case ShapeKind::Ellipsoid:
            box.add(c - s.radii);
            box.add(c + s.radii);
            break;
        case ShapeKind::Box:
            box.add(c - 0.5 * s.size);
            box.add(c + 0.5 * s.size);
            break;
        case ShapeKind::Cylinder:
        case ShapeKind::Cone:
            box.add(c - Vec3(s.radius, 0.0, s.radius));
            box.add(c + Vec3(s.radius, s.height, s.radius));
            break;
        case ShapeKind::Hemisphere:
            box.add(c - Vec3(s.radius, 0.0, s.radius));
            box.add(c + Vec3::Constant(s.radius));
            break;
        case ShapeKind::Disc:
            box.add(c - Vec3(s.radius, s.radius, 0.0));
            box.add(c + Vec3(s.radius, s.radius, 0.0));
            break;
        case ShapeKind::Mesh:
            if (s.mesh) {
                box.add(c + s.scale * s.mesh->bounds().min);
                box.add(c + s.scale * s.mesh->bounds().max);
            }
            break;
    }
    return box;
}

double shapeInsideValue(const Shape& s, const Vec3& p) {
    const Vec3 d = p - s.offset;
    switch (s.kind) {
        case ShapeKind::Sphere:
            return d.norm() - s.radius;
        case ShapeKind::Ellipsoid:
            return d.cwiseQuotient(s.radii).norm() - 1.0;
        case ShapeKind::Box:
            return (d.cwiseAbs() - 0.5 * s.size).maxCoeff();
        case ShapeKind::Cylinder:
            return std::max({axisDistance(p, s.offset) - s.radius, -d.y(), d.y() - s.height});
        case ShapeKind::Cone:
            return std::max({axisDistance(p, s.offset) - s.radius * (1.0 - d.y() / s.height),
                             -d.y(), d.y() - s.height});
        case ShapeKind::Hemisphere:
            return std::max(d.norm() - s.radius, -d.y());
        case ShapeKind::Disc: {
            const double r = std::hypot(d.x(), d.y());
            return std::max(r - s.radius, s.innerRadius - r);
        }
        case ShapeKind::Mesh:
            return s.mesh && s.mesh->contains(toMeshCoordinates(s, p)) ? -1.0 : 1.0;
    }
    return 1.0;
}

bool shapeContains(const Shape& s, const Vec3& p) { return shapeInsideValue(s, p) <= 0.0; }

namespace {

// Minimum of the convex inside function of the shape without its hole along [a, b] is ≤ 0.
bool segmentHitsConvexPart(const Shape& s, const Vec3& a, const Vec3& b) {
    Shape outer = s;
    outer.innerRadius = 0.0;
    auto f = [&](double t) { return shapeInsideValue(outer, a + t * (b - a)); };
    if (f(0.0) <= 0.0 || f(1.0) <= 0.0) return true;
    // Golden-section search; a convex function has no other local minimum to get stuck in.
    constexpr double kInvPhi = 0.6180339887498949;
    double lo = 0.0, hi = 1.0;
    double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
    double f1 = f(x1), f2 = f(x2);
    for (int i = 0; i < 60 && f1 > 0.0 && f2 > 0.0; ++i) {
        if (f1 < f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - kInvPhi * (hi - lo), f1 = f(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + kInvPhi * (hi - lo), f2 = f(x2);
        }
    }
    return f1 <= 0.0 || f2 <= 0.0;
}

}  // namespace

bool segmentHitsShape(const Shape& s, const Vec3& a, const Vec3& b) {
    // Cheap rejection: the segment's box misses the shape's box (a disc blocks along all z).
    const Aabb bounds = shapeBounds(s);
    const int axes = s.kind == ShapeKind::Disc ? 2 : 3;
    for (int i = 0; i < axes; ++i) {
        if (std::max(a[i], b[i]) < bounds.min[i] || std::min(a[i], b[i]) > bounds.max[i]) {
            return false;
        }
    }
    if (s.kind == ShapeKind::Mesh) {
        return s.mesh && s.mesh->segmentHits(toMeshCoordinates(s, a), toMeshCoordinates(s, b));
    }
    if (!segmentHitsConvexPart(s, a, b)) return false;
    if (s.kind != ShapeKind::Disc || s.innerRadius <= 0.0) return true;
    // Annulus: the segment misses it only when it lies wholly in the (convex) hole.
    auto inHole = [&](const Vec3& p) {
        return std::hypot(p.x() - s.offset.x(), p.y() - s.offset.y()) < s.innerRadius;
    };
    return !(inHole(a) && inHole(b));
}

Vec3 sampleShape(const Shape& s, double u1, double u2, double u3) {
    const double phi = 2.0 * kPi * u2;
    switch (s.kind) {
        case ShapeKind::Sphere:
        case ShapeKind::Ellipsoid:
        case ShapeKind::Hemisphere: {
            // Radius by the cube root (volume grows with r³), direction uniform on the sphere;
            // the hemisphere takes cos θ ∈ [0, 1) only.
            const double r = std::cbrt(u1);
            const double cosTheta = s.kind == ShapeKind::Hemisphere ? u3 : 1.0 - 2.0 * u3;
            const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
            const Vec3 unit(r * sinTheta * std::cos(phi), r * cosTheta,
                            r * sinTheta * std::sin(phi));
            const Vec3 scale = s.kind == ShapeKind::Ellipsoid ? s.radii : Vec3::Constant(s.radius);
            return s.offset + unit.cwiseProduct(scale);
        }
        case ShapeKind::Box:
            return s.offset + Vec3(u1 - 0.5, u2 - 0.5, u3 - 0.5).cwiseProduct(s.size);
        case ShapeKind::Cylinder: {
            const double r = s.radius * std::sqrt(u1);
            return s.offset + Vec3(r * std::cos(phi), s.height * u3, r * std::sin(phi));
        }
        case ShapeKind::Cone: {
            // Height with density ∝ (1 - y/h)²: y = h (1 - ∛(1 - u)); radius there R ∛(1 - u).
            const double c = std::cbrt(1.0 - u3);
            const double r = s.radius * c * std::sqrt(u1);
            return s.offset + Vec3(r * std::cos(phi), s.height * (1.0 - c), r * std::sin(phi));
        }
        case ShapeKind::Disc: {
            const double r2 = s.innerRadius * s.innerRadius;
            const double r = std::sqrt(r2 + u1 * (s.radius * s.radius - r2));
            return s.offset + Vec3(r * std::cos(phi), r * std::sin(phi), 0.0);
        }
        case ShapeKind::Mesh: {
            const Aabb box = shapeBounds(s);
            if (box.empty()) return s.offset;
            return box.min + Vec3(u1, u2, u3).cwiseProduct(box.extent());
        }
    }
    return s.offset;
}

namespace {

// Rejection sampling: uniform in the bounding box, kept when inside, so uniform in the volume.
std::vector<Vec3> sampleMeshEnvelope(const Envelope& envelope, Rng& rng) {
    std::vector<Vec3> points;
    if (!envelope.shape.mesh) return points;
    points.reserve(envelope.pointCount);
    const std::uint64_t maxDraws = kMaxMeshDrawsPerPoint * envelope.pointCount;
    for (std::uint64_t draw = 0; draw < maxDraws && points.size() < envelope.pointCount; ++draw) {
        const double u1 = rng.uniform01();
        const double u2 = rng.uniform01();
        const double u3 = rng.uniform01();
        const Vec3 p = sampleShape(envelope.shape, u1, u2, u3);
        if (shapeContains(envelope.shape, p)) points.push_back(p);
    }
    return points;
}

}  // namespace

std::vector<Vec3> sampleEnvelope(const Envelope& envelope, std::uint64_t baseSeed) {
    Rng rng = Rng::forStream(hashCombine(baseSeed, envelope.seed), 0);
    if (envelope.shape.kind == ShapeKind::Mesh) return sampleMeshEnvelope(envelope, rng);
    std::vector<Vec3> points;
    points.reserve(envelope.pointCount);
    for (std::uint32_t i = 0; i < envelope.pointCount; ++i) {
        const double u1 = rng.uniform01();
        const double u2 = rng.uniform01();
        const double u3 = rng.uniform01();
        points.push_back(sampleShape(envelope.shape, u1, u2, u3));
    }
    return points;
}

std::vector<Vec3> sampleAttractionPoints(std::span<const Envelope> envelopes,
                                         std::span<const Shape> obstacles, std::uint64_t baseSeed) {
    std::vector<Vec3> all;
    for (const Envelope& e : envelopes) {
        const std::vector<Vec3> points = sampleEnvelope(e, baseSeed);
        all.insert(all.end(), points.begin(), points.end());
    }
    if (obstacles.empty()) return all;
    return removePointsInside(all, obstacles);
}

std::vector<Vec3> removePointsInside(std::span<const Vec3> points,
                                     std::span<const Shape> obstacles) {
    std::vector<Vec3> kept;
    kept.reserve(points.size());
    for (const Vec3& p : points) {
        const bool inside = std::any_of(obstacles.begin(), obstacles.end(),
                                        [&](const Shape& o) { return shapeContains(o, p); });
        if (!inside) kept.push_back(p);
    }
    return kept;
}

}  // namespace ramus
