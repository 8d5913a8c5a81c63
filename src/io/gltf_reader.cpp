// Based on: the glTF 2.0 specification (Khronos), §3.7.2 primitive modes (strip and fan
// triangle order), §3.5.3 node transforms (TRS or a decomposable matrix), §3.9 materials;
// parsing by tinygltf (syoyo/tinygltf).
#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "io/gltf_accessors.hpp"
#include "io/tinygltf_config.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {

namespace {

using io::accessorAt;
using io::readAccessor;
using io::Reader;
using io::readIndices;
using tinygltf::Model;

// Images are not needed for geometry: accept them without decoding.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

// Triangle lists from TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN index sequences (glTF §3.7.2.1).
std::vector<std::uint32_t> triangulate(const std::vector<std::uint32_t>& v, int mode) {
    std::vector<std::uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 3 * 3));
        return out;
    }
    for (std::size_t i = 0; i + 2 < v.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
        } else {  // fan
            out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
        }
    }
    return out;
}

Material convertMaterial(const Reader& r, int index) {
    Material m;
    if (index < 0) {  // glTF's default material
        m.name = "default";
        m.baseColor = Vec4f::Ones();
        m.metallic = 1.0f;
        m.roughness = 1.0f;
        return m;
    }
    if (index >= static_cast<int>(r.model.materials.size())) {
        r.fail("material " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Material& g = r.model.materials[index];
    auto unit = [](double v) { return static_cast<float>(std::clamp(v, 0.0, 1.0)); };
    m.name = g.name.empty() ? "material_" + std::to_string(index) : g.name;
    const std::vector<double>& c = g.pbrMetallicRoughness.baseColorFactor;
    for (int i = 0; i < 4 && i < static_cast<int>(c.size()); ++i) m.baseColor[i] = unit(c[i]);
    m.metallic = unit(g.pbrMetallicRoughness.metallicFactor);
    m.roughness = unit(g.pbrMetallicRoughness.roughnessFactor);
    m.doubleSided = g.doubleSided;
    return m;
}

// The primitive's name as ramus writes it ("extras": {"name": …}), or empty.
std::string primitiveName(const tinygltf::Primitive& p) {
    if (p.extras_json_string.empty()) return {};
    const nlohmann::json extras = nlohmann::json::parse(p.extras_json_string, nullptr, false);
    if (!extras.is_object() || !extras.contains("name") || !extras["name"].is_string()) return {};
    return extras["name"].get<std::string>();
}

// Scene and SceneNode extras are JSON objects; other extras values are not kept.
bool isJsonObject(const std::string& text) { return !text.empty() && text.front() == '{'; }

int attribute(const tinygltf::Primitive& p, const char* name) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

// Builds one Mesh from a glTF mesh; primitives that share vertex accessors share vertices.
class MeshBuilder {
public:
    explicit MeshBuilder(const Reader& r) : r_(r) {}
    Mesh build(const tinygltf::Mesh& gltfMesh);

private:
    std::uint32_t addVertices(const std::array<int, 4>& key);
    std::uint32_t materialIndex(int gltfMaterial);

    const Reader& r_;
    Mesh mesh_;
    std::vector<std::pair<std::array<int, 4>, std::uint32_t>> vertexSets_;
    std::vector<std::pair<int, std::uint32_t>> materials_;
    bool hasNormals_ = true, hasTangents_ = true, hasUvs_ = true;
};

// Appends the vertices of accessors {POSITION, NORMAL, TANGENT, TEXCOORD_0}; returns the base.
std::uint32_t MeshBuilder::addVertices(const std::array<int, 4>& key) {
    for (const auto& [k, base] : vertexSets_) {
        if (k == key) return base;
    }
    const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
    const std::size_t n = accessorAt(r_, key[0], "POSITION").count;
    if (mesh_.positions.size() + n > std::numeric_limits<std::uint32_t>::max()) {
        r_.fail("mesh '" + mesh_.name + "' has too many vertices");
    }
    auto fill = [&](auto& into, int accessor, int components, const char* what, bool& has) {
        using V = typename std::decay_t<decltype(into)>::value_type;
        std::vector<double> data;
        if (accessor >= 0) data = readAccessor(r_, accessor, components, what);
        if (accessor < 0 || data.size() != n * components) {
            has = false;
            data.assign(n * components, 0.0);
        }
        for (std::size_t i = 0; i < n; ++i) {
            V v;
            for (int c = 0; c < components; ++c)
                v[c] = static_cast<float>(data[i * components + c]);
            into.push_back(v);
        }
    };
    bool always = true;
    fill(mesh_.positions, key[0], 3, "POSITION", always);
    fill(mesh_.normals, key[1], 3, "NORMAL", hasNormals_);
    fill(mesh_.tangents, key[2], 4, "TANGENT", hasTangents_);
    fill(mesh_.uvs, key[3], 2, "TEXCOORD_0", hasUvs_);
    vertexSets_.emplace_back(key, base);
    return base;
}

std::uint32_t MeshBuilder::materialIndex(int gltfMaterial) {
    for (const auto& [g, local] : materials_) {
        if (g == gltfMaterial) return local;
    }
    const auto local = static_cast<std::uint32_t>(mesh_.materials.size());
    mesh_.materials.push_back(convertMaterial(r_, gltfMaterial));
    materials_.emplace_back(gltfMaterial, local);
    return local;
}

Mesh MeshBuilder::build(const tinygltf::Mesh& gltfMesh) {
    mesh_.name = gltfMesh.name.empty() ? "mesh" : gltfMesh.name;
    for (const tinygltf::Primitive& p : gltfMesh.primitives) {
        const bool triangles = p.mode == TINYGLTF_MODE_TRIANGLES ||
                               p.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
                               p.mode == TINYGLTF_MODE_TRIANGLE_FAN;
        const int position = attribute(p, "POSITION");
        if (!triangles || position < 0) continue;  // points and lines have no surface
        const std::array<int, 4> key{position, attribute(p, "NORMAL"), attribute(p, "TANGENT"),
                                     attribute(p, "TEXCOORD_0")};
        const std::uint32_t base = addVertices(key);
        const std::size_t count = accessorAt(r_, position, "POSITION").count;
        const std::vector<std::uint32_t> tri = triangulate(readIndices(r_, p, count), p.mode);
        if (tri.empty()) continue;
        MeshPrimitive prim;
        prim.firstIndex = static_cast<std::uint32_t>(mesh_.indices.size());
        prim.indexCount = static_cast<std::uint32_t>(tri.size());
        prim.material = materialIndex(p.material);
        prim.name = primitiveName(p);
        for (std::uint32_t i : tri) mesh_.indices.push_back(base + i);
        mesh_.primitives.push_back(std::move(prim));
    }
    if (!hasNormals_) mesh_.normals.clear();
    if (!hasTangents_) mesh_.tangents.clear();
    if (!hasUvs_) mesh_.uvs.clear();
    return std::move(mesh_);
}

// Node transform: TRS as given, or a matrix split into translation, rotation and scale (a
// negative determinant becomes a negative x scale).
void setTransform(const tinygltf::Node& g, SceneNode& node) {
    if (g.matrix.size() == 16) {
        Mat4 m;
        for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = g.matrix[i];
        node.translation = m.topRightCorner<3, 1>();
        Mat3 linear = m.topLeftCorner<3, 3>();
        for (int c = 0; c < 3; ++c) node.scale[c] = linear.col(c).norm();
        if (linear.determinant() < 0.0) node.scale.x() = -node.scale.x();
        if (node.scale.cwiseAbs().minCoeff() > 0.0) {
            for (int c = 0; c < 3; ++c) linear.col(c) /= node.scale[c];
            node.rotation = Eigen::Quaterniond(linear).normalized();
        }
        return;
    }
    if (g.translation.size() == 3)
        node.translation = Vec3(g.translation[0], g.translation[1], g.translation[2]);
    if (g.scale.size() == 3) node.scale = Vec3(g.scale[0], g.scale[1], g.scale[2]);
    if (g.rotation.size() == 4) {
        const Eigen::Quaterniond q(g.rotation[3], g.rotation[0], g.rotation[1], g.rotation[2]);
        if (q.norm() > 0.0) node.rotation = q.normalized();
    }
}

// glTF node indices in an order where parents come before children (depth-first from the
// default scene's roots, or from every parentless node when the file has no scene).
std::vector<int> nodeOrder(const Reader& r, const std::vector<int>& roots) {
    const std::size_t n = r.model.nodes.size();
    std::vector<int> order;
    std::vector<char> visited(n, 0);
    std::vector<int> stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        if (i < 0 || i >= static_cast<int>(n))
            r.fail("node " + std::to_string(i) + " does not exist");
        if (visited[i])
            r.fail("node " + std::to_string(i) +
                   " is reached twice; the node hierarchy must be a forest");
        visited[i] = 1;
        order.push_back(i);
        const std::vector<int>& children = r.model.nodes[i].children;
        stack.insert(stack.end(), children.rbegin(), children.rend());
    }
    return order;
}

std::vector<int> parentsOf(const Reader& r) {
    std::vector<int> parent(r.model.nodes.size(), -1);
    for (std::size_t i = 0; i < r.model.nodes.size(); ++i) {
        for (int c : r.model.nodes[i].children) {
            if (c < 0 || c >= static_cast<int>(parent.size()) || parent[c] >= 0 ||
                c == static_cast<int>(i)) {
                r.fail("node " + std::to_string(i) + " has an invalid or shared child " +
                       std::to_string(c));
            }
            parent[c] = static_cast<int>(i);
        }
    }
    return parent;
}

void convertNodes(const Reader& r, Scene& scene) {
    const std::vector<int> parent = parentsOf(r);
    std::vector<int> roots;
    if (!r.model.scenes.empty()) {
        const int s = r.model.defaultScene >= 0 ? r.model.defaultScene : 0;
        if (s >= static_cast<int>(r.model.scenes.size()))
            r.fail("default scene " + std::to_string(s) + " does not exist");
        roots = r.model.scenes[s].nodes;
        const std::string& extras = r.model.scenes[s].extras_json_string;
        if (isJsonObject(extras)) scene.extrasJson = extras;
    } else {
        for (std::size_t i = 0; i < parent.size(); ++i) {
            if (parent[i] < 0) roots.push_back(static_cast<int>(i));
        }
    }
    for (int root : roots) {
        if (root >= 0 && root < static_cast<int>(parent.size()) && parent[root] >= 0) {
            r.fail("scene root node " + std::to_string(root) + " has a parent");
        }
    }
    const std::vector<int> order = nodeOrder(r, roots);
    std::vector<int> newIndex(r.model.nodes.size(), -1);
    for (int g : order) {
        const tinygltf::Node& gn = r.model.nodes[g];
        SceneNode node;
        node.name = gn.name;
        node.parent = parent[g] < 0 ? -1 : newIndex[parent[g]];
        if (gn.mesh >= static_cast<int>(scene.meshes.size()))
            r.fail("node " + std::to_string(g) + " refers to missing mesh " +
                   std::to_string(gn.mesh));
        node.mesh = std::max(gn.mesh, -1);
        if (isJsonObject(gn.extras_json_string)) node.extrasJson = gn.extras_json_string;
        setTransform(gn, node);
        newIndex[g] = static_cast<int>(scene.nodes.size());
        scene.nodes.push_back(std::move(node));
    }
}

Model loadModel(const std::string& path, std::size_t maxBytes) {
    const std::string bytes = readFile(path, maxBytes);
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        throw Error(path + ": cannot read glTF: file is larger than 4 GiB");
    tinygltf::TinyGLTF loader;
    loader.SetStoreOriginalJSONForExtrasAndExtensions(true);
    loader.SetImageLoader(&skipImage, nullptr);
    const std::string baseDir = std::filesystem::path(path).parent_path().string();
    Model model;
    std::string err, warn;
    const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                             reinterpret_cast<const unsigned char*>(bytes.data()),
                                             static_cast<unsigned int>(bytes.size()), baseDir)
               : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                            static_cast<unsigned int>(bytes.size()), baseDir);
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
        throw Error(path +
                    ": cannot read glTF: " + (err.empty() ? std::string("unknown error") : err));
    }
    return model;
}

}  // namespace

Scene readGltf(const std::string& path, std::size_t maxBytes) {
    const Model model = loadModel(path, maxBytes);
    const Reader r{model, path};
    Scene scene;
    for (const tinygltf::Mesh& m : model.meshes) scene.meshes.push_back(MeshBuilder(r).build(m));
    convertNodes(r, scene);
    return scene;
}

}  // namespace ramus
