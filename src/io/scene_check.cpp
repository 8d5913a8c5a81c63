#include "io/scene_check.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>

#include "ramus/error.hpp"

namespace ramus::io {

namespace {

// How far a vertex's weights may sum from 1 (the writer normalises them exactly).
constexpr float kWeightSumTolerance = 1e-3f;

[[noreturn]] void fail(const std::string& context, const std::string& what) {
    throw Error(context + ": " + what);
}

std::string meshLabel(const Mesh& mesh, std::size_t index) {
    return "mesh " + std::to_string(index) + " ('" + mesh.name + "')";
}

// Where a mesh check fails: "<context>: mesh i ('name')", built only for the message of a check
// that fails (a scene of many small meshes — a skeleton's bones — would otherwise build a label
// per mesh).
struct MeshWhere {
    const std::string& context;
    const Mesh& mesh;
    std::size_t index;
};

[[noreturn]] void fail(const MeshWhere& where, const std::string& what) {
    fail(where.context + ": " + meshLabel(where.mesh, where.index), what);
}

template <typename Vec>
bool allFinite(const Vec& v) {
    for (int i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i])) return false;
    }
    return true;
}

// Whether the vector stays finite at float precision, as the writers store node transforms.
bool finiteAsFloats(const Vec3& v) { return allFinite(Vec3f(v.cast<float>())); }

// Whether all `count` floats are finite: a float is ±inf or NaN exactly when its exponent
// bits are all ones. One branch-free pass that the compiler vectorizes; only a failure looks
// closer.
bool allFiniteFloats(const float* values, std::size_t count) {
    constexpr std::uint32_t kExponent = 0x7F800000u;
    std::uint32_t nonFinite = 0;
    for (std::size_t i = 0; i < count; ++i) {
        nonFinite |= static_cast<std::uint32_t>(
            (std::bit_cast<std::uint32_t>(values[i]) & kExponent) == kExponent);
    }
    return nonFinite == 0;
}

template <typename Vec>
void checkAttribute(const std::vector<Vec>& values, std::size_t vertexCount, const char* name,
                    const MeshWhere& where) {
    if (!values.empty() && values.size() != vertexCount) {
        fail(where, std::string(name) + " has " + std::to_string(values.size()) +
                        " entries; expected 0 or " + std::to_string(vertexCount) +
                        " (one per vertex)");
    }
    static_assert(sizeof(Vec) == sizeof(float) * Vec::SizeAtCompileTime, "packed vectors");
    if (values.empty() ||
        allFiniteFloats(values.data()->data(), values.size() * Vec::SizeAtCompileTime)) {
        return;
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!allFinite(values[i])) {
            fail(where, std::string(name) + " of vertex " + std::to_string(i) + " is not finite");
        }
    }
}

void checkMaterial(const Material& m, const MeshWhere& where) {
    auto inUnitRange = [](float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; };
    const char* channels[] = {"red", "green", "blue", "alpha"};
    for (int c = 0; c < 4; ++c) {
        if (!inUnitRange(m.baseColor[c])) {
            fail(where, "material '" + m.name + "': baseColor " + channels[c] + " is " +
                            formatFloat(m.baseColor[c]) + "; expected a value in [0, 1]");
        }
    }
    if (!inUnitRange(m.metallic)) {
        fail(where, "material '" + m.name + "': metallic is " + formatFloat(m.metallic) +
                        "; expected a value in [0, 1]");
    }
    if (!inUnitRange(m.roughness)) {
        fail(where, "material '" + m.name + "': roughness is " + formatFloat(m.roughness) +
                        "; expected a value in [0, 1]");
    }
    if (m.alphaMask && !inUnitRange(m.alphaCutoff)) {
        fail(where, "material '" + m.name + "': alphaCutoff is " + formatFloat(m.alphaCutoff) +
                        "; expected a value in [0, 1]");
    }
    const std::pair<const char*, const Image*> textures[] = {
        {"baseColorTexture", m.baseColorTexture.get()}, {"normalTexture", m.normalTexture.get()}};
    for (const auto& [name, image] : textures) {
        if (image == nullptr) continue;
        const std::size_t expected = image->width > 0 && image->height > 0
                                         ? std::size_t{4} * static_cast<std::size_t>(image->width) *
                                               static_cast<std::size_t>(image->height)
                                         : 0;
        if (expected == 0 || image->rgba.size() != expected) {
            fail(where, "material '" + m.name + "': " + name + " is " +
                            std::to_string(image->width) + "x" + std::to_string(image->height) +
                            " with " + std::to_string(image->rgba.size()) +
                            " bytes; expected a non-empty image with 4 bytes (RGBA) per pixel");
        }
    }
}

// Custom attributes: names glTF accepts for application-specific data, unique, 1–4 finite
// components per vertex.
void checkCustomAttributes(const Mesh& mesh, const MeshWhere& where) {
    const std::size_t n = mesh.positions.size();
    for (std::size_t k = 0; k < mesh.attributes.size(); ++k) {
        const VertexAttribute& a = mesh.attributes[k];
        const std::string label = "attribute '" + a.name + "'";
        if (a.name.size() < 2 || a.name[0] != '_') {
            fail(where, label + ": expected a name starting with '_' (glTF application-specific " +
                            "attributes), e.g. _WIND");
        }
        for (std::size_t j = 0; j < k; ++j) {
            if (mesh.attributes[j].name == a.name) fail(where, label + " is given twice");
        }
        if (a.components < 1 || a.components > 4) {
            fail(where,
                 label + " has " + std::to_string(a.components) + " components; expected 1 to 4");
        }
        const std::size_t expected = n * static_cast<std::size_t>(a.components);
        if (a.values.size() != expected) {
            fail(where, label + " has " + std::to_string(a.values.size()) + " values; expected " +
                            std::to_string(expected) + " (" + std::to_string(a.components) +
                            " per vertex)");
        }
        for (std::size_t i = 0; i < a.values.size(); ++i) {
            if (!std::isfinite(a.values[i])) {
                fail(where,
                     label + " of vertex " + std::to_string(i / a.components) + " is not finite");
            }
        }
    }
}

void checkPrimitives(const Mesh& mesh, const MeshWhere& where) {
    const std::size_t materialCount = std::max<std::size_t>(1, mesh.materials.size());
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const MeshPrimitive& prim = mesh.primitives[p];
        const auto label = [&] {
            return "primitive " + std::to_string(p) + " ('" + prim.name + "')";
        };
        if (prim.firstIndex % 3 != 0 || prim.indexCount % 3 != 0) {
            fail(where, label() + " covers indices " + std::to_string(prim.firstIndex) + " +" +
                            std::to_string(prim.indexCount) +
                            "; expected whole triangles (multiples of 3)");
        }
        if (std::uint64_t{prim.firstIndex} + prim.indexCount > mesh.indices.size()) {
            fail(where, label() + " ends at index " +
                            std::to_string(std::uint64_t{prim.firstIndex} + prim.indexCount) +
                            "; expected at most " + std::to_string(mesh.indices.size()));
        }
        if (prim.material >= materialCount) {
            fail(where, label() + " uses material " + std::to_string(prim.material) +
                            "; expected < " + std::to_string(materialCount));
        }
    }
}

// Joints and weights come together; weights are finite, non-negative and sum to 1.
void checkSkinAttributes(const Mesh& mesh, const MeshWhere& where) {
    const std::size_t n = mesh.positions.size();
    checkAttribute(mesh.weights, n, "weights", where);
    if (!mesh.joints.empty() && mesh.joints.size() != n) {
        fail(where, "joints has " + std::to_string(mesh.joints.size()) +
                        " entries; expected 0 or " + std::to_string(n) + " (one per vertex)");
    }
    if (mesh.joints.empty() != mesh.weights.empty()) {
        fail(where, "has " + std::to_string(mesh.joints.size()) + " joints and " +
                        std::to_string(mesh.weights.size()) +
                        " weights; expected both or neither (skinning needs both)");
    }
    // Weights w[0..3] that are negative or do not sum to 1.
    auto badWeights = [](const float* w) {
        const float sum = (w[0] + w[1]) + (w[2] + w[3]);
        const float least = std::min(std::min(w[0], w[1]), std::min(w[2], w[3]));
        return (least < 0.0f) | (std::abs(sum - 1.0f) > kWeightSumTolerance);
    };
    // Branch-free first over the flat floats (the compiler vectorizes it); the message is
    // looked for on failure only.
    const float* flat = mesh.weights.empty() ? nullptr : mesh.weights.data()->data();
    bool anyBad = false;
    for (std::size_t i = 0; i < 4 * mesh.weights.size(); i += 4) anyBad |= badWeights(flat + i);
    for (std::size_t i = 0; anyBad && i < mesh.weights.size(); ++i) {
        const Vec4f& w = mesh.weights[i];
        if (badWeights(w.data())) {
            fail(where, "weights of vertex " + std::to_string(i) + " are (" + formatFloat(w[0]) +
                            ", " + formatFloat(w[1]) + ", " + formatFloat(w[2]) + ", " +
                            formatFloat(w[3]) + "); expected non-negative weights summing to 1");
        }
    }
}

void checkMesh(const Mesh& mesh, const MeshWhere& where) {
    const std::size_t n = mesh.positions.size();
    checkAttribute(mesh.positions, n, "positions", where);
    checkAttribute(mesh.normals, n, "normals", where);
    checkAttribute(mesh.tangents, n, "tangents", where);
    checkAttribute(mesh.uvs, n, "uvs", where);
    checkSkinAttributes(mesh, where);
    checkCustomAttributes(mesh, where);
    if (mesh.indices.size() % 3 != 0) {
        fail(where, "has " + std::to_string(mesh.indices.size()) +
                        " indices; expected a multiple of 3 (triangles)");
    }
    std::uint32_t largest = 0;
    for (const std::uint32_t index : mesh.indices) largest = std::max(largest, index);
    for (std::size_t i = 0; largest >= n && i < mesh.indices.size(); ++i) {
        if (mesh.indices[i] >= n) {
            fail(where, "index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) +
                            "; expected < " + std::to_string(n) + " (the vertex count)");
        }
    }
    checkPrimitives(mesh, where);
    for (const Material& m : mesh.materials) checkMaterial(m, where);
}

// Whether node i is valid; cheap (no strings), so the located messages of checkNode are built
// only for a node that fails.
bool nodeIsValid(const Scene& scene, std::size_t i) {
    const SceneNode& node = scene.nodes[i];
    const int meshCount = static_cast<int>(scene.meshes.size());
    const int skinCount = static_cast<int>(scene.skins.size());
    if (node.parent < -1 || node.parent >= static_cast<int>(i)) return false;
    if (node.mesh < -1 || node.mesh >= meshCount || node.skin < -1 || node.skin >= skinCount) {
        return false;
    }
    if (!finiteAsFloats(node.translation) || !finiteAsFloats(node.scale)) return false;
    if (node.mesh >= 0 && (node.skin >= 0) == scene.meshes[node.mesh].joints.empty()) return false;
    if (node.mesh < 0 && node.skin >= 0) return false;
    const double norm = node.rotation.norm();
    return std::isfinite(norm) && norm >= 1e-6;
}

void checkNode(const Scene& scene, std::size_t i, const std::string& context) {
    if (nodeIsValid(scene, i)) return;
    const SceneNode& node = scene.nodes[i];
    const std::string where = context + ": node " + std::to_string(i) + " ('" + node.name + "')";
    if (node.parent < -1 || node.parent >= static_cast<int>(i)) {
        fail(where, "parent is " + std::to_string(node.parent) +
                        "; expected -1 or an earlier node (parents come before children)");
    }
    if (node.mesh < -1 || node.mesh >= static_cast<int>(scene.meshes.size())) {
        fail(where, "mesh is " + std::to_string(node.mesh) + "; expected -1 or < " +
                        std::to_string(scene.meshes.size()));
    }
    if (!finiteAsFloats(node.translation) || !finiteAsFloats(node.scale)) {
        fail(where, "translation or scale is not finite (or beyond the float range)");
    }
    if (node.skin < -1 || node.skin >= static_cast<int>(scene.skins.size())) {
        fail(where, "skin is " + std::to_string(node.skin) + "; expected -1 or < " +
                        std::to_string(scene.skins.size()));
    }
    if (node.mesh >= 0) {
        const Mesh& mesh = scene.meshes[node.mesh];
        if (node.skin >= 0 && mesh.joints.empty()) {
            fail(where, "has skin " + std::to_string(node.skin) + " but its mesh '" + mesh.name +
                            "' has no joints and weights");
        }
        if (node.skin < 0 && !mesh.joints.empty()) {
            fail(where, "holds the skinned mesh '" + mesh.name + "' but has no skin");
        }
    } else if (node.skin >= 0) {
        fail(where, "has skin " + std::to_string(node.skin) + " but no mesh");
    }
    const double norm = node.rotation.norm();
    if (!std::isfinite(norm) || norm < 1e-6) {
        fail(where, "rotation is not a valid quaternion (norm " + std::to_string(norm) + ")");
    }
}

void checkInverseBindMatrices(const Skin& skin, const std::string& where) {
    if (!skin.inverseBindMatrices.empty() &&
        skin.inverseBindMatrices.size() != skin.joints.size()) {
        fail(where, "has " + std::to_string(skin.inverseBindMatrices.size()) +
                        " inverse bind matrices; expected 0 or " +
                        std::to_string(skin.joints.size()) + " (one per joint)");
    }
    for (std::size_t j = 0; j < skin.inverseBindMatrices.size(); ++j) {
        const Mat4& m = skin.inverseBindMatrices[j];
        const double det = m.topLeftCorner<3, 3>().determinant();
        if (!allFinite(m.reshaped()) || m.row(3) != Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0) ||
            !(std::abs(det) > 1e-30)) {
            fail(where, "inverse bind matrix " + std::to_string(j) +
                            " is not an invertible affine matrix with bottom row (0, 0, 0, 1)");
        }
    }
}

// Joints are distinct existing nodes below the skeleton root; one matrix per joint.
void checkSkin(const Scene& scene, std::size_t k, const std::string& context) {
    const Skin& skin = scene.skins[k];
    const std::string where = context + ": skin " + std::to_string(k) + " ('" + skin.name + "')";
    const int nodeCount = static_cast<int>(scene.nodes.size());
    if (skin.joints.empty()) fail(where, "has no joints; expected at least one joint node");
    for (int joint : skin.joints) {
        if (joint < 0 || joint >= nodeCount) {
            fail(where, "joint node " + std::to_string(joint) + " does not exist; expected < " +
                            std::to_string(nodeCount));
        }
    }
    std::vector<int> sorted = skin.joints;
    std::sort(sorted.begin(), sorted.end());
    const auto duplicate = std::adjacent_find(sorted.begin(), sorted.end());
    if (duplicate != sorted.end()) {
        fail(where,
             "lists node " + std::to_string(*duplicate) + " twice; expected distinct joints");
    }
    if (skin.skeleton < -1 || skin.skeleton >= nodeCount) {
        fail(where, "skeleton is " + std::to_string(skin.skeleton) + "; expected -1 or < " +
                        std::to_string(nodeCount));
    }
    // Nodes at or below the skeleton root, in one pass (parents come before children).
    std::vector<char> below(scene.nodes.size(), static_cast<char>(skin.skeleton < 0));
    for (std::size_t i = 0; skin.skeleton >= 0 && i < scene.nodes.size(); ++i) {
        const int parent = scene.nodes[i].parent;
        below[i] = static_cast<char>(static_cast<int>(i) == skin.skeleton ||
                                     (parent >= 0 && below[parent] != 0));
    }
    for (int joint : skin.joints) {
        if (below[joint] == 0) {
            fail(where, "joint node " + std::to_string(joint) + " is not below the skeleton root " +
                            std::to_string(skin.skeleton));
        }
    }
    checkInverseBindMatrices(skin, where);
}

// Every joint index of a skinned mesh names a joint of the skin of each node that holds it.
void checkSkinnedNode(const Scene& scene, std::size_t i, const std::string& context) {
    const SceneNode& node = scene.nodes[i];
    if (node.skin < 0) return;
    const std::size_t jointCount = scene.skins[node.skin].joints.size();
    const Mesh& mesh = scene.meshes[node.mesh];
    // Branch-free first over the flat indices; the message is looked for on failure only.
    std::uint16_t largest = 0;
    const std::uint16_t* flat = mesh.joints.empty() ? nullptr : mesh.joints.data()->data();
    for (std::size_t k = 0; k < 4 * mesh.joints.size(); ++k) largest = std::max(largest, flat[k]);
    for (std::size_t v = 0; largest >= jointCount && v < mesh.joints.size(); ++v) {
        for (std::uint16_t j : mesh.joints[v]) {
            if (j >= jointCount) {
                fail(context + ": node " + std::to_string(i) + " ('" + node.name + "')",
                     "vertex " + std::to_string(v) + " of mesh '" + mesh.name + "' uses joint " +
                         std::to_string(j) + "; expected < " + std::to_string(jointCount) +
                         " (the joints of skin " + std::to_string(node.skin) + ")");
            }
        }
    }
}

}  // namespace

void checkScene(const Scene& scene, const std::string& context) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) checkNode(scene, i, context);
    for (std::size_t k = 0; k < scene.skins.size(); ++k) checkSkin(scene, k, context);
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) checkSkinnedNode(scene, i, context);
    if (scene.nodes.empty()) {
        for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
            if (!scene.meshes[m].joints.empty()) {
                fail(context + ": " + meshLabel(scene.meshes[m], m),
                     "is skinned but the scene has no nodes; expected a node with a skin");
            }
        }
    }
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        checkMesh(scene.meshes[m], MeshWhere{context, scene.meshes[m], m});
    }
}

std::vector<MeshPrimitive> drawnPrimitives(const Mesh& mesh) {
    std::vector<MeshPrimitive> result;
    if (mesh.primitives.empty()) {
        if (!mesh.indices.empty()) result.push_back(wholeMeshPrimitive(mesh));
        return result;
    }
    for (const MeshPrimitive& p : mesh.primitives) {
        if (p.indexCount > 0) result.push_back(p);
    }
    return result;
}

MeshPrimitive wholeMeshPrimitive(const Mesh& mesh) {
    return MeshPrimitive{0, static_cast<std::uint32_t>(mesh.indices.size()), 0, mesh.name};
}

bool drawsTriangles(const Mesh& mesh) {
    if (mesh.primitives.empty()) return !mesh.indices.empty();
    return std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                       [](const MeshPrimitive& p) { return p.indexCount > 0; });
}

const Material& primitiveMaterial(const Mesh& mesh, const MeshPrimitive& primitive) {
    static const Material kDefault{};
    if (mesh.materials.empty()) return kDefault;
    return mesh.materials[primitive.material];
}

std::vector<MeshInstance> meshInstances(const Scene& scene) {
    std::vector<MeshInstance> result;
    auto drawable = [&](int m) { return drawsTriangles(scene.meshes[m]); };
    if (scene.nodes.empty()) {
        for (int m = 0; m < static_cast<int>(scene.meshes.size()); ++m) {
            if (drawable(m)) result.push_back(MeshInstance{-1, m, Mat4::Identity()});
        }
        return result;
    }
    std::vector<Mat4> world(scene.nodes.size());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const SceneNode& n = scene.nodes[i];
        const Eigen::Affine3d local =
            Eigen::Translation3d(n.translation) * n.rotation.normalized() * Eigen::Scaling(n.scale);
        world[i] = n.parent < 0 ? local.matrix() : Mat4(world[n.parent] * local.matrix());
        if (n.mesh >= 0 && drawable(n.mesh)) {
            result.push_back(MeshInstance{static_cast<int>(i), n.mesh, world[i]});
        }
    }
    return result;
}

std::string formatFloat(float value) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc{} ? std::string(buffer, end) : std::string("nan");
}

}  // namespace ramus::io
