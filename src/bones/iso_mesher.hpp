// Isosurface meshing of a signed-distance function (seed 000 §5.6: the default bone models).
//
// Based on: A. Doi and A. Koide, "An Efficient Method of Triangulating Equi-Valued Surfaces by
// Using Tetrahedral Cells", IEICE Trans. E74(1), 1991 (marching tetrahedra).
#pragma once

#include <array>
#include <functional>

#include "ramus/math.hpp"
#include "ramus/mesh.hpp"

namespace ramus {

/// Signed distance: negative inside, positive outside.
using DistanceFunction = std::function<double(const Vec3&)>;

/// Meshes the zero set of `distance` inside the box [lo, hi] on a regular grid of `cells`
/// cells per axis (each ≥ 1) with marching tetrahedra (Kuhn split of every cube along the same
/// diagonal, so the result is watertight). The grid is padded by one cell on every side, so a
/// surface inside [lo, hi] never touches the grid border and the mesh is closed. Triangles are
/// counter-clockwise seen from outside; normals are unit gradients of `distance` (central
/// differences). No vertex sits on a grid corner (values with |v| < ε are nudged to +ε), and
/// vertices keep at least 1 % of an edge away from its ends, so no triangle is degenerate.
/// An empty zero set gives an empty mesh.
Mesh meshIsosurface(const DistanceFunction& distance, const Vec3& lo, const Vec3& hi,
                    const std::array<int, 3>& cells);

/// The finest mesh of meshIsosurface within `maxTriangles` (≥ 1) on a grid of cubic cells
/// (the box grows to a whole number of them), at most `maxCellsLongest` cells along the longest
/// axis of [lo, hi]. The cell count is searched deterministically in quarter cells: from a guess
/// (a probe at 16 cells; counts grow with n²) down until the mesh fits, then up to two cells
/// finer, keeping the finest that fits (counts are not monotonic in the grid size). If even 2
/// cells are too many, the 2-cell mesh is returned.
Mesh meshIsosurfaceWithinBudget(const DistanceFunction& distance, const Vec3& lo, const Vec3& hi,
                                int maxTriangles, int maxCellsLongest);

}  // namespace ramus
