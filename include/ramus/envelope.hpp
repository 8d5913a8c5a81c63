// Envelopes and obstacles for space colonization (seed 002 §3.3, §4.3.2; SPEC §C): closed
// shapes that are filled with attraction points, or that remove points and block growth.
// Axes as in glTF: +Y is up. Lengths are model units (the seed uses cm).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ramus/file_util.hpp"
#include "ramus/math.hpp"

namespace ramus {

class MeshVolume;  // ramus/mesh_volume.hpp

/// The kinds of shape. "Anchor" is the point `Shape::offset` places:
enum class ShapeKind {
    Sphere,      ///< anchor = centre; `radius`
    Ellipsoid,   ///< anchor = centre; semi-axes `radii` (x, y, z)
    Box,         ///< anchor = centre; edge lengths `size` (x, y, z)
    Cylinder,    ///< anchor = centre of the bottom disc; axis +Y; `radius`, `height`
    Cone,        ///< anchor = centre of the base disc; apex `height` above it on +Y; `radius`
    Hemisphere,  ///< anchor = centre of the flat face; dome towards +Y; `radius`
    /// 2D (seed 002 fig 3.2): the disc r ≤ `radius` in the plane z = anchor.z, minus the hole
    /// r < `innerRadius` (0 = a full disc). As an obstacle it blocks the infinite prism along z
    /// (and must have innerRadius = 0).
    Disc,
    /// A closed triangle mesh (`mesh`, e.g. from readMeshVolume): a point p of the mesh file
    /// lies at offset + scale · p. Inside by the even-odd rule. Sampled by rejection in its
    /// bounding box, so sampleShape maps to the box only.
    Mesh,
};

/// Lower-case name as used in config files ("sphere", "ellipsoid", "box", "cylinder", "cone",
/// "hemisphere", "disc", "mesh").
const char* shapeKindName(ShapeKind kind);

/// A closed shape at an offset. Only the fields its kind names are used; all are model units
/// and must be finite, positive where used (innerRadius ≥ 0 and < radius).
struct Shape {
    ShapeKind kind = ShapeKind::Sphere;
    Vec3 offset = Vec3::Zero();  ///< where the anchor is (relative to the tree's origin)
    double radius = 1.0;
    double height = 1.0;
    double innerRadius = 0.0;
    Vec3 radii = Vec3::Ones();
    Vec3 size = Vec3::Ones();
    double scale = 1.0;                      ///< Mesh: factor on the file's coordinates (> 0)
    std::shared_ptr<const MeshVolume> mesh;  ///< Mesh: the closed surface (required)
};

/// Empty string when `shape` is valid, else a sentence naming the first bad field
/// (e.g. "radius must be > 0 (model units); got -2"; "mesh is missing" for a Mesh without one).
std::string validateShape(const Shape& shape);

/// Axis-aligned bounds of the shape (for a disc: zero thickness in z).
Aabb shapeBounds(const Shape& shape);

/// A convex "inside" function: ≤ 0 exactly on the closed shape, > 0 outside. Not a true
/// distance, but it grows with the distance. A disc with a hole is not convex: its value is
/// still ≤ 0 exactly on the annulus. A mesh gives −1 inside and +1 outside (no distance).
double shapeInsideValue(const Shape& shape, const Vec3& p);

/// True when p lies in the closed shape (for a disc: in the prism along z over the annulus).
bool shapeContains(const Shape& shape, const Vec3& p);

/// True when the segment [a, b] meets the closed shape. Exact up to ~1e-9 of the segment's
/// length (golden-section minimum of the convex inside function along the segment; for a disc
/// with a hole: meets the outer disc and is not wholly inside the hole; for a mesh: crosses or
/// touches its surface, or lies inside, see MeshVolume::segmentHits).
bool segmentHitsShape(const Shape& shape, const Vec3& a, const Vec3& b);

/// Maps three uniform numbers in [0, 1) to a point uniformly distributed in the shape's volume
/// (area for a disc). Pure function: the same numbers give the same point. For a mesh: a point
/// uniform in its bounding box (sampleEnvelope keeps only those inside).
Vec3 sampleShape(const Shape& shape, double u1, double u2, double u3);

/// An envelope: a shape to fill with `pointCount` attraction points drawn with its own `seed`
/// (seed 002 §4.3.2: same seed, same points).
struct Envelope {
    Shape shape;
    std::uint32_t pointCount = 1000;  ///< N; 0 gives no points
    std::uint64_t seed = 0;
};

/// The points of one envelope: pointCount points, each from three uniform numbers of
/// Rng::forStream(hashCombine(baseSeed, envelope.seed), 0). Same inputs, same points. A mesh
/// envelope draws points uniform in its bounding box and keeps those inside (rejection
/// sampling) until it has pointCount; after kMaxMeshDrawsPerPoint · pointCount draws it stops
/// with fewer (only a mesh filling less than ~1/10 000 of its box can get there).
std::vector<Vec3> sampleEnvelope(const Envelope& envelope, std::uint64_t baseSeed = 0);

/// Draws per requested point after which mesh rejection sampling gives up.
inline constexpr std::uint64_t kMaxMeshDrawsPerPoint = 10000;

/// The points of all envelopes, in envelope order, without those inside any obstacle
/// (removed, not replaced). No envelopes → empty.
std::vector<Vec3> sampleAttractionPoints(std::span<const Envelope> envelopes,
                                         std::span<const Shape> obstacles,
                                         std::uint64_t baseSeed = 0);

/// Removes the points that lie inside any obstacle, keeping the order of the others.
std::vector<Vec3> removePointsInside(std::span<const Vec3> points,
                                     std::span<const Shape> obstacles);

/// Reads attraction points from a text file, by extension (case-insensitive):
/// `.xyz`/`.txt` — "x y z" per line (more columns ignored; '#' comments, blank lines skipped);
/// `.csv` — "x,y,z" per line, an optional non-numeric header line;
/// `.ply` — ASCII PLY with a vertex element having float/double properties x, y, z.
/// Throws Error "file:line: what; expected …" on malformed input or non-finite values, and
/// when the file has more than `maxBytes` bytes (readFile).
std::vector<Vec3> readPointsFile(const std::string& path,
                                 std::size_t maxBytes = kMaxInputFileBytes);

/// Parses point text as readPointsFile does; `format` is "xyz", "csv" or "ply"; `fileName` is
/// used in error messages only.
std::vector<Vec3> parsePoints(const std::string& text, const std::string& format,
                              const std::string& fileName);

}  // namespace ramus
