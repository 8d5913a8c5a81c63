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
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "core/text_builder.hpp"
#include "io/json_writer.hpp"
#include "io/scene_check.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/render.hpp"

namespace ramus {

namespace {

static_assert(std::endian::native == std::endian::little, "GLB is little-endian");

using io::JsonWriter;

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

// glTF tangents: unit xyz and w exactly ±1. A zero tangent becomes a unit vector perpendicular
// to the vertex normal (or +X without normals).
void unitTangents(const std::vector<Vec4f>& tangents, const std::vector<Vec3f>& normals,
                  float* out) {
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
        const float v[4] = {t.x(), t.y(), t.z(), tangents[i].w() < 0.0f ? -1.0f : 1.0f};
        std::memcpy(out + 4 * i, v, sizeof v);  // the BIN chunk is only 4-byte aligned
    }
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

// JSON's name for the type of the valid JSON value that starts with `first`.
const char* jsonTypeName(char first) {
    switch (first) {
        case '[':
            return "array";
        case '"':
            return "string";
        case 't':
        case 'f':
            return "boolean";
        case 'n':
            return "null";
        default:
            return "number";
    }
}

// Validates an extras text (a JSON object) and writes it compactly as the value of "extras";
// where() names the owner in error messages.
template <typename Where>
void writeExtras(JsonWriter& w, const std::string& text, Where where) {
    w.key("extras");
    const std::string error = w.jsonValue(text);
    if (!error.empty()) throw Error(where() + ": extras are not valid JSON: " + error);
    const std::size_t first = text.find_first_not_of(" \t\n\r");
    if (text[first] != '{') {
        throw Error(where() + ": extras must be a JSON object; got " +
                    std::string(jsonTypeName(text[first])));
    }
}

// Whether `text` is a JSON object without insignificant whitespace (what SceneNode::
// extrasCompact promises).
[[maybe_unused]] bool validCompactObject(const std::string& text) {
    std::string copy;
    return io::appendCompactJson(copy, text).empty() && copy == text && text.front() == '{';
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
        for (const VertexAttribute& a : m.attributes) bytes += a.values.size() * 4 + 3;
    }
    for (const Skin& skin : scene.skins) bytes += skin.inverseBindMatrices.size() * 64 + 3;
    return bytes + 3;
}

// Collects the JSON document (streamed, one string per top-level array) and the binary chunk of
// one GLB.
class GlbBuilder {
public:
    GlbBuilder(const Scene& scene, std::string context)
        : scene_(scene), context_(std::move(context)) {}

    /// Checks the scene and builds the file; call once.
    void encode();
    /// The file, in pieces that follow each other (the large JSON arrays are not joined into
    /// one copy: a file writer writes the pieces with one writev); valid while the builder is.
    std::span<const std::string_view> parts() const { return parts_; }

private:
    // A buffer view that many accessors read, planned before any mesh is written so that its
    // bytes lie in one range of the BIN chunk, then filled mesh by mesh. All meshes' vertex
    // data of one element size share one view (byteStride = that size, which glTF §3.6.2.4
    // asks of a vertex view read by several accessors), and all indices of one width share
    // one: a scene of many small meshes (a skeleton's bones) then has a handful of views
    // instead of five per mesh.
    struct SharedView {
        std::size_t bytes = 0;  // planned size
        int view = -1;          // the glTF buffer view, once laid out
        std::size_t start = 0;  // its first byte in the BIN chunk
        std::size_t used = 0;   // bytes filled so far (vertex views fill in order)
    };
    // What the plan decided for one mesh.
    struct MeshPlan {
        bool drawn = false;           // has triangles (else nothing is written)
        bool rigid = false;           // skinned with every vertex bound to one joint alone
        bool byteJoints = true;       // JOINTS_0 as UNSIGNED_BYTE (else UNSIGNED_SHORT)
        bool shortIndices = true;     // UNSIGNED_SHORT indices (else UNSIGNED_INT)
        bool indicesShared = false;   // an earlier mesh wrote the same indices
        std::size_t indexOffset = 0;  // the indices' byte offset in their index view
        // Skins that are not rigid, normalized (normalizeSkinning).
        std::vector<std::array<std::uint16_t, 4>> joints;
        std::vector<Vec4f> weights;
    };

    // A buffer view of `count` elements of T written by fill(T* destination), 4-byte aligned.
    // byteStride (0: none) is required when several accessors read one vertex view.
    template <typename T, typename Fill>
    int addBufferView(std::size_t count, int target, Fill fill, int byteStride = 0);
    int addAccessor(int view, std::size_t byteOffset, int componentType, std::size_t count,
                    const char* type, const Vec3f* bounds = nullptr, bool normalized = false);
    int addMaterial(const Material& material);
    int addTexture(const Image& image);
    SharedView& vertexView(std::size_t elementBytes) { return vertexViews_[elementBytes / 4 - 1]; }
    void planMesh(std::size_t m);
    void planSkin(const Mesh& mesh, MeshPlan& plan);
    void planIndices(std::size_t m);
    void layOutSharedViews();
    // An accessor of `count` vertex elements of `elementBytes` bytes (T components each), whose
    // data fill(T* destination) writes into the shared vertex view of that element size.
    template <typename T, typename Fill>
    int addVertexAccessor(std::size_t count, std::size_t elementBytes, int componentType,
                          const char* type, Fill fill, const Vec3f* bounds = nullptr,
                          bool normalized = false);
    void addVertexAttributes(const Mesh& mesh, const MeshPlan& plan, JsonWriter& attributes);
    void addSkinAttributes(const Mesh& mesh, const MeshPlan& plan, JsonWriter& attributes);
    void writeIndices(const Mesh& mesh, const MeshPlan& plan);
    int addIndexAccessor(int view, std::size_t byteOffset, bool shortIndices, std::size_t count);
    int addRigidWeights(std::size_t count);
    int addMesh(std::size_t m);
    void addNodes(const std::vector<int>& meshIndex);
    void addNode(std::size_t i, std::span<const int> children, const std::vector<int>& meshIndex);
    void addSkins();
    void writeName(JsonWriter& w, const std::string& name, const char* owner, std::size_t index);
    void writeDocument(std::string& out);
    // Makes room for `bytes` in the BIN chunk. The first allocation covers binBytesBound;
    // only data of unknown size (encoded PNG images) can make it grow.
    void reserveBin(std::size_t bytes) {
        if (bytes <= binCapacity_) return;
        const std::size_t capacity = std::max(bytes, 2 * binCapacity_);
        std::unique_ptr<char[]> larger(new char[capacity]);
        if (binSize_ > 0) std::memcpy(larger.get(), bin_.get(), binSize_);
        bin_ = std::move(larger);
        binCapacity_ = capacity;
    }
    // Pads the BIN chunk with zeros to the next multiple of 4 bytes (views and the chunk end).
    void alignBin() {
        while (binSize_ % 4 != 0) bin_[binSize_++] = '\0';
    }

    const Scene& scene_;
    std::string context_;
    // The BIN chunk: allocated at binBytesBound (no zero fill; grows only for images); binSize_
    // bytes are used.
    std::unique_ptr<char[]> bin_;
    // The file's own bytes: the 12-byte header, the JSON chunk's header and the JSON text
    // except the spliced arrays, the padding and the BIN chunk's header.
    std::string glue_;
    // Where a top-level array's elements (a text of their own) go into glue_'s text.
    struct Splice {
        std::size_t at;  // offset in glue_
        const std::string* text;
    };
    std::vector<Splice> splices_;
    std::vector<std::string_view> parts_;
    std::size_t binCapacity_ = 0, binSize_ = 0;
    std::string bufferViewsText_, accessorsText_, materialsText_, meshesText_, nodesText_,
        skinsText_, imagesText_, texturesText_;
    // The texts of the floats written so far (node transforms of mirrored bones, bounds of
    // twin meshes repeat), shared by the writers.
    std::unique_ptr<detail::FloatTextCache> floats_ = std::make_unique<detail::FloatTextCache>();
    JsonWriter bufferViews_{bufferViewsText_, floats_.get()},
        accessors_{accessorsText_, floats_.get()}, materials_{materialsText_, floats_.get()},
        meshes_{meshesText_, floats_.get()}, nodes_{nodesText_, floats_.get()},
        skins_{skinsText_, floats_.get()}, images_{imagesText_, floats_.get()},
        textures_{texturesText_, floats_.get()};
    int bufferViewCount_ = 0, accessorCount_ = 0, meshCount_ = 0;
    std::vector<int> roots_;
    std::vector<MeshPlan> plans_;  // one per scene mesh
    std::string attributesText_;   // the current mesh's attributes object (reused)
    // Shared views: vertex data of 4, 8, 12 and 16 bytes per element; indices by width.
    std::array<SharedView, 4> vertexViews_;
    SharedView shortIndexView_, intIndexView_;
    // Index buffers with equal contents (bone meshes fitted from one library model; boxes) are
    // written once, found by a hash of their values: hash → mesh.
    std::unordered_multimap<std::uint64_t, std::size_t> indexOwners_;
    // The mesh whose indices were written or reused last (none yet: the largest size_t).
    std::size_t lastIndexOwner_ = std::numeric_limits<std::size_t>::max();
    // (view, byte offset, count) → index accessor
    std::map<std::tuple<int, std::size_t, std::size_t>, int> indexAccessors_;
    // The rigid weights (1, 0, 0, 0) are written once, as long as the longest rigid mesh, at
    // the start of the 4-byte vertex view; every rigid mesh's WEIGHTS_0 accessor reads them.
    std::size_t rigidVertexCount_ = 0;
    std::unordered_map<std::size_t, int> rigidWeightAccessors_;  // by vertex count
    std::vector<Material> materialKeys_;
    std::size_t lastMaterial_ = 0;           // the material found or added last
    std::vector<const Image*> textureKeys_;  // one glTF image and texture each
};

template <typename T, typename Fill>
int GlbBuilder::addBufferView(std::size_t count, int target, Fill fill, int byteStride) {
    static_assert(alignof(T) <= 4, "buffer views are only 4-byte aligned");
    alignBin();
    const std::size_t offset = binSize_;
    const std::size_t bytes = count * sizeof(T);
    reserveBin(offset + bytes + 3);
    fill(reinterpret_cast<T*>(bin_.get() + offset));
    binSize_ += bytes;
    JsonWriter& w = bufferViews_;
    w.beginObject();
    w.key("buffer");
    w.value(0);
    w.key("byteOffset");
    w.value(std::uint64_t{offset});
    w.key("byteLength");
    w.value(std::uint64_t{bytes});
    if (byteStride != 0) {
        w.key("byteStride");
        w.value(byteStride);
    }
    if (target != 0) {  // inverse bind matrices have none
        w.key("target");
        w.value(target);
    }
    w.endObject();
    return bufferViewCount_++;
}

// bounds: {min, max} (POSITION needs them) or null; normalized: integers read as [0, 1].
// bounds: {min, max} (POSITION needs them) or null; normalized: integers read as [0, 1].
int GlbBuilder::addAccessor(int view, std::size_t byteOffset, int componentType, std::size_t count,
                            const char* type, const Vec3f* bounds, bool normalized) {
    char buffer[320];  // the literals (~110), 4 integers (≤ 80), 6 floats (≤ 6·15) and commas
    detail::TextBuilder t(buffer, buffer + sizeof buffer);
    t.text(R"({"bufferView":)").number(static_cast<std::uint64_t>(view));
    if (byteOffset != 0) t.text(R"(,"byteOffset":)").number(byteOffset);
    t.text(R"(,"componentType":)").number(static_cast<std::uint64_t>(componentType));
    if (normalized) t.text(R"(,"normalized":true)");
    t.text(R"(,"count":)").number(count).text(R"(,"type":")").text(std::string_view(type));
    t.text("\"");
    if (bounds != nullptr) {
        t.text(R"(,"min":)").floats(bounds[0].data(), 3, *floats_);
        t.text(R"(,"max":)").floats(bounds[1].data(), 3, *floats_);
    }
    t.text("}");
    accessors_.rawValue(t.view());
    return accessorCount_++;
}

int GlbBuilder::addMaterial(const Material& m) {
    // Meshes in a row often share their material (bones of one kind): that one first.
    if (lastMaterial_ < materialKeys_.size() && sameMaterial(materialKeys_[lastMaterial_], m)) {
        return static_cast<int>(lastMaterial_);
    }
    for (std::size_t i = 0; i < materialKeys_.size(); ++i) {
        if (sameMaterial(materialKeys_[i], m)) return static_cast<int>(lastMaterial_ = i);
    }
    lastMaterial_ = materialKeys_.size();
    materialKeys_.push_back(m);
    JsonWriter& w = materials_;
    w.beginObject();
    if (!m.name.empty()) writeName(w, m.name, "material", materialKeys_.size() - 1);
    w.key("pbrMetallicRoughness");
    w.beginObject();
    w.key("baseColorFactor");
    w.numbers(m.baseColor.data(), 4);
    w.key("metallicFactor");
    w.value(m.metallic);
    w.key("roughnessFactor");
    w.value(m.roughness);
    if (m.baseColorTexture) {
        w.key("baseColorTexture");
        w.beginObject();
        w.key("index");
        w.value(addTexture(*m.baseColorTexture));
        w.endObject();
    }
    w.endObject();
    if (m.normalTexture) {
        w.key("normalTexture");
        w.beginObject();
        w.key("index");
        w.value(addTexture(*m.normalTexture));
        w.endObject();
    }
    if (m.alphaMask) {
        w.key("alphaMode");
        w.value("MASK");
        w.key("alphaCutoff");
        w.value(m.alphaCutoff);
    } else if (m.baseColor.w() < 1.0f) {
        w.key("alphaMode");
        w.value("BLEND");
    }
    if (m.doubleSided) {
        w.key("doubleSided");
        w.value(true);
    }
    w.endObject();
    return static_cast<int>(materialKeys_.size()) - 1;
}

// A texture of `image` (PNG in a buffer view, sampler 0: linear filtering, REPEAT); an image
// used by several materials is stored once.
int GlbBuilder::addTexture(const Image& image) {
    for (std::size_t i = 0; i < textureKeys_.size(); ++i) {
        if (textureKeys_[i] == &image) return static_cast<int>(i);
    }
    const std::string png = encodePng(image);
    const int view = addBufferView<char>(
        png.size(), 0, [&png](char* dst) { std::memcpy(dst, png.data(), png.size()); });
    images_.beginObject();
    images_.key("bufferView");
    images_.value(view);
    images_.key("mimeType");
    images_.value("image/png");
    images_.endObject();
    textures_.beginObject();
    textures_.key("sampler");
    textures_.value(0);
    textures_.key("source");
    textures_.value(static_cast<int>(textureKeys_.size()));
    textures_.endObject();
    textureKeys_.push_back(&image);
    return static_cast<int>(textureKeys_.size()) - 1;
}

// Whether every vertex is bound to its first joint alone (weights (w, 0, 0, 0), w > 0): what
// skeleton bones are. normalizeSkinning then gives weights (1, 0, 0, 0) and joints (j, 0, 0, 0).
bool rigidlyBound(const Mesh& mesh) {
    for (const Vec4f& w : mesh.weights) {
        if (!(w[0] > 0.0f) || w[1] != 0.0f || w[2] != 0.0f || w[3] != 0.0f) return false;
    }
    return true;
}

// FNV-1a over the index values and the index width.
std::uint64_t indexHash(const std::vector<std::uint32_t>& indices, bool shortIndices) {
    std::uint64_t h = 1469598103934665603ull ^ (shortIndices ? 1u : 0u);
    for (std::uint32_t i : indices) h = (h ^ i) * 1099511628211ull;
    return h;
}

// Adds mesh m's data to the shared views' planned sizes.
void GlbBuilder::planMesh(std::size_t m) {
    const Mesh& mesh = scene_.meshes[m];
    MeshPlan& plan = plans_[m];
    plan.drawn = io::drawsTriangles(mesh);
    if (!plan.drawn) return;
    const std::size_t n = mesh.positions.size();
    vertexView(12).bytes += 12 * n;
    if (!mesh.normals.empty()) vertexView(12).bytes += 12 * n;
    if (!mesh.tangents.empty()) vertexView(16).bytes += 16 * n;
    if (!mesh.uvs.empty()) vertexView(8).bytes += 8 * n;
    if (!mesh.joints.empty()) planSkin(mesh, plan);
    for (const VertexAttribute& a : mesh.attributes) {
        const auto bytes = static_cast<std::size_t>(4 * a.components);
        vertexView(bytes).bytes += bytes * n;
    }
    planIndices(m);
}

// JOINTS_0 as UNSIGNED_BYTE when every joint index fits, else UNSIGNED_SHORT. WEIGHTS_0 as
// normalised UNSIGNED_BYTE (1, 0, 0, 0) when every vertex is rigidly bound (255 reads back as
// exactly 1), else as FLOAT — never a lossy quantization.
void GlbBuilder::planSkin(const Mesh& mesh, MeshPlan& plan) {
    const std::size_t n = mesh.joints.size();
    plan.rigid = rigidlyBound(mesh);
    std::uint16_t maxJoint = 0;
    if (plan.rigid) {
        for (const auto& j : mesh.joints) maxJoint = std::max(maxJoint, j[0]);
        rigidVertexCount_ = std::max(rigidVertexCount_, n);
    } else {
        normalizeSkinning(mesh, plan.joints, plan.weights);
        for (const auto& j : plan.joints) maxJoint = std::max({maxJoint, j[0], j[1], j[2], j[3]});
        vertexView(16).bytes += 16 * n;
    }
    plan.byteJoints = maxJoint <= 255;
    vertexView(plan.byteJoints ? 4 : 8).bytes += (plan.byteJoints ? 4 : 8) * n;
}

// The mesh's indices: UNSIGNED_SHORT when every index fits below 65535 (65535 is the
// primitive restart value), else UNSIGNED_INT; an earlier mesh's with the same values and width
// are reused.
void GlbBuilder::planIndices(std::size_t m) {
    const Mesh& mesh = scene_.meshes[m];
    MeshPlan& plan = plans_[m];
    plan.shortIndices = mesh.positions.size() <= 65535;
    // A single mesh (a tree without LODs) shares with nothing: no hash over its indices.
    const bool shareable = scene_.meshes.size() > 1;
    // Reuses the indices of mesh `owner` (which wrote them) when they are the same.
    auto shareWith = [&](std::size_t owner) {
        const MeshPlan& other = plans_[owner];
        if (other.shortIndices != plan.shortIndices ||
            scene_.meshes[owner].indices != mesh.indices) {
            return false;
        }
        plan.indexOffset = other.indexOffset;
        plan.indicesShared = true;
        lastIndexOwner_ = owner;
        return true;
    };
    // Meshes in a row often have the same indices (a skeleton's boxes): the last one that
    // wrote indices is compared first, without hashing (a chain of dependent multiplications).
    if (shareable && lastIndexOwner_ < m && shareWith(lastIndexOwner_)) return;
    const std::uint64_t hash = shareable ? indexHash(mesh.indices, plan.shortIndices) : 0;
    const auto [first, last] = indexOwners_.equal_range(hash);
    for (auto it = first; it != last; ++it) {
        if (shareWith(it->second)) return;
    }
    lastIndexOwner_ = m;
    SharedView& view = plan.shortIndices ? shortIndexView_ : intIndexView_;
    plan.indexOffset = view.bytes;
    view.bytes += mesh.indices.size() * (plan.shortIndices ? 2 : 4);
    if (shareable) indexOwners_.emplace(hash, m);
}

// Gives every planned shared view its range of the BIN chunk and its glTF buffer view, and
// writes the rigid weights.
void GlbBuilder::layOutSharedViews() {
    if (rigidVertexCount_ > 0) vertexView(4).bytes += 4 * rigidVertexCount_;
    auto layOut = [this](SharedView& shared, int target, int byteStride) {
        if (shared.bytes == 0) return;
        shared.view = addBufferView<char>(
            shared.bytes, target, [](char*) {}, byteStride);
        shared.start = binSize_ - shared.bytes;
    };
    for (std::size_t k = 0; k < vertexViews_.size(); ++k) {
        layOut(vertexViews_[k], kArrayBuffer, static_cast<int>(4 * (k + 1)));
    }
    layOut(intIndexView_, kElementArrayBuffer, 0);
    layOut(shortIndexView_, kElementArrayBuffer, 0);
    SharedView& weights = vertexView(4);
    if (rigidVertexCount_ > 0) {
        char* dst = bin_.get() + weights.start;
        for (std::size_t i = 0; i < 4 * rigidVertexCount_; ++i) dst[i] = i % 4 == 0 ? '\xff' : 0;
        weights.used = 4 * rigidVertexCount_;
    }
}

template <typename T, typename Fill>
int GlbBuilder::addVertexAccessor(std::size_t count, std::size_t elementBytes, int componentType,
                                  const char* type, Fill fill, const Vec3f* bounds,
                                  bool normalized) {
    static_assert(alignof(T) <= 4, "the BIN chunk is only 4-byte aligned");
    SharedView& shared = vertexView(elementBytes);
    const std::size_t offset = shared.used;
    RAMUS_ASSERT(offset + count * elementBytes <= shared.bytes);
    fill(reinterpret_cast<T*>(bin_.get() + shared.start + offset));
    shared.used += count * elementBytes;
    return addAccessor(shared.view, offset, componentType, count, type, bounds, normalized);
}

// Writes POSITION (with the min/max glTF requires), NORMAL (unit; a zero normal becomes +Y),
// TANGENT and TEXCOORD_0 accessors shared by all primitives of the mesh into the attributes
// object.
void GlbBuilder::addVertexAttributes(const Mesh& mesh, const MeshPlan& plan,
                                     JsonWriter& attributes) {
    const std::size_t n = mesh.positions.size();
    // Plain float loops: Eigen's per-vertex temporaries cost several times more here.
    float lo[3] = {mesh.positions[0].x(), mesh.positions[0].y(), mesh.positions[0].z()};
    float hi[3] = {lo[0], lo[1], lo[2]};
    const float* p = mesh.positions.data()->data();
    for (std::size_t i = 0; i < 3 * n; i += 3) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[i + k]);
            hi[k] = std::max(hi[k], p[i + k]);
        }
    }
    const Vec3f bounds[2] = {Vec3f(lo[0], lo[1], lo[2]), Vec3f(hi[0], hi[1], hi[2])};
    auto copyOf = [](const auto& values) {
        return [&values](char* dst) {
            std::memcpy(dst, values.data(), values.size() * sizeof(values[0]));
        };
    };
    attributes.key("POSITION");
    attributes.value(
        addVertexAccessor<char>(n, 12, kFloat, "VEC3", copyOf(mesh.positions), bounds));
    if (!mesh.normals.empty()) {
        attributes.key("NORMAL");
        attributes.value(addVertexAccessor<float>(n, 12, kFloat, "VEC3", [&mesh, n](float* dst) {
            const float* v = mesh.normals.data()->data();
            for (std::size_t i = 0; i < 3 * n; i += 3) {
                const float len =
                    std::sqrt(v[i] * v[i] + v[i + 1] * v[i + 1] + v[i + 2] * v[i + 2]);
                const bool usable = len > 1e-20f;
                dst[i] = usable ? v[i] / len : 0.0f;
                dst[i + 1] = usable ? v[i + 1] / len : 1.0f;
                dst[i + 2] = usable ? v[i + 2] / len : 0.0f;
            }
        }));
    }
    if (!mesh.tangents.empty()) {
        attributes.key("TANGENT");
        attributes.value(addVertexAccessor<float>(n, 16, kFloat, "VEC4", [&mesh](float* dst) {
            unitTangents(mesh.tangents, mesh.normals, dst);
        }));
    }
    if (!mesh.uvs.empty()) {
        attributes.key("TEXCOORD_0");
        attributes.value(addVertexAccessor<char>(n, 8, kFloat, "VEC2", copyOf(mesh.uvs)));
    }
    if (!mesh.joints.empty()) addSkinAttributes(mesh, plan, attributes);
    static const char* const kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4"};
    for (const VertexAttribute& a : mesh.attributes) {
        attributes.key(a.name);
        attributes.value(addVertexAccessor<char>(n, static_cast<std::size_t>(4 * a.components),
                                                 kFloat, kTypes[a.components - 1],
                                                 copyOf(a.values)));
    }
}

// JOINTS_0 and WEIGHTS_0 as planSkin decided.
void GlbBuilder::addSkinAttributes(const Mesh& mesh, const MeshPlan& plan, JsonWriter& attributes) {
    const std::size_t n = mesh.joints.size();
    // A rigid vertex's joints are (j, 0, 0, 0); the others come normalized.
    auto joint = [&](std::size_t v, int k) -> std::uint16_t {
        if (plan.rigid) return k == 0 ? mesh.joints[v][0] : 0;
        return plan.joints[v][k];
    };
    attributes.key("JOINTS_0");
    if (plan.byteJoints && plan.rigid) {  // (j, 0, 0, 0) per vertex: what bones have
        attributes.value(addVertexAccessor<std::uint8_t>(
            n, 4, kUnsignedByte, "VEC4", [&mesh, n](std::uint8_t* dst) {
                std::memset(dst, 0, 4 * n);
                for (std::size_t v = 0; v < n; ++v) {
                    dst[4 * v] = static_cast<std::uint8_t>(mesh.joints[v][0]);
                }
            }));
    } else if (plan.byteJoints) {
        attributes.value(
            addVertexAccessor<std::uint8_t>(n, 4, kUnsignedByte, "VEC4", [&](std::uint8_t* dst) {
                for (std::size_t v = 0; v < n; ++v) {
                    for (int k = 0; k < 4; ++k) *dst++ = static_cast<std::uint8_t>(joint(v, k));
                }
            }));
    } else {
        attributes.value(
            addVertexAccessor<std::uint16_t>(n, 8, kUnsignedShort, "VEC4", [&](std::uint16_t* dst) {
                for (std::size_t v = 0; v < n; ++v) {
                    for (int k = 0; k < 4; ++k) *dst++ = joint(v, k);
                }
            }));
    }
    attributes.key("WEIGHTS_0");
    if (plan.rigid) {
        attributes.value(addRigidWeights(n));
    } else {
        attributes.value(addVertexAccessor<char>(n, 16, kFloat, "VEC4", [&plan](char* dst) {
            std::memcpy(dst, plan.weights.data(), plan.weights.size() * sizeof(Vec4f));
        }));
    }
}

// The WEIGHTS_0 accessor of `count` rigidly bound vertices: normalised UNSIGNED_BYTE (1, 0, 0, 0)
// from the start of the 4-byte vertex view (layOutSharedViews wrote them there).
int GlbBuilder::addRigidWeights(std::size_t count) {
    const auto [it, added] = rigidWeightAccessors_.try_emplace(count, -1);
    if (added) {
        it->second =
            addAccessor(vertexView(4).view, 0, kUnsignedByte, count, "VEC4", nullptr, true);
    }
    return it->second;
}

// The mesh's indices at their planned place (unless an earlier mesh wrote the same ones).
void GlbBuilder::writeIndices(const Mesh& mesh, const MeshPlan& plan) {
    if (plan.indicesShared) return;
    const SharedView& view = plan.shortIndices ? shortIndexView_ : intIndexView_;
    char* dst = bin_.get() + view.start + plan.indexOffset;
    if (plan.shortIndices) {
        auto* out = reinterpret_cast<std::uint16_t*>(dst);
        for (std::uint32_t i : mesh.indices) *out++ = static_cast<std::uint16_t>(i);
    } else {
        std::memcpy(dst, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
    }
}

// An index accessor; the same range of the same view gets the same accessor.
int GlbBuilder::addIndexAccessor(int view, std::size_t byteOffset, bool shortIndices,
                                 std::size_t count) {
    const auto [it, added] = indexAccessors_.try_emplace({view, byteOffset, count}, -1);
    if (!added) return it->second;
    it->second = addAccessor(view, byteOffset, shortIndices ? kUnsignedShort : kUnsignedInt, count,
                             "SCALAR");
    return it->second;
}

// One glTF mesh: vertex accessors shared by its primitives, its indices, one index accessor and
// one glTF primitive per drawn MeshPrimitive. Returns -1 (nothing written) for meshes without
// triangles.
int GlbBuilder::addMesh(std::size_t m) {
    const Mesh& mesh = scene_.meshes[m];
    const MeshPlan& plan = plans_[m];
    if (!plan.drawn) return -1;
    // The drawn primitives (io::drawnPrimitives) without copying them.
    MeshPrimitive implicit;
    std::span<const MeshPrimitive> prims = mesh.primitives;
    if (prims.empty()) {
        implicit = io::wholeMeshPrimitive(mesh);
        prims = {&implicit, 1};
    }
    attributesText_.clear();
    JsonWriter attributes(attributesText_);
    attributes.beginObject();
    addVertexAttributes(mesh, plan, attributes);
    attributes.endObject();
    writeIndices(mesh, plan);
    const int indexView = (plan.shortIndices ? shortIndexView_ : intIndexView_).view;
    const std::size_t indexBytes = plan.shortIndices ? 2 : 4;
    JsonWriter& w = meshes_;
    w.beginObject();
    if (!mesh.name.empty()) writeName(w, mesh.name, "mesh", meshCount_);
    w.key("primitives");
    w.beginArray();
    std::size_t drawn = 0;
    for (const MeshPrimitive& p : prims) {
        if (p.indexCount == 0) continue;
        w.beginObject();
        w.key("attributes");
        w.rawValue(attributesText_);
        w.key("indices");
        w.value(addIndexAccessor(indexView, plan.indexOffset + p.firstIndex * indexBytes,
                                 plan.shortIndices, p.indexCount));
        w.key("material");
        w.value(addMaterial(io::primitiveMaterial(mesh, p)));
        if (!p.name.empty()) {
            w.key("extras");
            w.beginObject();
            writeName(w, p.name, "primitive", drawn);
            w.endObject();
        }
        w.endObject();
        ++drawn;
    }
    w.endArray();
    w.endObject();
    return meshCount_++;
}

// "name": the name of item `index` of kind `owner` ("node", "mesh", …).
void GlbBuilder::writeName(JsonWriter& w, const std::string& name, const char* owner,
                           std::size_t index) {
    w.key("name");
    try {
        w.value(name);
    } catch (const Error& e) {
        throw Error(context_ + ": " + owner + " " + std::to_string(index) + " name: " + e.what());
    }
}

void GlbBuilder::addNodes(const std::vector<int>& meshIndex) {
    if (scene_.nodes.empty()) {  // one root node per written mesh
        int count = 0;
        for (std::size_t m = 0; m < meshIndex.size(); ++m) {
            if (meshIndex[m] < 0) continue;
            nodes_.beginObject();
            if (!scene_.meshes[m].name.empty()) {
                writeName(nodes_, scene_.meshes[m].name, "mesh", m);
            }
            nodes_.key("mesh");
            nodes_.value(meshIndex[m]);
            nodes_.endObject();
            roots_.push_back(count++);
        }
        return;
    }
    // Children lists in node order, as offsets into one flat array.
    const std::size_t n = scene_.nodes.size();
    std::vector<int> childCount(n + 1, 0), children(n);
    for (const SceneNode& node : scene_.nodes) {
        if (node.parent >= 0) ++childCount[node.parent + 1];
    }
    for (std::size_t i = 0; i < n; ++i) childCount[i + 1] += childCount[i];
    std::vector<int> next(childCount.begin(), childCount.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        const int parent = scene_.nodes[i].parent;
        if (parent < 0) {
            roots_.push_back(static_cast<int>(i));
        } else {
            children[next[parent]++] = static_cast<int>(i);
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        addNode(i, {children.begin() + childCount[i], children.begin() + childCount[i + 1]},
                meshIndex);
    }
}

void GlbBuilder::addNode(std::size_t i, std::span<const int> children,
                         const std::vector<int>& meshIndex) {
    const SceneNode& n = scene_.nodes[i];
    JsonWriter& w = nodes_;
    w.beginObject();
    if (!n.name.empty()) writeName(w, n.name, "node", i);
    if (!children.empty()) {
        w.key("children");
        w.numbers(children.data(), children.size());
    }
    // mesh, skin and the transform in one piece (TextBuilder). The transform at float
    // precision, as readers store it (glTF's binary data are floats too): shorter and faster
    // to write than doubles' 17 digits.
    char buffer[240];  // the keys (~60), 2 integers (≤ 40), 10 floats (≤ 10·15) and commas
    detail::TextBuilder t(buffer, buffer + sizeof buffer);
    if (n.mesh >= 0 && meshIndex[n.mesh] >= 0) {
        t.text(R"(,"mesh":)").number(static_cast<std::uint64_t>(meshIndex[n.mesh]));
        if (n.skin >= 0) t.text(R"(,"skin":)").number(static_cast<std::uint64_t>(n.skin));
    }
    const Eigen::Quaterniond q = n.rotation.normalized();
    if (q.coeffs() != Eigen::Quaterniond::Identity().coeffs()) {
        const Eigen::Vector4f xyzw = q.coeffs().cast<float>();
        t.text(R"(,"rotation":)").floats(xyzw.data(), 4, *floats_);
    }
    if (n.scale != Vec3::Ones()) {
        const Vec3f scale = n.scale.cast<float>();
        t.text(R"(,"scale":)").floats(scale.data(), 3, *floats_);
    }
    if (n.translation != Vec3::Zero()) {
        const Vec3f translation = n.translation.cast<float>();
        t.text(R"(,"translation":)").floats(translation.data(), 3, *floats_);
    }
    std::string_view members = t.view();
    if (!members.empty()) members.remove_prefix(1);  // rawMembers writes the first comma
    w.rawMembers(members);
    if (!n.extrasJson.empty() && n.extrasCompact) {
        RAMUS_ASSERT(validCompactObject(n.extrasJson));
        w.key("extras");
        w.rawValue(n.extrasJson);
    } else if (!n.extrasJson.empty()) {
        writeExtras(w, n.extrasJson, [&] {
            return context_ + ": node " + std::to_string(i) + " ('" + n.name + "')";
        });
    }
    w.endObject();
}

// Skins with their inverse bind matrices (MAT4 FLOAT, column-major, in a buffer view without
// a target, as glTF §3.7.3.1 asks).
void GlbBuilder::addSkins() {
    for (std::size_t s = 0; s < scene_.skins.size(); ++s) {
        const Skin& skin = scene_.skins[s];
        JsonWriter& w = skins_;
        w.beginObject();
        if (!skin.name.empty()) writeName(w, skin.name, "skin", s);
        if (!skin.inverseBindMatrices.empty()) {
            const std::vector<Mat4>& matrices = skin.inverseBindMatrices;
            const int view = addBufferView<float>(16 * matrices.size(), 0, [&](float* dst) {
                for (const Mat4& m : matrices) {
                    for (int k = 0; k < 16; ++k) *dst++ = static_cast<float>(m(k % 4, k / 4));
                }
            });
            w.key("inverseBindMatrices");
            w.value(addAccessor(view, 0, kFloat, matrices.size(), "MAT4"));
        }
        if (skin.skeleton >= 0) {
            w.key("skeleton");
            w.value(skin.skeleton);
        }
        w.key("joints");
        w.numbers(skin.joints.data(), skin.joints.size());
        w.endObject();
    }
}

// The JSON chunk's text (appended to `out`): the top-level object with its arrays in a fixed
// order.
void GlbBuilder::writeDocument(std::string& out) {
    JsonWriter w(out);
    w.beginObject();
    w.key("asset");
    w.beginObject();
    const bool customGenerator = !scene_.generator.empty() && scene_.generator != "ramus";
    w.key("generator");
    try {
        w.value(customGenerator ? std::string_view(scene_.generator) : kGenerator);
    } catch (const Error& e) {
        throw Error(context_ + ": generator: " + e.what());
    }
    w.key("version");
    w.value("2.0");
    w.endObject();
    w.key("scene");
    w.value(0);
    w.key("scenes");
    w.beginArray();
    w.beginObject();
    if (!roots_.empty()) {
        w.key("nodes");
        w.numbers(roots_.data(), roots_.size());
    }
    if (!scene_.extrasJson.empty())
        writeExtras(w, scene_.extrasJson, [&] { return context_ + ": scene"; });
    w.endObject();
    w.endArray();
    const std::pair<const char*, const std::string*> arrays[] = {
        {"nodes", &nodesText_},         {"meshes", &meshesText_},          {"skins", &skinsText_},
        {"materials", &materialsText_}, {"textures", &texturesText_},      {"images", &imagesText_},
        {"accessors", &accessorsText_}, {"bufferViews", &bufferViewsText_}};
    for (const auto& [name, text] : arrays) {
        if (text->empty()) continue;
        w.key(name);
        w.beginArray();
        splices_.push_back({out.size(), text});  // the elements, comma-separated
        w.endArray();
    }
    if (!textureKeys_.empty()) {
        // glTF's defaults are REPEAT wrapping; linear, mipmapped filtering suits tiling bark.
        w.key("samplers");
        w.rawValue(R"([{"magFilter":9729,"minFilter":9987}])");
    }
    if (binSize_ != 0) {
        w.key("buffers");
        w.beginArray();
        w.beginObject();
        w.key("byteLength");
        w.value(std::uint64_t{binSize_});
        w.endObject();
        w.endArray();
    }
    w.endObject();
}

// Builds the file: `head` is the 12-byte header, the JSON chunk and the BIN chunk's header;
// the BIN chunk's bytes follow in bin() (kept apart so a file writer needs no joined copy).
void GlbBuilder::encode() {
    io::checkScene(scene_, context_);
    reserveBin(binBytesBound(scene_));
    std::size_t extrasBytes = 0;
    for (const SceneNode& node : scene_.nodes) extrasBytes += node.extrasJson.size();
    nodesText_.reserve(extrasBytes + 160 * scene_.nodes.size());
    // Typical sizes (a mesh has up to 6 accessors and one primitive), so the texts grow
    // without repeated copies in scenes of many small meshes (one per skeleton bone).
    const std::size_t meshes = scene_.meshes.size();
    accessorsText_.reserve(6 * 110 * meshes);
    meshesText_.reserve(220 * meshes);
    plans_.resize(meshes);
    for (std::size_t m = 0; m < meshes; ++m) planMesh(m);
    layOutSharedViews();
    std::vector<int> meshIndex(meshes);
    for (std::size_t m = 0; m < meshes; ++m) meshIndex[m] = addMesh(m);
    RAMUS_ASSERT(std::all_of(vertexViews_.begin(), vertexViews_.end(),
                             [](const SharedView& view) { return view.used == view.bytes; }));
    addNodes(meshIndex);
    addSkins();
    alignBin();

    // Header and JSON chunk header first (lengths filled in below), the JSON text with the
    // arrays spliced in, padding, then BIN's chunk header and BIN.
    glue_.reserve(20 + 256 + scene_.extrasJson.size() + 8 * roots_.size() +
                  scene_.generator.size() + 3 + 8);
    glue_.resize(20);
    writeDocument(glue_);
    std::size_t jsonBytes = glue_.size() - 20;
    for (const Splice& splice : splices_) jsonBytes += splice.text->size();
    const std::size_t padding = (4 - jsonBytes % 4) % 4;
    glue_.append(padding, ' ');
    jsonBytes += padding;
    const std::size_t jsonEnd = glue_.size();
    const std::size_t total = 20 + jsonBytes + (binSize_ == 0 ? 0 : 8 + binSize_);
    if (total > 0xFFFFFFFFu) throw Error(context_ + ": scene is too large for a GLB (> 4 GiB)");
    const std::uint32_t header[5] = {kGlbMagic, 2, static_cast<std::uint32_t>(total),
                                     static_cast<std::uint32_t>(jsonBytes), kChunkJson};
    std::memcpy(glue_.data(), header, sizeof header);
    if (binSize_ != 0) {
        const std::uint32_t binHeader[2] = {static_cast<std::uint32_t>(binSize_), kChunkBin};
        glue_.append(reinterpret_cast<const char*>(binHeader), sizeof binHeader);
    }
    // glue_ is complete: views into it stay valid from here on.
    const std::string_view glue = glue_;
    std::size_t from = 0;
    for (const Splice& splice : splices_) {
        parts_.push_back(glue.substr(from, splice.at - from));
        parts_.push_back(*splice.text);
        from = splice.at;
    }
    parts_.push_back(glue.substr(from, jsonEnd - from));
    if (binSize_ != 0) {
        parts_.push_back(glue.substr(jsonEnd));
        parts_.push_back({bin_.get(), binSize_});
    }
}

}  // namespace

std::string encodeGlb(const Scene& scene) {
    GlbBuilder builder(scene, "scene");
    builder.encode();
    std::string out;
    std::size_t bytes = 0;
    for (const std::string_view part : builder.parts()) bytes += part.size();
    out.reserve(bytes);
    for (const std::string_view part : builder.parts()) out += part;
    return out;
}

void writeGlb(const Scene& scene, const std::string& path) {
    GlbBuilder builder(scene, path);
    builder.encode();
    writeFileAtomic(path, builder.parts());
}

}  // namespace ramus
