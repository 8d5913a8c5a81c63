// Based on: the incremental convex hull (de Berg, Cheong, van Kreveld, Overmars,
// "Computational Geometry", 3rd ed., §11.2), with a face scan instead of conflict lists.
//
// Robustness: callers perturb points so that no four are exactly coplanar at the scale of
// `epsilon`; a point within epsilon of every face it might see counts as inside. The horizon
// of a visible set must be one simple cycle; when rounding makes it anything else, build()
// reports failure instead of returning a broken surface.
#include "welded_hull.hpp"

#include <algorithm>
#include <cmath>

namespace ramus::detail {

std::int32_t ConvexHull::addFace(std::span<const Vec3> points, std::uint32_t a, std::uint32_t b,
                                 std::uint32_t c) {
    Face face;
    face.v = {a, b, c};
    face.neighbour = {-1, -1, -1};
    const Vec3 n = (points[b] - points[a]).cross(points[c] - points[a]);
    const double length = n.norm();
    face.normal = length > 0.0 ? Vec3(n / length) : Vec3::Zero();
    face.offset = face.normal.dot(points[a]);
    face.visibleStamp = 0;
    face.alive = true;
    faces_.push_back(face);
    return static_cast<std::int32_t>(faces_.size() - 1);
}

// Extreme points along x, then farthest from them, from their line and from their plane.
bool ConvexHull::initialSimplex(std::span<const Vec3> points, double epsilon) {
    std::uint32_t a = 0;
    for (std::uint32_t i = 1; i < points.size(); ++i) {
        if (points[i].x() < points[a].x()) a = i;
    }
    std::uint32_t b = a;
    double best = 0.0;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const double d = (points[i] - points[a]).squaredNorm();
        if (d > best) best = d, b = i;
    }
    if (best <= epsilon * epsilon) return false;
    const Vec3 axis = (points[b] - points[a]).normalized();
    std::uint32_t c = a;
    best = 0.0;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const Vec3 d = points[i] - points[a];
        const double off = (d - d.dot(axis) * axis).squaredNorm();
        if (off > best) best = off, c = i;
    }
    if (best <= epsilon * epsilon) return false;
    const Vec3 normal = (points[b] - points[a]).cross(points[c] - points[a]).normalized();
    std::uint32_t d = a;
    best = 0.0;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const double off = std::abs(normal.dot(points[i] - points[a]));
        if (off > best) best = off, d = i;
    }
    if (best <= epsilon) return false;
    if (normal.dot(points[d] - points[a]) > 0.0) std::swap(b, c);  // d below face (a, b, c)
    simplex_ = {a, b, c, d};
    const std::int32_t f0 = addFace(points, a, b, c);
    const std::int32_t f1 = addFace(points, a, d, b);
    const std::int32_t f2 = addFace(points, b, d, c);
    const std::int32_t f3 = addFace(points, c, d, a);
    live_ = {f0, f1, f2, f3};
    // Neighbours across each directed edge: the face holding the reversed edge.
    for (std::int32_t f : {f0, f1, f2, f3}) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t u = faces_[f].v[e];
            const std::uint32_t w = faces_[f].v[(e + 1) % 3];
            for (std::int32_t g : {f0, f1, f2, f3}) {
                for (int k = 0; k < 3; ++k) {
                    if (faces_[g].v[k] == w && faces_[g].v[(k + 1) % 3] == u) {
                        faces_[f].neighbour[e] = g;
                    }
                }
            }
        }
    }
    return true;
}

bool ConvexHull::addPoint(std::span<const Vec3> points, std::uint32_t p, double epsilon) {
    // Visible faces: the point lies more than epsilon above their plane.
    const std::uint32_t stamp = p + 1;
    visible_.clear();
    for (const std::int32_t f : live_) {
        Face& face = faces_[f];
        if (face.normal.dot(points[p]) - face.offset > epsilon) {
            face.visibleStamp = stamp;
            visible_.push_back(f);
        }
    }
    if (visible_.empty()) return true;  // inside (or on) the hull
    // Horizon: edges of visible faces whose neighbour is hidden; each becomes a new face.
    created_.clear();
    for (std::int32_t f : visible_) {
        for (int e = 0; e < 3; ++e) {
            const std::int32_t g = faces_[f].neighbour[e];
            if (faces_[g].visibleStamp == stamp) continue;
            const std::uint32_t u = faces_[f].v[e];
            const std::uint32_t w = faces_[f].v[(e + 1) % 3];
            if (startFace_[u] >= 0 || endFace_[w] >= 0) return false;  // not a simple cycle
            const std::int32_t h = addFace(points, u, w, p);
            faces_[h].neighbour[0] = g;
            for (int k = 0; k < 3; ++k) {
                if (faces_[g].neighbour[k] == f) faces_[g].neighbour[k] = h;
            }
            startFace_[u] = h;
            endFace_[w] = h;
            created_.push_back(h);
        }
    }
    for (std::int32_t f : visible_) faces_[f].alive = false;
    // The scan above passes over the dead faces (most of those made, as the hull grows).
    std::erase_if(live_, [&](std::int32_t f) { return !faces_[f].alive; });
    live_.insert(live_.end(), created_.begin(), created_.end());
    bool closed = true;
    for (std::int32_t h : created_) {
        const std::uint32_t u = faces_[h].v[0];
        const std::uint32_t w = faces_[h].v[1];
        faces_[h].neighbour[1] = startFace_[w];  // across (w, p)
        faces_[h].neighbour[2] = endFace_[u];    // across (p, u)
        closed = closed && startFace_[w] >= 0 && endFace_[u] >= 0;
    }
    for (std::int32_t h : created_) {
        startFace_[faces_[h].v[0]] = -1;
        endFace_[faces_[h].v[1]] = -1;
    }
    return closed;
}

bool ConvexHull::build(std::span<const Vec3> points, double epsilon) {
    faces_.clear();
    result_.clear();
    if (points.size() < 4 || !initialSimplex(points, epsilon)) return false;
    startFace_.assign(points.size(), -1);
    endFace_.assign(points.size(), -1);
    for (std::uint32_t p = 0; p < points.size(); ++p) {
        if (std::find(simplex_.begin(), simplex_.end(), p) != simplex_.end()) continue;
        if (!addPoint(points, p, epsilon)) return false;
    }
    collectFaces();
    return true;
}

bool ConvexHull::extend(std::span<const Vec3> points, std::uint32_t from, double epsilon) {
    result_.clear();
    startFace_.resize(points.size(), -1);
    endFace_.resize(points.size(), -1);
    for (std::uint32_t p = from; p < points.size(); ++p) {
        if (!addPoint(points, p, epsilon)) return false;
    }
    collectFaces();
    return true;
}

void ConvexHull::collectFaces() {
    for (const Face& face : faces_) {
        if (face.alive) result_.push_back(face.v);
    }
}

}  // namespace ramus::detail
