// Based on: the even-odd (ray parity) point-in-polyhedron test (e.g. O'Rourke, "Computational
// Geometry in C", 2nd ed., §7.4), made consistent for rays through edges and vertices by
// evaluating every edge function in one canonical vertex order and breaking zeros with the
// symbolic perturbation (x + ε, y + ε²) of Edelsbrunner and Mücke, "Simulation of Simplicity"
// (1990); segment–triangle intersection after Möller and Trumbore, "Fast, Minimum Storage
// Ray/Triangle Intersection" (1997). SPEC §C (points inside a closed mesh; obstacles).
#include "ramus/mesh_volume.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "ramus/error.hpp"

namespace ramus {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

bool lexLess(const Vec3& a, const Vec3& b) {
    if (a.x() != b.x()) return a.x() < b.x();
    if (a.y() != b.y()) return a.y() < b.y();
    return a.z() < b.z();
}

// Merges vertices with identical coordinates (kept in lexicographic order); returns the new
// index of every old vertex.
std::vector<std::uint32_t> mergeEqualVertices(std::vector<Vec3>& vertices) {
    std::vector<std::uint32_t> order(vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return lexLess(vertices[a], vertices[b]);
    });
    std::vector<std::uint32_t> remap(vertices.size());
    std::vector<Vec3> merged;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Vec3& p = vertices[order[i]];
        if (merged.empty() || merged.back() != p) merged.push_back(p);
        remap[order[i]] = static_cast<std::uint32_t>(merged.size() - 1);
    }
    vertices = std::move(merged);
    return remap;
}

// Edges used by an odd number of triangles: where the surface is open.
std::size_t countBoundaryEdges(const std::vector<Triangle>& triangles) {
    std::vector<std::uint64_t> edges;
    edges.reserve(triangles.size() * 3);
    for (const Triangle& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = t[static_cast<std::size_t>(k)];
            const std::uint64_t b = t[static_cast<std::size_t>((k + 1) % 3)];
            edges.push_back(std::min(a, b) << 32 | std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    std::size_t boundary = 0;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        boundary += (j - i) % 2;
        i = j;
    }
    return boundary;
}

// The edge function of (px, py) against the directed edge a→b in the xy plane (> 0: left of
// it), and its sign with zeros broken by the perturbation (px + ε, py + ε²). The value is
// computed with the lexicographically smaller endpoint first, so the triangles sharing an edge
// see bitwise the same number (negated for the opposite direction); at a vertex it is exactly 0.
struct EdgeSide {
    double value;
    int sign;  // 0 only for an edge that is a single point in xy
};

EdgeSide edgeSide(const Vec3& a, const Vec3& b, double px, double py) {
    const bool swap = b.x() < a.x() || (b.x() == a.x() && b.y() < a.y());
    const Vec3& u = swap ? b : a;
    const Vec3& v = swap ? a : b;
    const double dx = v.x() - u.x(), dy = v.y() - u.y();  // dx ≥ 0; dy ≥ 0 when dx = 0
    const double e = dx * (py - u.y()) - dy * (px - u.x());
    int sign = 0;
    if (e != 0.0) {
        sign = e > 0.0 ? 1 : -1;
    } else if (dy != 0.0) {
        sign = dy > 0.0 ? -1 : 1;  // e(p + (ε, ε²)) = dx·ε² − dy·ε
    } else if (dx != 0.0) {
        sign = 1;
    }
    return swap ? EdgeSide{-e, -sign} : EdgeSide{e, sign};
}

// Möller–Trumbore with a small tolerance, so a segment through a shared edge or vertex hits at
// least one of the triangles there. A segment parallel to the triangle's plane does not hit it
// (its crossing into the volume is found on a neighbouring triangle).
bool segmentHitsTriangle(const Vec3& a, const Vec3& b, const Vec3& v0, const Vec3& v1,
                         const Vec3& v2) {
    constexpr double kTolerance = 1e-9;
    const Vec3 dir = b - a, e1 = v1 - v0, e2 = v2 - v0;
    const Vec3 pvec = dir.cross(e2);
    const double det = e1.dot(pvec);
    if (det == 0.0 || !std::isfinite(det)) return false;
    const double inv = 1.0 / det;
    const Vec3 tvec = a - v0;
    const double u = tvec.dot(pvec) * inv;
    if (u < -kTolerance || u > 1.0 + kTolerance) return false;
    const Vec3 qvec = tvec.cross(e1);
    const double v = dir.dot(qvec) * inv;
    if (v < -kTolerance || u + v > 1.0 + kTolerance) return false;
    const double t = e2.dot(qvec) * inv;
    return t >= -kTolerance && t <= 1.0 + kTolerance;
}

}  // namespace

MeshVolume::MeshVolume(std::vector<Vec3> vertices, std::vector<Triangle> triangles)
    : vertices_(std::move(vertices)) {
    for (const Vec3& p : vertices_) {
        if (!p.allFinite()) throw Error("a vertex coordinate is not finite");
    }
    for (const Triangle& t : triangles) {
        for (const std::uint32_t i : t) {
            if (i >= vertices_.size()) {
                throw Error("triangle vertex index " + std::to_string(i) + " is out of range; " +
                            "expected < " + std::to_string(vertices_.size()));
            }
        }
    }
    // Merge equal vertices, then drop triangles that collapsed to a segment (each such
    // triangle uses one of its edges twice, so the surface stays closed without it).
    const std::vector<std::uint32_t> remap = mergeEqualVertices(vertices_);
    triangles_.reserve(triangles.size());
    for (const Triangle& t : triangles) {
        const Triangle m{remap[t[0]], remap[t[1]], remap[t[2]]};
        if (m[0] != m[1] && m[1] != m[2] && m[2] != m[0]) triangles_.push_back(m);
    }
    if (triangles_.empty()) throw Error("the mesh has no triangles (with three distinct corners)");
    const std::size_t boundary = countBoundaryEdges(triangles_);
    if (boundary > 0) {
        throw Error("the mesh is not closed: " + std::to_string(boundary) +
                    " boundary edges (used by an odd number of triangles); expected a closed "
                    "surface that encloses a volume");
    }
    for (const Triangle& t : triangles_) {
        for (const std::uint32_t i : t) bounds_.add(vertices_[i]);
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (!(bounds_.max[axis] > bounds_.min[axis])) {
            throw Error(std::string("the mesh is flat along ") + "xyz"[axis] +
                        ": it encloses no volume");
        }
    }
    buildGrid();
}

int MeshVolume::cellX(double x) const {
    const double c = std::floor((x - bounds_.min.x()) / cellWidth_);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(gridX_ - 1)));
}

int MeshVolume::cellY(double y) const {
    const double c = std::floor((y - bounds_.min.y()) / cellHeight_);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(gridY_ - 1)));
}

void MeshVolume::buildGrid() {
    // About one cell per triangle, square-ish cells.
    const double wx = bounds_.max.x() - bounds_.min.x(), wy = bounds_.max.y() - bounds_.min.y();
    const double target = std::clamp(static_cast<double>(triangles_.size()), 1.0, 4.0e6);
    gridX_ = static_cast<int>(std::clamp(std::round(std::sqrt(target * wx / wy)), 1.0, 2048.0));
    gridY_ = static_cast<int>(std::clamp(std::round(target / gridX_), 1.0, 2048.0));
    cellWidth_ = wx / gridX_;
    cellHeight_ = wy / gridY_;
    // Widen each triangle's box a little so that rounding in cellX/cellY cannot miss it.
    const double marginX = 1e-7 * cellWidth_, marginY = 1e-7 * cellHeight_;
    auto forCells = [&](const Triangle& t, auto&& visit) {
        double x0 = vertices_[t[0]].x(), x1 = x0, y0 = vertices_[t[0]].y(), y1 = y0;
        for (const std::uint32_t i : t) {
            x0 = std::min(x0, vertices_[i].x()), x1 = std::max(x1, vertices_[i].x());
            y0 = std::min(y0, vertices_[i].y()), y1 = std::max(y1, vertices_[i].y());
        }
        for (int j = cellY(y0 - marginY); j <= cellY(y1 + marginY); ++j) {
            for (int i = cellX(x0 - marginX); i <= cellX(x1 + marginX); ++i) {
                visit(static_cast<std::size_t>(j) * static_cast<std::size_t>(gridX_) +
                      static_cast<std::size_t>(i));
            }
        }
    };
    const std::size_t cells = static_cast<std::size_t>(gridX_) * static_cast<std::size_t>(gridY_);
    cellStart_.assign(cells + 1, 0);
    for (const Triangle& t : triangles_) forCells(t, [&](std::size_t c) { ++cellStart_[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) cellStart_[c + 1] += cellStart_[c];
    cellTriangles_.resize(cellStart_[cells]);
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t k = 0; k < triangles_.size(); ++k) {
        forCells(triangles_[k],
                 [&](std::size_t c) { cellTriangles_[fill[c]++] = static_cast<std::uint32_t>(k); });
    }
}

bool MeshVolume::contains(const Vec3& p) const {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(p[axis] >= bounds_.min[axis] && p[axis] <= bounds_.max[axis])) return false;
    }
    const std::size_t cell = static_cast<std::size_t>(cellY(p.y())) * gridX_ + cellX(p.x());
    // Count the triangles the ray from p along +z passes (the perturbed ray, see edgeSide).
    int crossings = 0;
    for (std::uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
        const Triangle& t = triangles_[cellTriangles_[k]];
        const Vec3 &a = vertices_[t[0]], &b = vertices_[t[1]], &c = vertices_[t[2]];
        const EdgeSide ab = edgeSide(a, b, p.x(), p.y());
        if (ab.sign == 0) continue;
        const EdgeSide bc = edgeSide(b, c, p.x(), p.y());
        if (bc.sign != ab.sign) continue;
        const EdgeSide ca = edgeSide(c, a, p.x(), p.y());
        if (ca.sign != ab.sign) continue;
        // The edge functions are the barycentric weights of the opposite corners.
        const double sum = ab.value + bc.value + ca.value;
        if (sum == 0.0) continue;
        const double z = (bc.value * a.z() + ca.value * b.z() + ab.value * c.z()) / sum;
        if (z == p.z()) return true;  // on the surface, which belongs to the closed volume
        if (z > p.z()) ++crossings;
    }
    return crossings % 2 == 1;
}

bool MeshVolume::crossesSurface(const Vec3& a, const Vec3& b) const {
    const double marginX = 1e-7 * cellWidth_, marginY = 1e-7 * cellHeight_;
    const int i0 = cellX(std::min(a.x(), b.x()) - marginX);
    const int i1 = cellX(std::max(a.x(), b.x()) + marginX);
    const int j0 = cellY(std::min(a.y(), b.y()) - marginY);
    const int j1 = cellY(std::max(a.y(), b.y()) + marginY);
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const std::size_t cell = static_cast<std::size_t>(j) * gridX_ + i;
            for (std::uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
                const Triangle& t = triangles_[cellTriangles_[k]];
                if (segmentHitsTriangle(a, b, vertices_[t[0]], vertices_[t[1]], vertices_[t[2]])) {
                    return true;
                }
            }
        }
    }
    return false;
}

bool MeshVolume::segmentHits(const Vec3& a, const Vec3& b) const {
    // Box rejection, then the surface; a segment that does not cross it lies wholly inside or
    // wholly outside, which its first end point tells.
    for (int axis = 0; axis < 3; ++axis) {
        if (std::max(a[axis], b[axis]) < bounds_.min[axis] ||
            std::min(a[axis], b[axis]) > bounds_.max[axis]) {
            return false;
        }
    }
    return crossesSurface(a, b) || contains(a);
}

}  // namespace ramus
