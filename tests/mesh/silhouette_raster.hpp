// Binary silhouettes of meshes for the tests: orthographic views along the coordinate axes,
// triangles rasterized by edge functions in double precision (which pixel centres a mesh
// covers, which pixel squares it touches), and the exact Euclidean distance transform of a
// mask (Felzenszwalb & Huttenlocher 2012).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ramus/math.hpp"
#include "ramus/mesh.hpp"

namespace ramus::test {

/// An orthographic view along a coordinate axis: world (u, v) = (p[axisU], p[axisV]) maps to
/// pixel coordinates x = (u - u0) / pixel, y = (v0 - v) / pixel (rows top to bottom, v up);
/// pixel (i, j) has its centre at (i + 0.5, j + 0.5).
struct Camera {
    int axisU = 2, axisV = 1;
    double u0 = 0.0, v0 = 0.0, pixel = 1.0;
    int width = 0, height = 0;
    Vec2 project(const Vec3& p) const { return {(p[axisU] - u0) / pixel, (v0 - p[axisV]) / pixel}; }
    /// World (u, v) of the centre of pixel (x, y).
    Vec2 worldAt(std::size_t x, std::size_t y) const {
        return {u0 + (double(x) + 0.5) * pixel, v0 - (double(y) + 0.5) * pixel};
    }
};

/// A camera looking along coordinate axis `axis` (0 = x: z right, y up; 1 = y: x right, z up;
/// 2 = z: x right, y up), framing `box` plus `margin` × its longer side on every side with
/// square pixels, `resolution` of them along the longer side.
Camera fitCamera(const Aabb& box, int axis, int resolution, double margin);

/// Whether `box` projects inside the frame (no pixel of it clipped off).
bool insideFrame(const Camera& camera, const Aabb& box);

/// A binary image.
struct Mask {
    int width = 0, height = 0;
    std::vector<std::uint8_t> covered;  ///< width × height, row-major; 1 = covered
    std::size_t area() const;           ///< covered pixels
};

/// A mesh's silhouette twice: the pixels whose centre it covers, and the pixels whose square it
/// touches (conservative: a twig thinner than a pixel leaves no gaps there).
struct Silhouette {
    Mask centres, touched;
};

/// Both silhouettes of `mesh` seen by `camera`; triangles of either winding count, triangles
/// without area are skipped.
Silhouette rasterize(const Mesh& mesh, const Camera& camera);

/// Squared distance (pixels²) from every pixel to the nearest covered pixel of a mask, and
/// that pixel's index (y · width + x).
struct DistanceField {
    std::vector<double> squared;
    std::vector<int> nearest;
};

/// Exact Euclidean distance transform of `mask` (linear in its pixel count); pixels of an
/// empty mask get about 1e20.
DistanceField distanceTo(const Mask& mask);

}  // namespace ramus::test
