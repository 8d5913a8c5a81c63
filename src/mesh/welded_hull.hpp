// A small incremental 3D convex hull for the junctions of the welded mesher.
//
// Based on: Clarkson and Shor 1989 / the textbook incremental hull (de Berg et al.,
// "Computational Geometry", §11.2) without conflict lists: junction point sets are small
// (tens to a few hundred points), so a scan over the faces per point is cheaper than keeping
// conflict graphs.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "ramus/math.hpp"

namespace ramus::detail {

/// Reusable hull builder; keeps its scratch arrays between calls (no allocation per call once
/// warmed up).
class ConvexHull {
public:
    /// Builds the hull of `points`; `epsilon` (model units, > 0) is the distance above a face
    /// at which a point counts as outside it. Returns false when the points span no volume or
    /// rounding broke the horizon (a point saw a non-disc set of faces): callers then fall
    /// back. Faces are counter-clockwise seen from outside.
    bool build(std::span<const Vec3> points, double epsilon);
    /// Adds points[from …] to the hull of the last successful build (or extend) of
    /// points[0, from): the same result as building the hull of all of them in that order.
    bool extend(std::span<const Vec3> points, std::uint32_t from, double epsilon);

    /// Faces of the last successful build (indices into its points).
    const std::vector<std::array<std::uint32_t, 3>>& faces() const { return result_; }

private:
    struct Face {
        std::array<std::uint32_t, 3> v;
        std::array<std::int32_t, 3> neighbour;  // across edge (v[e], v[e+1])
        Vec3 normal;
        double offset;
        std::uint32_t visibleStamp;
        bool alive;
    };

    bool initialSimplex(std::span<const Vec3> points, double epsilon);
    std::int32_t addFace(std::span<const Vec3> points, std::uint32_t a, std::uint32_t b,
                         std::uint32_t c);
    bool addPoint(std::span<const Vec3> points, std::uint32_t p, double epsilon);
    void collectFaces();

    std::vector<Face> faces_;
    std::vector<std::int32_t> startFace_;  // per point: new face whose horizon edge starts there
    std::vector<std::int32_t> endFace_;    // per point: new face whose horizon edge ends there
    std::vector<std::int32_t> live_;       // the alive faces, in index order
    std::vector<std::int32_t> visible_;
    std::vector<std::int32_t> created_;
    std::vector<std::array<std::uint32_t, 3>> result_;
    std::array<std::uint32_t, 4> simplex_{};
};

}  // namespace ramus::detail
