// Triangle meshes as flat arrays, ready for glTF/OBJ export and preview rendering.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/image.hpp"
#include "ramus/math.hpp"

namespace ramus {

/// A PBR metallic-roughness material (maps 1:1 to glTF's; OBJ export writes Kd from baseColor
/// and the textures as PNG files next to the OBJ).
struct Material {
    std::string name = "material";
    Vec4f baseColor{0.8f, 0.8f, 0.8f, 1.0f};  ///< linear RGBA
    float metallic = 0.0f;
    float roughness = 0.9f;
    bool doubleSided = false;
    /// glTF alphaMode MASK: fragments whose alpha (baseColor alpha × texture alpha) is below
    /// alphaCutoff are discarded, the rest are opaque (leaf cards). Without it a baseColor alpha
    /// below 1 is written as BLEND.
    bool alphaMask = false;
    float alphaCutoff = 0.5f;  ///< in [0, 1]; only with alphaMask
    /// Multiplies baseColor (glTF baseColorTexture, sampled with TEXCOORD_0, wrapping REPEAT);
    /// shared so copies of meshes (LODs, appended meshes) do not copy pixels. Null = none.
    std::shared_ptr<const Image> baseColorTexture = nullptr;
    /// Tangent-space normal map (glTF normalTexture; +Y = image up, needs normals and tangents).
    std::shared_ptr<const Image> normalTexture = nullptr;
};

/// Whether two materials are the same (all fields equal; textures by identity).
bool sameMaterial(const Material& a, const Material& b);

/// A custom per-vertex attribute, written to glTF as an application-specific attribute (its
/// name starts with '_', glTF 2.0 §3.7.2.1) of FLOAT components; OBJ export ignores it.
struct VertexAttribute {
    std::string name;           ///< e.g. "_WIND"; must start with '_', unique within the mesh
    int components = 1;         ///< 1..4 floats per vertex (glTF SCALAR, VEC2, VEC3, VEC4)
    std::vector<float> values;  ///< components × vertex count, vertex-major
};

/// A range of the index buffer drawn with one material (glTF primitive / OBJ usemtl group).
struct MeshPrimitive {
    std::uint32_t firstIndex = 0;  ///< into Mesh::indices, multiple of 3
    std::uint32_t indexCount = 0;  ///< multiple of 3
    std::uint32_t material = 0;    ///< index into Mesh::materials
    std::string name;              ///< e.g. "bark", "leaves"
};

/// Indexed triangle mesh. positions is always filled; normals, tangents, uvs, joints and weights
/// are either empty or the same length as positions. Triangles are counter-clockwise seen from
/// outside. tangents are glTF tangents: xyz unit tangent, w = ±1 bitangent sign.
/// joints and weights (glTF JOINTS_0 / WEIGHTS_0) skin the mesh: both empty or both filled;
/// joints index into the Skin of the node that holds the mesh, weights are ≥ 0 and sum to 1
/// per vertex (unused slots: weight 0). Positions are the bind pose.
struct Mesh {
    std::string name = "mesh";
    std::vector<Vec3f> positions;
    std::vector<Vec3f> normals;
    std::vector<Vec4f> tangents;
    std::vector<Vec2f> uvs;
    std::vector<std::array<std::uint16_t, 4>> joints;  ///< per vertex: 4 indices into Skin::joints
    std::vector<Vec4f> weights;                        ///< per vertex: the 4 joints' weights
    std::vector<VertexAttribute> attributes;  ///< custom attributes (e.g. wind data), any number
    std::vector<std::uint32_t> indices;
    std::vector<MeshPrimitive> primitives;  ///< cover indices; empty = one primitive, material 0
    std::vector<Material> materials;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    Aabb bounds() const;
};

/// The custom attribute called `name`, or null.
const VertexAttribute* findAttribute(const Mesh& mesh, std::string_view name);

/// Appends `other` to `mesh` (indices, primitives and materials re-based). Attribute arrays
/// that one side lacks are dropped from the result unless both have them (joints and weights
/// are kept or dropped together; custom attributes are matched by name and component count).
/// Appending a mesh without vertices changes no attribute. Joint indices are copied unchanged:
/// both meshes must refer to the same Skin.
void appendMesh(Mesh& mesh, const Mesh& other);
/// The same, taking `other`'s arrays where `mesh` has none yet instead of copying them.
void appendMesh(Mesh& mesh, Mesh&& other);

/// Appends to `to` a copy of vertex `v` of `from` (which may be `to`): every vertex array that
/// `from` has, custom attributes by position (`to` must have the same ones, in order). Returns
/// the new vertex's index.
std::uint32_t appendVertexCopy(Mesh& to, const Mesh& from, std::uint32_t v);

/// Removes the vertices no triangle uses, keeping the others in order; every vertex array
/// (normals, tangents, UVs, joints, weights, custom attributes) is compacted with them.
void removeUnusedVertices(Mesh& mesh);

/// Merges primitives that draw with the same material (sameMaterial) into one, in the order of
/// their first appearance, reordering the index buffer accordingly; duplicate materials are
/// removed. Triangles and vertices are unchanged, so e.g. several trees appended into one mesh
/// end with one "bark" primitive. A mesh without primitives is left as it is.
void mergePrimitivesByMaterial(Mesh& mesh);

}  // namespace ramus
