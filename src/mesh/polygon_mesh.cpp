// Based on: ABOP §5.1 (polygons `{ . }` recorded by the turtle, e.g. leaves); Newell's method
// for the plane of a polygon (Sutherland, Sproull, Schumacker 1974; Tampieri, Graphics Gems III
// "Newell's method for computing the plane equation of a polygon"); ear clipping (Meisters
// 1975, "Polygons have ears"); SPEC §D (optional leaves).
//
// Each polygon becomes one sheet: vertices of its own with the flat Newell normal, triangles
// counter-clockwise around that normal. The material is made doubleSided (a leaf must show
// from behind too) instead of emitting mirrored back faces, which would double the triangles
// and z-fight.
// UV rule: v runs from the polygon's first vertex (its base, v = 1) toward its farthest vertex
// (v = 0, the image's top in glTF's top-left UV origin), u across; both are scaled to 0..1 over
// the polygon's bounds in that frame, so a leaf texture fills the leaf. The tangent points to
// increasing u and cross(normal, tangent) to decreasing v, so w = +1 (glTF normal maps: +Y is
// image up).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "ramus/tube_mesher.hpp"

namespace ramus {
namespace {

// Plane frame of one polygon: unit normal (Newell), tangent (increasing u), bitangent
// (toward the far vertex); normal = tangent × bitangent.
struct PolygonFrame {
    Vec3 normal, tangent, bitangent;
};

// Returns false for polygons without area (collinear or coincident vertices).
bool polygonFrame(std::span<const Vec3> poly, PolygonFrame& frame) {
    Vec3 newell = Vec3::Zero();
    double far2 = 0.0;
    std::size_t farIndex = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec3& a = poly[i];
        const Vec3& b = poly[(i + 1) % poly.size()];
        newell += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                       (a.x() - b.x()) * (a.y() + b.y()));
        const double d2 = (a - poly[0]).squaredNorm();
        if (d2 > far2) {
            far2 = d2;
            farIndex = i;
        }
    }
    // |newell| is twice the area; compare with the squared size so the test is scale free.
    const double twiceArea = newell.norm();
    if (!(twiceArea > 1e-12 * far2) || far2 == 0.0) return false;
    frame.normal = newell / twiceArea;
    Vec3 up = poly[farIndex] - poly[0];
    up -= up.dot(frame.normal) * frame.normal;
    if (up.squaredNorm() <= 1e-12 * far2) {
        // Far vertex straight above the plane (strongly non-planar input): any in-plane axis.
        const Vec3 a = frame.normal.cwiseAbs();
        const int axis = a.x() <= a.y() && a.x() <= a.z() ? 0 : (a.y() <= a.z() ? 1 : 2);
        up = Vec3::Unit(axis) - frame.normal[axis] * frame.normal;
    }
    frame.bitangent = up.normalized();
    frame.tangent = frame.bitangent.cross(frame.normal);
    return true;
}

double cross2(const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Reusable buffers of the ear clipper (no allocation per polygon once they have grown).
struct EarClipper {
    std::vector<Vec2> points;
    std::vector<std::uint32_t> prev, next;

    bool isEar(std::uint32_t i, double eps) const;
    // Appends triangles (indices offset by `base`) counter-clockwise in the plane; points must
    // be a counter-clockwise polygon. Corners without area are dropped, not emitted.
    void triangulate(std::uint32_t base, double eps, std::vector<std::uint32_t>& out);
};

bool EarClipper::isEar(std::uint32_t i, double eps) const {
    const Vec2& a = points[prev[i]];
    const Vec2& b = points[i];
    const Vec2& c = points[next[i]];
    if (cross2(a, b, c) <= eps) return false;  // reflex or flat corner
    for (std::uint32_t j = next[next[i]]; j != prev[i]; j = next[j]) {
        const Vec2& p = points[j];
        if (p == a || p == b || p == c) continue;
        // Another vertex inside or on the candidate ear (on it would leave a T-junction).
        if (cross2(a, b, p) >= -eps && cross2(b, c, p) >= -eps && cross2(c, a, p) >= -eps) {
            return false;
        }
    }
    return true;
}

void EarClipper::triangulate(std::uint32_t base, double eps, std::vector<std::uint32_t>& out) {
    const auto m = static_cast<std::uint32_t>(points.size());
    prev.resize(m);
    next.resize(m);
    for (std::uint32_t i = 0; i < m; ++i) {
        prev[i] = (i + m - 1) % m;
        next[i] = (i + 1) % m;
    }
    std::uint32_t remaining = m;
    std::uint32_t cursor = 0;
    std::uint32_t misses = 0;  // vertices tried since the last clip
    while (remaining > 3) {
        const bool flat =
            std::abs(cross2(points[prev[cursor]], points[cursor], points[next[cursor]])) <= eps;
        // After a full round without an ear (self-intersecting or noisy input) clip anyway so
        // the loop always ends; every clip removes one vertex.
        const bool clip = flat || isEar(cursor, eps) || misses > remaining;
        if (!clip) {
            cursor = next[cursor];
            ++misses;
            continue;
        }
        if (!flat) out.insert(out.end(), {base + prev[cursor], base + cursor, base + next[cursor]});
        next[prev[cursor]] = next[cursor];
        prev[next[cursor]] = prev[cursor];
        cursor = prev[cursor];
        --remaining;
        misses = 0;
    }
    if (std::abs(cross2(points[prev[cursor]], points[cursor], points[next[cursor]])) > eps) {
        out.insert(out.end(), {base + prev[cursor], base + cursor, base + next[cursor]});
    }
}

// Appends one polygon's vertices (flat normal, tangent, UVs over its bounds in the plane frame)
// and its ear-clipped triangles.
void appendPolygon(std::span<const Vec3> poly, const PolygonFrame& frame, EarClipper& clipper,
                   Mesh& mesh) {
    // Plane coordinates (u along tangent, v along bitangent) and their bounds.
    clipper.points.clear();
    Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
    Vec2 hi = -lo;
    for (const Vec3& q : poly) {
        const Vec3 d = q - poly[0];
        const Vec2 xy(d.dot(frame.tangent), d.dot(frame.bitangent));
        clipper.points.push_back(xy);
        lo = lo.cwiseMin(xy);
        hi = hi.cwiseMax(xy);
    }
    const Vec2 size = (hi - lo).cwiseMax(Vec2::Constant(1e-300));
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    const Vec3f normal = frame.normal.cast<float>();
    const Vec4f tangent(static_cast<float>(frame.tangent.x()),
                        static_cast<float>(frame.tangent.y()),
                        static_cast<float>(frame.tangent.z()), 1.0f);
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2& xy = clipper.points[i];
        mesh.positions.push_back(poly[i].cast<float>());
        mesh.normals.push_back(normal);
        mesh.tangents.push_back(tangent);
        mesh.uvs.emplace_back(static_cast<float>((xy.x() - lo.x()) / size.x()),
                              static_cast<float>((hi.y() - xy.y()) / size.y()));
    }
    clipper.triangulate(base, 1e-12 * size.squaredNorm(), mesh.indices);
}

}  // namespace

Mesh buildPolygonMesh(std::span<const Vec3> vertices, std::span<const std::uint32_t> offsets,
                      const Material& material, std::vector<std::uint32_t>* vertexPolygons) {
    Mesh mesh;
    mesh.name = "leaves";
    const std::size_t polygons = offsets.empty() ? 0 : offsets.size() - 1;
    const std::size_t total =
        polygons == 0 ? 0 : std::min<std::size_t>(offsets.back(), vertices.size());
    mesh.positions.reserve(total);
    mesh.normals.reserve(total);
    mesh.tangents.reserve(total);
    mesh.uvs.reserve(total);
    mesh.indices.reserve(total * 3);
    EarClipper clipper;
    for (std::size_t p = 0; p < polygons; ++p) {
        const std::size_t begin = offsets[p];
        const std::size_t end = offsets[p + 1];
        if (end < begin + 3 || end > vertices.size()) continue;
        const std::span<const Vec3> poly = vertices.subspan(begin, end - begin);
        PolygonFrame frame;
        if (!polygonFrame(poly, frame)) continue;

        appendPolygon(poly, frame, clipper, mesh);
        if (vertexPolygons != nullptr) {
            vertexPolygons->resize(mesh.positions.size(), static_cast<std::uint32_t>(p));
        }
    }
    if (!mesh.indices.empty()) {
        Material sheet = material;
        sheet.doubleSided = true;
        mesh.materials.push_back(sheet);
        mesh.primitives.push_back(
            MeshPrimitive{0, static_cast<std::uint32_t>(mesh.indices.size()), 0, "leaves"});
    }
    return mesh;
}

}  // namespace ramus
