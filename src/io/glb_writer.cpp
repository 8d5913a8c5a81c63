// Based on: the glTF 2.0 specification (Khronos, https://registry.khronos.org/glTF/specs/2.0/
// glTF-2.0.html), §3.6 binary data storage (accessors, buffer views, alignment), §3.7 meshes,
// §3.9 materials, §4.4 GLB file format (12-byte header, JSON chunk padded with spaces, BIN
// chunk padded with zeros, 4-byte alignment).
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "io/scene_check.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {

namespace {

static_assert(std::endian::native == std::endian::little, "GLB is little-endian");

using Json = nlohmann::ordered_json;

constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr const char* kGenerator = "ramus 0.1.0";

// A float as the JSON number with the fewest digits that reads back as the same float.
double jsonFloat(float v) {
    const std::string text = io::formatFloat(v);
    double d = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), d);
    return d;
}

Json jsonVec(const float* v, int n) {
    Json a = Json::array();
    for (int i = 0; i < n; ++i) a.push_back(jsonFloat(v[i]));
    return a;
}

// Unit normals as glTF requires; a zero normal (degenerate geometry) becomes +Y.
std::vector<Vec3f> unitNormals(const std::vector<Vec3f>& normals) {
    std::vector<Vec3f> out(normals.size());
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const float len = normals[i].norm();
        out[i] = len > 1e-20f ? Vec3f(normals[i] / len) : Vec3f(0.0f, 1.0f, 0.0f);
    }
    return out;
}

// glTF tangents: unit xyz and w exactly ±1. A zero tangent becomes a unit vector perpendicular
// to the vertex normal (or +X without normals).
std::vector<Vec4f> unitTangents(const std::vector<Vec4f>& tangents,
                                const std::vector<Vec3f>& normals) {
    std::vector<Vec4f> out(tangents.size());
    for (std::size_t i = 0; i < tangents.size(); ++i) {
        Vec3f t = tangents[i].head<3>();
        const float len = t.norm();
        if (len > 1e-20f) {
            t /= len;
        } else if (!normals.empty()) {
            const Vec3f& n = normals[i];
            t = std::abs(n.x()) < 0.9f ? Vec3f::UnitX().cross(n) : Vec3f::UnitY().cross(n);
            t = t.norm() > 1e-20f ? Vec3f(t.normalized()) : Vec3f::UnitX();
        } else {
            t = Vec3f::UnitX();
        }
        out[i] = Vec4f(t.x(), t.y(), t.z(), tangents[i].w() < 0.0f ? -1.0f : 1.0f);
    }
    return out;
}

// glTF WEIGHTS_0: each vertex's weights divided by their sum (checkScene allows ±0.001), the
// weights of a joint listed twice merged into its first slot, and JOINTS_0 entries of unused
// slots set to 0 (the validator warns about non-zero joints with zero weight).
void normalizeSkinning(const Mesh& mesh, std::vector<std::array<std::uint16_t, 4>>& joints,
                       std::vector<Vec4f>& weights) {
    joints = mesh.joints;
    weights.resize(mesh.weights.size());
    for (std::size_t v = 0; v < joints.size(); ++v) {
        std::array<double, 4> w{};
        for (int k = 0; k < 4; ++k) {
            int first = 0;
            while (joints[v][first] != joints[v][k]) ++first;
            w[first] += mesh.weights[v][k];
        }
        const double sum = w[0] + w[1] + w[2] + w[3];
        for (int k = 0; k < 4; ++k) {
            weights[v][k] = static_cast<float>(w[k] / sum);
            if (weights[v][k] == 0.0f) joints[v][k] = 0;
        }
    }
}

Json materialJson(const Material& m) {
    Json pbr;
    pbr["baseColorFactor"] = jsonVec(m.baseColor.data(), 4);
    pbr["metallicFactor"] = jsonFloat(m.metallic);
    pbr["roughnessFactor"] = jsonFloat(m.roughness);
    Json j;
    if (!m.name.empty()) j["name"] = m.name;
    j["pbrMetallicRoughness"] = std::move(pbr);
    if (m.baseColor.w() < 1.0f) j["alphaMode"] = "BLEND";
    if (m.doubleSided) j["doubleSided"] = true;
    return j;
}

bool sameMaterial(const Material& a, const Material& b) {
    return a.name == b.name && a.baseColor == b.baseColor && a.metallic == b.metallic &&
           a.roughness == b.roughness && a.doubleSided == b.doubleSided;
}

Json parseExtras(const std::string& text, const std::string& where) {
    Json extras;
    try {
        extras = Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw Error(where + ": extras are not valid JSON: " + e.what());
    }
    if (!extras.is_object()) {
        throw Error(where + ": extras must be a JSON object; got " +
                    std::string(extras.type_name()));
    }
    return extras;
}

// An upper bound of the BIN chunk's size (every attribute at full width, 3 bytes of alignment
// padding per buffer view), so the chunk is allocated once.
std::size_t binBytesBound(const Scene& scene) {
    std::size_t bytes = 0;
    for (const Mesh& m : scene.meshes) {
        bytes += m.positions.size() * sizeof(Vec3f) + m.normals.size() * sizeof(Vec3f) +
                 m.tangents.size() * sizeof(Vec4f) + m.uvs.size() * sizeof(Vec2f) +
                 m.joints.size() * sizeof(m.joints[0]) + m.weights.size() * sizeof(Vec4f) +
                 m.indices.size() * sizeof(std::uint32_t) + 7 * 3;
    }
    for (const Skin& skin : scene.skins) bytes += skin.inverseBindMatrices.size() * 64 + 3;
    return bytes + 3;
}

// Collects the JSON document and the binary chunk of one GLB.
class GlbBuilder {
public:
    GlbBuilder(const Scene& scene, std::string context)
        : scene_(scene), context_(std::move(context)) {}

    std::string encode();

private:
    template <typename T>
    int addBufferView(const std::vector<T>& data, int target);
    int addAccessor(int view, std::size_t byteOffset, int componentType, std::size_t count,
                    const char* type);
    int addMaterial(const Material& material);
    int addVertexAttributes(const Mesh& mesh, Json& attributes);
    void addSkinAttributes(const Mesh& mesh, Json& attributes);
    int addMesh(const Mesh& mesh);
    void addNodes(const std::vector<int>& meshIndex);
    void addSkins();
    Json sceneJson() const;

    const Scene& scene_;
    std::string context_;
    std::string bin_;
    Json bufferViews_ = Json::array();
    Json accessors_ = Json::array();
    Json materials_ = Json::array();
    Json meshes_ = Json::array();
    Json nodes_ = Json::array();
    Json skins_ = Json::array();
    std::vector<int> roots_;
    std::vector<Material> materialKeys_;
};

template <typename T>
int GlbBuilder::addBufferView(const std::vector<T>& data, int target) {
    bin_.resize((bin_.size() + 3) & ~std::size_t{3}, '\0');  // 4-byte aligned views
    const std::size_t offset = bin_.size();
    const std::size_t bytes = data.size() * sizeof(T);
    bin_.resize(offset + bytes);
    std::memcpy(bin_.data() + offset, data.data(), bytes);
    Json view;
    view["buffer"] = 0;
    view["byteOffset"] = offset;
    view["byteLength"] = bytes;
    if (target != 0) view["target"] = target;  // inverse bind matrices have none
    bufferViews_.push_back(std::move(view));
    return static_cast<int>(bufferViews_.size()) - 1;
}

int GlbBuilder::addAccessor(int view, std::size_t byteOffset, int componentType, std::size_t count,
                            const char* type) {
    Json a;
    a["bufferView"] = view;
    if (byteOffset != 0) a["byteOffset"] = byteOffset;
    a["componentType"] = componentType;
    a["count"] = count;
    a["type"] = type;
    accessors_.push_back(std::move(a));
    return static_cast<int>(accessors_.size()) - 1;
}

int GlbBuilder::addMaterial(const Material& material) {
    for (std::size_t i = 0; i < materialKeys_.size(); ++i) {
        if (sameMaterial(materialKeys_[i], material)) return static_cast<int>(i);
    }
    materialKeys_.push_back(material);
    materials_.push_back(materialJson(material));
    return static_cast<int>(materials_.size()) - 1;
}

// Writes POSITION (with the min/max glTF requires), NORMAL, TANGENT and TEXCOORD_0 accessors
// shared by all primitives of the mesh; returns the POSITION accessor.
int GlbBuilder::addVertexAttributes(const Mesh& mesh, Json& attributes) {
    const std::size_t n = mesh.positions.size();
    Vec3f lo = mesh.positions[0], hi = mesh.positions[0];
    for (const Vec3f& p : mesh.positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const int position =
        addAccessor(addBufferView(mesh.positions, kArrayBuffer), 0, kFloat, n, "VEC3");
    accessors_[position]["min"] = jsonVec(lo.data(), 3);
    accessors_[position]["max"] = jsonVec(hi.data(), 3);
    attributes["POSITION"] = position;
    if (!mesh.normals.empty()) {
        const int view = addBufferView(unitNormals(mesh.normals), kArrayBuffer);
        attributes["NORMAL"] = addAccessor(view, 0, kFloat, n, "VEC3");
    }
    if (!mesh.tangents.empty()) {
        const int view = addBufferView(unitTangents(mesh.tangents, mesh.normals), kArrayBuffer);
        attributes["TANGENT"] = addAccessor(view, 0, kFloat, n, "VEC4");
    }
    if (!mesh.uvs.empty()) {
        const int view = addBufferView(mesh.uvs, kArrayBuffer);
        attributes["TEXCOORD_0"] = addAccessor(view, 0, kFloat, n, "VEC2");
    }
    if (!mesh.joints.empty()) addSkinAttributes(mesh, attributes);
    return position;
}

// JOINTS_0 as UNSIGNED_BYTE when every joint index fits, else UNSIGNED_SHORT; WEIGHTS_0 as
// normalised FLOAT.
void GlbBuilder::addSkinAttributes(const Mesh& mesh, Json& attributes) {
    std::vector<std::array<std::uint16_t, 4>> joints;
    std::vector<Vec4f> weights;
    normalizeSkinning(mesh, joints, weights);
    std::uint16_t maxJoint = 0;
    for (const auto& j : joints) maxJoint = std::max({maxJoint, j[0], j[1], j[2], j[3]});
    int jointView = 0;
    if (maxJoint <= 255) {
        std::vector<std::array<std::uint8_t, 4>> narrow(joints.size());
        for (std::size_t v = 0; v < joints.size(); ++v) {
            for (int k = 0; k < 4; ++k) narrow[v][k] = static_cast<std::uint8_t>(joints[v][k]);
        }
        jointView = addBufferView(narrow, kArrayBuffer);
    } else {
        jointView = addBufferView(joints, kArrayBuffer);
    }
    const std::size_t n = joints.size();
    attributes["JOINTS_0"] =
        addAccessor(jointView, 0, maxJoint <= 255 ? kUnsignedByte : kUnsignedShort, n, "VEC4");
    attributes["WEIGHTS_0"] =
        addAccessor(addBufferView(weights, kArrayBuffer), 0, kFloat, n, "VEC4");
}

// One glTF mesh: shared vertex accessors, one index buffer view, one index accessor and one
// glTF primitive per drawn MeshPrimitive. Returns -1 (nothing written) for meshes without
// triangles.
int GlbBuilder::addMesh(const Mesh& mesh) {
    const std::vector<MeshPrimitive> prims = io::drawnPrimitives(mesh);
    if (prims.empty()) return -1;
    Json attributes;
    addVertexAttributes(mesh, attributes);
    // UNSIGNED_SHORT when every index fits below 65535 (65535 is the primitive restart value).
    const bool shortIndices = mesh.positions.size() <= 65535;
    int indexView = 0;
    if (shortIndices) {
        std::vector<std::uint16_t> narrow(mesh.indices.size());
        for (std::size_t i = 0; i < narrow.size(); ++i) {
            narrow[i] = static_cast<std::uint16_t>(mesh.indices[i]);
        }
        indexView = addBufferView(narrow, kElementArrayBuffer);
    } else {
        indexView = addBufferView(mesh.indices, kElementArrayBuffer);
    }
    const std::size_t indexSize = shortIndices ? 2 : 4;
    Json primitives = Json::array();
    for (const MeshPrimitive& p : prims) {
        Json prim;
        prim["attributes"] = attributes;
        prim["indices"] =
            addAccessor(indexView, p.firstIndex * indexSize,
                        shortIndices ? kUnsignedShort : kUnsignedInt, p.indexCount, "SCALAR");
        prim["material"] = addMaterial(io::primitiveMaterial(mesh, p));
        if (!p.name.empty()) prim["extras"] = Json{{"name", p.name}};
        primitives.push_back(std::move(prim));
    }
    Json j;
    if (!mesh.name.empty()) j["name"] = mesh.name;
    j["primitives"] = std::move(primitives);
    meshes_.push_back(std::move(j));
    return static_cast<int>(meshes_.size()) - 1;
}

void GlbBuilder::addNodes(const std::vector<int>& meshIndex) {
    if (scene_.nodes.empty()) {  // one root node per written mesh
        for (std::size_t m = 0; m < meshIndex.size(); ++m) {
            if (meshIndex[m] < 0) continue;
            Json node;
            if (!scene_.meshes[m].name.empty()) node["name"] = scene_.meshes[m].name;
            node["mesh"] = meshIndex[m];
            roots_.push_back(static_cast<int>(nodes_.size()));
            nodes_.push_back(std::move(node));
        }
        return;
    }
    std::vector<std::vector<int>> children(scene_.nodes.size());
    for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
        const int parent = scene_.nodes[i].parent;
        (parent < 0 ? roots_ : children[parent]).push_back(static_cast<int>(i));
    }
    for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
        const SceneNode& n = scene_.nodes[i];
        Json node;
        if (!n.name.empty()) node["name"] = n.name;
        if (!children[i].empty()) node["children"] = children[i];
        if (n.mesh >= 0 && meshIndex[n.mesh] >= 0) {
            node["mesh"] = meshIndex[n.mesh];
            if (n.skin >= 0) node["skin"] = n.skin;
        }
        const Eigen::Quaterniond q = n.rotation.normalized();
        if (q.coeffs() != Eigen::Quaterniond::Identity().coeffs()) {
            node["rotation"] = {q.x(), q.y(), q.z(), q.w()};
        }
        if (n.scale != Vec3::Ones()) node["scale"] = {n.scale.x(), n.scale.y(), n.scale.z()};
        if (n.translation != Vec3::Zero()) {
            node["translation"] = {n.translation.x(), n.translation.y(), n.translation.z()};
        }
        if (!n.extrasJson.empty()) {
            node["extras"] = parseExtras(
                n.extrasJson, context_ + ": node " + std::to_string(i) + " ('" + n.name + "')");
        }
        nodes_.push_back(std::move(node));
    }
}

// Skins with their inverse bind matrices (MAT4 FLOAT, column-major, in a buffer view without
// a target, as glTF §3.7.3.1 asks).
void GlbBuilder::addSkins() {
    for (const Skin& skin : scene_.skins) {
        Json j;
        if (!skin.name.empty()) j["name"] = skin.name;
        if (!skin.inverseBindMatrices.empty()) {
            std::vector<float> matrices;
            matrices.reserve(16 * skin.inverseBindMatrices.size());
            for (const Mat4& m : skin.inverseBindMatrices) {
                for (int k = 0; k < 16; ++k)
                    matrices.push_back(static_cast<float>(m(k % 4, k / 4)));
            }
            j["inverseBindMatrices"] = addAccessor(addBufferView(matrices, 0), 0, kFloat,
                                                   skin.inverseBindMatrices.size(), "MAT4");
        }
        if (skin.skeleton >= 0) j["skeleton"] = skin.skeleton;
        j["joints"] = skin.joints;
        skins_.push_back(std::move(j));
    }
}

Json GlbBuilder::sceneJson() const {
    Json s = Json::object();
    if (!roots_.empty()) s["nodes"] = roots_;
    if (!scene_.extrasJson.empty()) {
        s["extras"] = parseExtras(scene_.extrasJson, context_ + ": scene");
    }
    return s;
}

std::string GlbBuilder::encode() {
    io::checkScene(scene_, context_);
    bin_.reserve(binBytesBound(scene_));
    std::vector<int> meshIndex;
    for (const Mesh& mesh : scene_.meshes) meshIndex.push_back(addMesh(mesh));
    addNodes(meshIndex);
    addSkins();
    bin_.resize((bin_.size() + 3) & ~std::size_t{3}, '\0');

    Json root;
    const bool customGenerator = !scene_.generator.empty() && scene_.generator != "ramus";
    root["asset"] = {{"generator", customGenerator ? scene_.generator : kGenerator},
                     {"version", "2.0"}};
    root["scene"] = 0;
    root["scenes"] = Json::array({sceneJson()});
    if (!nodes_.empty()) root["nodes"] = std::move(nodes_);
    if (!meshes_.empty()) root["meshes"] = std::move(meshes_);
    if (!skins_.empty()) root["skins"] = std::move(skins_);
    if (!materials_.empty()) root["materials"] = std::move(materials_);
    if (!accessors_.empty()) root["accessors"] = std::move(accessors_);
    if (!bufferViews_.empty()) root["bufferViews"] = std::move(bufferViews_);
    if (!bin_.empty()) root["buffers"] = Json::array({Json{{"byteLength", bin_.size()}}});

    std::string json = root.dump();
    json.resize((json.size() + 3) & ~std::size_t{3}, ' ');
    const std::size_t total = 12 + 8 + json.size() + (bin_.empty() ? 0 : 8 + bin_.size());
    if (total > 0xFFFFFFFFu) throw Error(context_ + ": scene is too large for a GLB (> 4 GiB)");

    std::string out;
    out.reserve(total);
    auto put32 = [&out](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    put32(kGlbMagic);
    put32(2);
    put32(static_cast<std::uint32_t>(total));
    put32(static_cast<std::uint32_t>(json.size()));
    put32(kChunkJson);
    out += json;
    if (!bin_.empty()) {
        put32(static_cast<std::uint32_t>(bin_.size()));
        put32(kChunkBin);
        out += bin_;
    }
    return out;
}

}  // namespace

std::string encodeGlb(const Scene& scene) { return GlbBuilder(scene, "scene").encode(); }

void writeGlb(const Scene& scene, const std::string& path) {
    writeFileAtomic(path, GlbBuilder(scene, path).encode());
}

}  // namespace ramus
