// Closed triangle meshes as volumes for space colonization (SPEC §C: "points sampled inside a
// closed mesh (OBJ/GLB)"; obstacles of any shape): an exact inside test and segment–surface
// intersection, both accelerated by a uniform grid over the triangles' xy projections.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ramus/file_util.hpp"
#include "ramus/math.hpp"

namespace ramus {

/// A closed triangle surface and the volume it encloses. Coordinates are the mesh's own (model
/// units). Immutable after construction; share it with std::shared_ptr<const MeshVolume>.
///
/// "Closed" means every edge is used by an even number of triangles (after merging vertices
/// with identical coordinates), so the surface bounds a volume; the orientation of the
/// triangles does not matter. The inside test counts the crossings of a ray along +z (even-odd
/// rule). Rays through edges and vertices are counted consistently (each edge function is
/// evaluated in one canonical vertex order, ties broken by the symbolic perturbation
/// (x + ε, y + ε²)), so the answer is exact for every point farther than rounding (~1e-15 of
/// the mesh size) from the surface; points on the surface may go either way.
class MeshVolume {
public:
    /// Builds the volume from vertices and triangles (indices into `vertices`). Vertices with
    /// identical coordinates are merged; triangles with two equal vertices are dropped. Throws
    /// Error with a sentence (no file name) when there are no triangles, a coordinate is not
    /// finite, an index is out of range, edges are open ("not closed: N boundary edges …"), or
    /// the mesh is flat along an axis (it encloses no volume).
    MeshVolume(std::vector<Vec3> vertices, std::vector<std::array<std::uint32_t, 3>> triangles);

    /// True when p lies inside the closed surface (even-odd rule). O(triangles in p's grid cell).
    bool contains(const Vec3& p) const;

    /// True when the segment [a, b] meets the closed volume: it crosses or touches the surface
    /// (within ~1e-9 of the triangles' size) or lies inside.
    bool segmentHits(const Vec3& a, const Vec3& b) const;

    /// Bounds of the (merged) vertices.
    const Aabb& bounds() const { return bounds_; }
    std::size_t triangleCount() const { return triangles_.size(); }
    std::size_t vertexCount() const { return vertices_.size(); }

private:
    bool crossesSurface(const Vec3& a, const Vec3& b) const;
    void buildGrid();
    int cellX(double x) const;
    int cellY(double y) const;

    std::vector<Vec3> vertices_;
    std::vector<std::array<std::uint32_t, 3>> triangles_;
    Aabb bounds_;
    // Uniform grid over the xy bounds: cell (i, j) lists, in cellTriangles_[cellStart_[c] ..
    // cellStart_[c + 1]), the triangles whose xy bounds (slightly widened) overlap it.
    int gridX_ = 1, gridY_ = 1;
    double cellWidth_ = 1.0, cellHeight_ = 1.0;
    std::vector<std::uint32_t> cellStart_, cellTriangles_;
};

/// Reads a closed mesh by extension (case-insensitive): `.obj` (Wavefront: `v` and `f` lines;
/// polygons are fan-triangulated, negative indices count back from the latest vertex, `vt`/`vn`
/// references and other statements are ignored), `.glb`/`.gltf` (every mesh of the scene,
/// placed by its node's world transform; meshes without nodes as they are). Throws Error
/// naming the file (and line for OBJ) when it cannot be read or parsed, or is not a closed
/// mesh (see MeshVolume), or has more than `maxBytes` bytes (readFile).
MeshVolume readMeshVolume(const std::string& path, std::size_t maxBytes = kMaxInputFileBytes);

/// Parses Wavefront OBJ text into a MeshVolume; `fileName` is used in error messages only.
MeshVolume parseObjVolume(const std::string& text, const std::string& fileName);

}  // namespace ramus
