// Internal helpers shared by the writers and the preview renderer: checking a Scene before it
// is written or drawn, and walking the meshes it places.
#pragma once

#include <string>
#include <vector>

#include "ramus/scene.hpp"

namespace ramus::io {

/// Checks everything a writer relies on and throws Error("<context>: …") on the first problem:
/// node parents in [-1, i), node mesh indices in range, finite and non-zero transforms; per
/// mesh: attribute arrays empty or of vertex count, finite attributes, whole triangles, indices
/// below the vertex count, primitives inside the index buffer referencing existing materials
/// (material 0 is allowed when the mesh has no materials), material factors finite and in
/// [0, 1]. Skins: joints and weights both present or both absent, weights ≥ 0 summing to 1
/// (±0.001); node skins in range and only on nodes whose mesh is skinned (and every skinned
/// mesh on a node with a skin, so a scene without nodes has no skinned mesh); skin joints
/// distinct existing nodes below the skin's skeleton root; one invertible inverse bind matrix
/// with bottom row (0, 0, 0, 1) per joint (or none); every vertex joint index below the joint
/// count of the skin of each node holding the mesh. `context` is usually the output path.
void checkScene(const Scene& scene, const std::string& context);

/// The primitives of `mesh` that draw at least one triangle, with the implicit "one primitive
/// over all indices, material 0" made explicit. Empty when the mesh has no triangles.
std::vector<MeshPrimitive> drawnPrimitives(const Mesh& mesh);
/// The implicit primitive of a mesh without primitives: all indices, material 0, the mesh's name.
MeshPrimitive wholeMeshPrimitive(const Mesh& mesh);
/// Whether drawnPrimitives(mesh) is non-empty, without building it.
bool drawsTriangles(const Mesh& mesh);

/// The material `primitive` draws with: mesh.materials[primitive.material], or the default
/// Material when the mesh has none.
const Material& primitiveMaterial(const Mesh& mesh, const MeshPrimitive& primitive);

/// One placement of a mesh in the world.
struct MeshInstance {
    int node = -1;  ///< index into Scene::nodes, or -1 when the scene has no nodes
    int mesh = 0;   ///< index into Scene::meshes
    Mat4 world = Mat4::Identity();
};

/// Every mesh placement in node order (world transforms composed parent-first). A scene without
/// nodes places each mesh once at the origin. Meshes without triangles are left out.
/// Precondition: checkScene passed.
std::vector<MeshInstance> meshInstances(const Scene& scene);

/// Shortest decimal text that reads back as the same float (std::to_chars), e.g. "0.1", "-2",
/// "1e-08". Locale-independent and deterministic.
std::string formatFloat(float value);

}  // namespace ramus::io
