// Writing and reading scenes: glTF 2.0 binary (.glb) and Wavefront OBJ + MTL.
#pragma once

#include <string>

#include "ramus/file_util.hpp"
#include "ramus/scene.hpp"

namespace ramus {

/// Serialises `scene` as a GLB (glTF 2.0 binary). Byte-identical for identical scenes.
/// Output passes the Khronos glTF validator with no errors.
std::string encodeGlb(const Scene& scene);

/// Writes a GLB atomically (temp file + rename).
void writeGlb(const Scene& scene, const std::string& path);

/// Writes `path` (.obj) and the material library next to it (same stem, .mtl), both
/// atomically. Nodes' transforms are applied to the vertices; one `o`/`g` group per node, except
/// that a skinned mesh gets one group per joint, named like the joint's node (a skeleton's
/// bones: "thigh_L", …), holding the triangles whose first corner is bound most strongly to
/// that joint and the vertices they use; materials are `usemtl` lines within the groups.
void writeObj(const Scene& scene, const std::string& path);

/// Writes .glb or .obj depending on the extension of `path` (case-insensitive); anything else
/// is an Error naming the extension and the supported ones.
void writeScene(const Scene& scene, const std::string& path);

/// Reads a GLB or glTF file into a Scene (meshes with positions/normals/indices and the node
/// hierarchy). Throws Error naming the file on malformed input (numbers beyond double range in
/// the JSON included), non-finite vertex data, and files of more than `maxBytes` bytes.
Scene readGltf(const std::string& path, std::size_t maxBytes = kMaxInputFileBytes);

}  // namespace ramus
