// Based on: the Wavefront OBJ and MTL file formats (Wavefront Advanced Visualizer manual,
// appendices B1 "Object Files" and B2 "Material Library Files"); PBR roughness → Ns as in
// Blender's OBJ exporter (Ns = 900·(1 − roughness)²), plus the common "Pr"/"Pm" PBR extension.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "io/scene_check.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/render.hpp"

namespace ramus {

namespace {

// OBJ/MTL names end at whitespace: replace it, and give unnamed things a name.
std::string objName(const std::string& name, const std::string& fallback) {
    if (name.empty()) return fallback;
    std::string out = name;
    for (char& c : out) {
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = '_';
    }
    return out;
}

void appendFloats(std::string& out, const char* tag, const float* v, int n) {
    out += tag;
    for (int i = 0; i < n; ++i) {
        out += ' ';
        out += io::formatFloat(v[i]);
    }
    out += '\n';
}

// The scene's distinct materials with unique OBJ names, in first-use order, and the PNG files
// of their textures (named after the OBJ's stem and the first material using them).
class MaterialTable {
public:
    explicit MaterialTable(std::string textureStem) : textureStem_(std::move(textureStem)) {}

    const std::string& nameOf(const Material& m) {
        for (std::size_t i = 0; i < materials_.size(); ++i) {
            if (sameMaterial(materials_[i], m)) return names_[i];
        }
        const std::string base = objName(m.name, "material");
        std::string name = base;
        for (int k = 2; std::find(names_.begin(), names_.end(), name) != names_.end(); ++k) {
            name = base + "_" + std::to_string(k);
        }
        materials_.push_back(m);
        names_.push_back(name);
        baseColorFiles_.push_back(textureFile(m.baseColorTexture.get(), name));
        normalFiles_.push_back(textureFile(m.normalTexture.get(), name + "_normal"));
        return names_.back();
    }

    /// The texture files to write: file name (next to the OBJ) and image.
    const std::vector<std::pair<std::string, const Image*>>& textureFiles() const {
        return textures_;
    }

    std::string mtl() const {
        std::string out = "# ramus 0.1.0 material library\n";
        for (std::size_t i = 0; i < materials_.size(); ++i) {
            const Material& m = materials_[i];
            // Specular colour: dielectric F0 = 0.04, blending to the base colour for metals.
            const Vec3f ks = Vec3f::Constant(0.04f) * (1.0f - m.metallic) +
                             Vec3f(m.baseColor.head<3>()) * m.metallic;
            // Rounded to 0.001: the exponent is a shading hint, float noise would only clutter.
            const double gloss = 1.0 - static_cast<double>(m.roughness);
            const auto ns = static_cast<float>(std::round(900.0 * gloss * gloss * 1000.0) / 1000.0);
            const Vec3f ka = Vec3f::Zero();
            out += "\nnewmtl " + names_[i] + "\n";
            appendFloats(out, "Ka", ka.data(), 3);
            appendFloats(out, "Kd", m.baseColor.data(), 3);
            appendFloats(out, "Ks", ks.data(), 3);
            appendFloats(out, "Ns", &ns, 1);
            appendFloats(out, "d", &m.baseColor[3], 1);
            out += "illum 2\n";
            appendFloats(out, "Pr", &m.roughness, 1);
            appendFloats(out, "Pm", &m.metallic, 1);
            if (!baseColorFiles_[i].empty()) {
                out += "map_Kd " + baseColorFiles_[i] + "\n";
                // Leaf cards: the same image's alpha cuts the leaf out.
                if (m.alphaMask) out += "map_d " + baseColorFiles_[i] + "\n";
            }
            if (!normalFiles_[i].empty()) out += "norm " + normalFiles_[i] + "\n";
        }
        return out;
    }

private:
    std::string textureFile(const Image* image, const std::string& materialName) {
        if (image == nullptr) return {};
        for (const auto& [file, known] : textures_) {
            if (known == image) return file;
        }
        textures_.emplace_back(textureStem_ + "_" + materialName + ".png", image);
        return textures_.back().first;
    }

    std::string textureStem_;
    std::vector<Material> materials_;
    std::vector<std::string> names_, baseColorFiles_, normalFiles_;
    std::vector<std::pair<std::string, const Image*>> textures_;
};

struct VertexBase {
    std::size_t position = 1;  // OBJ indices are 1-based and global over the file
    std::size_t uv = 1;
    std::size_t normal = 1;
};

void appendIndex(std::string& out, std::size_t value) {
    char buf[24];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, result.ptr);
}

// " v", " v/vt", " v//vn" or " v/vt/vn" for vertex i of the instance.
void appendCorner(std::string& out, const Mesh& mesh, const VertexBase& base, std::uint32_t i) {
    out += ' ';
    appendIndex(out, base.position + i);
    if (mesh.uvs.empty() && mesh.normals.empty()) return;
    out += '/';
    if (!mesh.uvs.empty()) appendIndex(out, base.uv + i);
    if (!mesh.normals.empty()) {
        out += '/';
        appendIndex(out, base.normal + i);
    }
}

// Vertices of one placed mesh (those listed in `subset`, else all): positions by the world
// matrix, normals by its cofactor matrix (the inverse transpose up to scale, defined even for
// zero scale), uvs flipped to OBJ's bottom-left origin.
void appendVertices(std::string& out, const Mesh& mesh, const Mat4& world,
                    const std::vector<std::uint32_t>* subset = nullptr) {
    const Eigen::Matrix3d m = world.topLeftCorner<3, 3>();
    Eigen::Matrix3d cofactor;
    cofactor << m.col(1).cross(m.col(2)), m.col(2).cross(m.col(0)), m.col(0).cross(m.col(1));
    if (m.determinant() < 0.0) cofactor = -cofactor;
    const std::size_t count = subset ? subset->size() : mesh.positions.size();
    auto vertex = [&](std::size_t k) { return subset ? (*subset)[k] : k; };
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3f& p = mesh.positions[vertex(k)];
        const Vec3f w = (m * p.cast<double>() + world.topRightCorner<3, 1>()).cast<float>();
        appendFloats(out, "v", w.data(), 3);
    }
    for (std::size_t k = 0; k < count && !mesh.uvs.empty(); ++k) {
        const Vec2f& uv = mesh.uvs[vertex(k)];
        const Vec2f t(uv.x(), 1.0f - uv.y());
        appendFloats(out, "vt", t.data(), 2);
    }
    for (std::size_t k = 0; k < count && !mesh.normals.empty(); ++k) {
        Vec3 w = cofactor * mesh.normals[vertex(k)].cast<double>();
        const double len = w.norm();
        w = len > 1e-300 ? Vec3(w / len) : Vec3(Vec3::UnitY());
        const Vec3f wf = w.cast<float>();
        appendFloats(out, "vn", wf.data(), 3);
    }
}

void appendFace(std::string& out, const Mesh& mesh, const VertexBase& base, std::uint32_t k,
                bool mirrored, const std::vector<std::uint32_t>* local = nullptr) {
    auto corner = [&](std::uint32_t i) {
        const std::uint32_t v = mesh.indices[i];
        appendCorner(out, mesh, base, local ? (*local)[v] : v);
    };
    // A mirroring transform turns counter-clockwise faces clockwise: swap two corners back.
    out += 'f';
    corner(k);
    corner(mirrored ? k + 2 : k + 1);
    corner(mirrored ? k + 1 : k + 2);
    out += '\n';
}

void advance(VertexBase& base, const Mesh& mesh, std::size_t count) {
    base.position += count;
    base.uv += mesh.uvs.empty() ? 0 : count;
    base.normal += mesh.normals.empty() ? 0 : count;
}

bool isMirrored(const Mat4& world) { return world.topLeftCorner<3, 3>().determinant() < 0.0; }

// Per vertex: the skin joint (index into Skin::joints) with the largest weight (the first of
// equal ones).
std::vector<std::uint32_t> dominantJoints(const Mesh& mesh) {
    std::vector<std::uint32_t> joint(mesh.positions.size());
    for (std::size_t v = 0; v < joint.size(); ++v) {
        int best = 0;
        for (int s = 1; s < 4; ++s) best = mesh.weights[v][s] > mesh.weights[v][best] ? s : best;
        joint[v] = mesh.joints[v][static_cast<std::size_t>(best)];
    }
    return joint;
}

// A skinned mesh bound to several joints: one o/g group per joint, named like the joint's node
// (e.g. "thigh_L"), with the triangles whose first corner is bound most strongly to it and the
// vertices they use, so a skeleton's bones import as separate objects; materials stay as usemtl
// within each group.
void appendJointGroups(std::string& out, const Scene& scene, const io::MeshInstance& inst,
                       MaterialTable& materials, VertexBase& base) {
    const Mesh& mesh = scene.meshes[inst.mesh];
    const Skin& skin = scene.skins[static_cast<std::size_t>(scene.nodes[inst.node].skin)];
    const std::vector<std::uint32_t> joint = dominantJoints(mesh);
    const std::vector<MeshPrimitive> primitives = io::drawnPrimitives(mesh);
    // Per joint: (first index of the triangle, its primitive), in index-buffer order.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> groups(skin.joints.size());
    for (std::uint32_t p = 0; p < primitives.size(); ++p) {
        const MeshPrimitive& prim = primitives[p];
        for (std::uint32_t k = prim.firstIndex; k < prim.firstIndex + prim.indexCount; k += 3) {
            groups[joint[mesh.indices[k]]].emplace_back(k, p);
        }
    }
    const bool mirrored = isMirrored(inst.world);
    std::vector<std::uint32_t> local(mesh.positions.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (groups[g].empty()) continue;
        const int node = skin.joints[g];
        const std::string name = objName(scene.nodes[node].name, "node_" + std::to_string(node));
        out += "o " + name + "\ng " + name + "\n";
        std::vector<std::uint32_t> used;
        for (const auto& [k, p] : groups[g])
            used.insert(used.end(), &mesh.indices[k], &mesh.indices[k] + 3);
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        for (std::uint32_t i = 0; i < used.size(); ++i) local[used[i]] = i;
        appendVertices(out, mesh, inst.world, &used);
        std::uint32_t current = ~0u;
        for (const auto& [k, p] : groups[g]) {
            if (p != current) {
                out +=
                    "usemtl " + materials.nameOf(io::primitiveMaterial(mesh, primitives[p])) + "\n";
                current = p;
            }
            appendFace(out, mesh, base, k, mirrored, &local);
        }
        advance(base, mesh, used.size());
    }
}

// The joint node that every vertex of a skinned instance is bound to most strongly (a bone
// mesh of a skeleton), or -1 when they differ.
int singleJointNode(const Scene& scene, const io::MeshInstance& inst) {
    const std::vector<std::uint32_t> joint = dominantJoints(scene.meshes[inst.mesh]);
    if (joint.empty() || std::any_of(joint.begin(), joint.end(),
                                     [&joint](std::uint32_t j) { return j != joint[0]; })) {
        return -1;
    }
    return scene.skins[static_cast<std::size_t>(scene.nodes[inst.node].skin)].joints[joint[0]];
}

void appendInstance(std::string& out, const Scene& scene, const io::MeshInstance& inst,
                    MaterialTable& materials, VertexBase& base) {
    const Mesh& mesh = scene.meshes[inst.mesh];
    int namingNode = inst.node;  // the group is named like this node
    if (inst.node >= 0 && scene.nodes[inst.node].skin >= 0 && !mesh.joints.empty()) {
        namingNode = singleJointNode(scene, inst);
        if (namingNode < 0) {
            appendJointGroups(out, scene, inst, materials, base);
            return;
        }
    }
    const std::string fallback = namingNode >= 0 ? "node_" + std::to_string(namingNode)
                                                 : "mesh_" + std::to_string(inst.mesh);
    const std::string name =
        objName(namingNode >= 0 ? scene.nodes[namingNode].name : mesh.name, fallback);
    out += "o " + name + "\ng " + name + "\n";
    appendVertices(out, mesh, inst.world);
    const bool mirrored = isMirrored(inst.world);
    for (const MeshPrimitive& prim : io::drawnPrimitives(mesh)) {
        out += "usemtl " + materials.nameOf(io::primitiveMaterial(mesh, prim)) + "\n";
        for (std::uint32_t k = prim.firstIndex; k < prim.firstIndex + prim.indexCount; k += 3) {
            appendFace(out, mesh, base, k, mirrored);
        }
    }
    advance(base, mesh, mesh.positions.size());
}

}  // namespace

void writeObj(const Scene& scene, const std::string& path) {
    io::checkScene(scene, path);
    const std::filesystem::path mtlPath = std::filesystem::path(path).replace_extension(".mtl");
    std::string obj = "# ramus 0.1.0 OBJ export: Y up, metres, front +Z\n";
    obj += "mtllib " + mtlPath.filename().string() + "\n";
    MaterialTable materials(objName(std::filesystem::path(path).stem().string(), "model"));
    VertexBase base;
    for (const io::MeshInstance& inst : io::meshInstances(scene)) {
        appendInstance(obj, scene, inst, materials, base);
    }
    // Textures and the library first, so the OBJ never points at missing or stale files.
    for (const auto& [file, image] : materials.textureFiles()) {
        writeFileAtomic((mtlPath.parent_path() / file).string(), encodePng(*image));
    }
    writeFileAtomic(mtlPath.string(), materials.mtl());
    writeFileAtomic(path, obj);
}

}  // namespace ramus
