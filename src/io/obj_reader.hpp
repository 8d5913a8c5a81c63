// Reading Wavefront OBJ geometry: `v`, `vn` and `f` statements with located errors, shared by
// the readers that turn OBJ files into something else (colonization volumes, bone models).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/math.hpp"

namespace ramus::io {

/// One face corner: indices into ObjGeometry::positions and ObjGeometry::normals.
struct ObjCorner {
    std::uint32_t position = 0;
    std::int64_t normal = -1;  ///< -1: the corner names no normal
};

/// The geometry of an OBJ file, indices resolved (0-based).
struct ObjGeometry {
    std::vector<Vec3> positions;  ///< `v x y z` in file order
    /// The same coordinates each parsed as a float: the float nearest to the written decimal,
    /// which the double cast to float can miss by double rounding (so float files round-trip).
    std::vector<Vec3f> floatPositions;
    std::vector<Vec3f> normals;  ///< `vn x y z` in file order, parsed as floats
    std::vector<std::array<ObjCorner, 3>> triangles;  ///< `f`, polygons fan-triangulated
    std::vector<int> triangleLines;                   ///< the line of each triangle's `f`
};

/// Parses OBJ text: `v` and `vn` need three finite coordinates (a fourth `v` weight is ignored),
/// `f` at least three corners "i", "i/t", "i//n" or "i/t/n" (1-based, or negative counting back
/// from the latest vertex or normal); polygons are fan-triangulated. Other statements (vt, o, g,
/// s, usemtl, mtllib, l, p, …) and comments are ignored. Throws Error "FILE:LINE:COL: …" for a
/// malformed statement or an index that refers to nothing; `fileName` is used in messages only.
ObjGeometry parseObjGeometry(std::string_view text, const std::string& fileName);

}  // namespace ramus::io
