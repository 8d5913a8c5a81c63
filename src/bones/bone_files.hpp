// Bone model meshes as files (docs/bones.md "User bone libraries"): reading a model's mesh from
// OBJ, glTF or GLB, the checks every loaded model passes, and the OBJ text a library is written
// as. Internal to the bones module (and its tests).
#pragma once

#include <string>
#include <vector>

#include "ramus/mesh.hpp"

namespace ramus::detail {

/// The mesh of a bone model file by extension (case-insensitive): `.obj` (positions, normals,
/// triangles; the vertices are the distinct position/normal pairs the faces use, in ascending
/// index order, so a file written by boneMeshObj reads back identical) or `.gltf`/`.glb` (every
/// mesh of the scene placed by its node's world transform, merged). Normals the file lacks (any
/// corner without one) are computed, area-weighted over vertices at equal positions. Then
/// checked by checkBoneMesh. The mesh is named `name`. Throws Error naming the file (and the OBJ
/// line) when it cannot be read, parsed or fails a check.
Mesh readBoneMesh(const std::string& path, const std::string& name);

/// Throws Error "FILE[:LINE]: …" unless `mesh` has triangles, finite positions, no degenerate
/// triangle (two corners at one position or zero area), is closed and consistently oriented
/// (after merging vertices at equal positions every edge is used once in each direction) and
/// encloses a positive signed volume (outward triangles). `triangleLines` (optional, one per
/// triangle) locates a bad triangle in the source file.
void checkBoneMesh(const Mesh& mesh, const std::string& file,
                   const std::vector<int>& triangleLines = {});

/// OBJ text of a model mesh: `v` and `vn` per vertex in the shortest form that reads back as
/// the same float, `f a//a b//b c//c` per triangle. Deterministic.
std::string boneMeshObj(const Mesh& mesh, const std::string& title);

}  // namespace ramus::detail
