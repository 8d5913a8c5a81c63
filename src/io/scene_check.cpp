#include "io/scene_check.hpp"

#include <charconv>
#include <cmath>

#include "ramus/error.hpp"

namespace ramus::io {

namespace {

[[noreturn]] void fail(const std::string& context, const std::string& what) {
    throw Error(context + ": " + what);
}

std::string meshLabel(const Mesh& mesh, std::size_t index) {
    return "mesh " + std::to_string(index) + " ('" + mesh.name + "')";
}

template <typename Vec>
bool allFinite(const Vec& v) {
    for (int i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i])) return false;
    }
    return true;
}

template <typename Vec>
void checkAttribute(const std::vector<Vec>& values, std::size_t vertexCount, const char* name,
                    const std::string& where) {
    if (!values.empty() && values.size() != vertexCount) {
        fail(where, std::string(name) + " has " + std::to_string(values.size()) +
                        " entries; expected 0 or " + std::to_string(vertexCount) +
                        " (one per vertex)");
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!allFinite(values[i])) {
            fail(where, std::string(name) + " of vertex " + std::to_string(i) + " is not finite");
        }
    }
}

void checkMaterial(const Material& m, const std::string& where) {
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
}

void checkPrimitives(const Mesh& mesh, const std::string& where) {
    const std::size_t materialCount = std::max<std::size_t>(1, mesh.materials.size());
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const MeshPrimitive& prim = mesh.primitives[p];
        const std::string label = "primitive " + std::to_string(p) + " ('" + prim.name + "')";
        if (prim.firstIndex % 3 != 0 || prim.indexCount % 3 != 0) {
            fail(where, label + " covers indices " + std::to_string(prim.firstIndex) + " +" +
                            std::to_string(prim.indexCount) +
                            "; expected whole triangles (multiples of 3)");
        }
        if (std::uint64_t{prim.firstIndex} + prim.indexCount > mesh.indices.size()) {
            fail(where, label + " ends at index " +
                            std::to_string(std::uint64_t{prim.firstIndex} + prim.indexCount) +
                            "; expected at most " + std::to_string(mesh.indices.size()));
        }
        if (prim.material >= materialCount) {
            fail(where, label + " uses material " + std::to_string(prim.material) +
                            "; expected < " + std::to_string(materialCount));
        }
    }
}

void checkMesh(const Mesh& mesh, const std::string& where) {
    const std::size_t n = mesh.positions.size();
    checkAttribute(mesh.positions, n, "positions", where);
    checkAttribute(mesh.normals, n, "normals", where);
    checkAttribute(mesh.tangents, n, "tangents", where);
    checkAttribute(mesh.uvs, n, "uvs", where);
    if (mesh.indices.size() % 3 != 0) {
        fail(where, "has " + std::to_string(mesh.indices.size()) +
                        " indices; expected a multiple of 3 (triangles)");
    }
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        if (mesh.indices[i] >= n) {
            fail(where, "index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) +
                            "; expected < " + std::to_string(n) + " (the vertex count)");
        }
    }
    checkPrimitives(mesh, where);
    for (const Material& m : mesh.materials) checkMaterial(m, where);
}

void checkNode(const Scene& scene, std::size_t i, const std::string& context) {
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
    if (!allFinite(node.translation) || !allFinite(node.scale)) {
        fail(where, "translation or scale is not finite");
    }
    const double norm = node.rotation.norm();
    if (!std::isfinite(norm) || norm < 1e-6) {
        fail(where, "rotation is not a valid quaternion (norm " + std::to_string(norm) + ")");
    }
}

}  // namespace

void checkScene(const Scene& scene, const std::string& context) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) checkNode(scene, i, context);
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        checkMesh(scene.meshes[m], context + ": " + meshLabel(scene.meshes[m], m));
    }
}

std::vector<MeshPrimitive> drawnPrimitives(const Mesh& mesh) {
    std::vector<MeshPrimitive> result;
    if (mesh.primitives.empty()) {
        if (!mesh.indices.empty()) {
            result.push_back(
                MeshPrimitive{0, static_cast<std::uint32_t>(mesh.indices.size()), 0, mesh.name});
        }
        return result;
    }
    for (const MeshPrimitive& p : mesh.primitives) {
        if (p.indexCount > 0) result.push_back(p);
    }
    return result;
}

const Material& primitiveMaterial(const Mesh& mesh, const MeshPrimitive& primitive) {
    static const Material kDefault{};
    if (mesh.materials.empty()) return kDefault;
    return mesh.materials[primitive.material];
}

std::vector<MeshInstance> meshInstances(const Scene& scene) {
    std::vector<MeshInstance> result;
    auto drawable = [&](int m) { return !drawnPrimitives(scene.meshes[m]).empty(); };
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
