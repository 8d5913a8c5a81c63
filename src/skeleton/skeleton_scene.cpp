// Based on: the glTF 2.0 specification (Khronos), §3.5 nodes and hierarchy, §3.7.3 skins
// (joints, inverse bind matrices, skeleton root); DESIGN.md "glTF" (axes, node names, extras);
// seed 000 §5.2 (bones as boxes in their own frames, joints with degrees of freedom).
#include "ramus/skeleton_scene.hpp"

#include <array>
#include <charconv>
#include <cmath>

#include "ramus/error.hpp"
#include "skeleton/number_text.hpp"

namespace ramus {

namespace {

// Internal axes → glTF axes: internal z (left) → X, y → Y, −x (front) → Z.
const Mat3 kInternalToGltf = (Mat3() << 0, 0, 1, 0, 1, 0, -1, 0, 0).finished();
// Node frame → bone frame: node +Y = bone +x, node +X = bone −y, node +Z = bone +z.
const Mat3 kBoneFromNode = (Mat3() << 0, 1, 0, -1, 0, 0, 0, 0, 1).finished();

// ---- boxes -----------------------------------------------------------------------------------

constexpr int kBoxVertices = 24;
constexpr int kBoxIndices = 36;

// A box in the bone frame: 4 corners per face with the face normal, corners counter-clockwise
// seen from outside. Returns false for boxes without volume.
struct BoxVertices {
    std::array<Vec3f, kBoxVertices> positions;
    std::array<Vec3f, kBoxVertices> normals;
};

// Per box vertex: the face axis, the face sign and the corners' (u, w) choice of hi (1) or
// lo (0), where (u, w, axis) is right-handed; CCW seen from +axis, reversed for the −axis face.
struct BoxCorner {
    int axis, sign, hiU, hiW;
};
constexpr std::array<BoxCorner, kBoxVertices> boxCorners() {
    std::array<BoxCorner, kBoxVertices> corners{};
    constexpr int order[2][4][2] = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                    {{0, 0}, {0, 1}, {1, 1}, {1, 0}}};
    int v = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign : {1, -1}) {
            for (const auto& c : order[sign > 0 ? 0 : 1]) corners[v++] = {axis, sign, c[0], c[1]};
        }
    }
    return corners;
}
constexpr std::array<BoxCorner, kBoxVertices> kBoxCorners = boxCorners();

// Per box vertex: its corner, bit k set where the vertex is at the box's hi end along axis k.
constexpr std::array<int, kBoxVertices> boxCornerOf() {
    std::array<int, kBoxVertices> corner{};
    for (int v = 0; v < kBoxVertices; ++v) {
        const BoxCorner& c = kBoxCorners[v];
        const int u = (c.axis + 1) % 3, w = (c.axis + 2) % 3;
        corner[v] = (c.sign > 0 ? 1 << c.axis : 0) | (c.hiU << u) | (c.hiW << w);
    }
    return corner;
}
constexpr std::array<int, kBoxVertices> kBoxCornerOf = boxCornerOf();

// The box's lowest and highest corner; false for boxes without volume.
bool boxBounds(const Vec3& extents, Vec3f& lo, Vec3f& hi) {
    if (!(extents.minCoeff() > 0.0) || !std::isfinite(extents.maxCoeff())) return false;
    lo = Vec3f(0.0f, static_cast<float>(-extents.y() / 2), static_cast<float>(-extents.z() / 2));
    hi = Vec3f(static_cast<float>(extents.x()), static_cast<float>(extents.y() / 2),
               static_cast<float>(extents.z() / 2));
    return true;
}

bool makeBox(const Vec3& extents, BoxVertices& box) {
    Vec3f lo, hi;
    if (!boxBounds(extents, lo, hi)) return false;
    for (int v = 0; v < kBoxVertices; ++v) {
        const BoxCorner& c = kBoxCorners[v];
        const int u = (c.axis + 1) % 3, w = (c.axis + 2) % 3;
        Vec3f p;
        p[c.axis] = c.sign > 0 ? hi[c.axis] : lo[c.axis];
        p[u] = c.hiU ? hi[u] : lo[u];
        p[w] = c.hiW ? hi[w] : lo[w];
        box.positions[v] = p;
        box.normals[v] = Vec3f::Zero();
        box.normals[v][c.axis] = static_cast<float>(c.sign);
    }
    return true;
}

// Indices of the box's 12 triangles (two per face of 4 corners).
constexpr std::array<std::uint32_t, kBoxIndices> boxIndices() {
    std::array<std::uint32_t, kBoxIndices> indices{};
    for (std::uint32_t f = 0; f < 6; ++f) {
        const std::uint32_t corner[6] = {0, 1, 2, 0, 2, 3};
        for (std::uint32_t k = 0; k < 6; ++k) indices[f * 6 + k] = f * 4 + corner[k];
    }
    return indices;
}
constexpr std::array<std::uint32_t, kBoxIndices> kBoxIndexPattern = boxIndices();

// ---- extras JSON -----------------------------------------------------------------------------

// Shortest round-trip text; −0 is written as 0.
void appendNumber(std::string& out, double value) { detail::appendShortest(out, value); }

void appendVector(std::string& out, const double* v, int n) {
    out += '[';
    for (int i = 0; i < n; ++i) {
        if (i > 0) out += ',';
        appendNumber(out, v[i]);
    }
    out += ']';
}

// "key":"value" (names from the vocabulary: no characters that need escaping).
void appendField(std::string& out, const char* key, std::string_view value) {
    out += '"';
    out += key;
    out += "\":\"";
    out += value;
    out += "\",";
}

// A unit quaternion of `rotation` with w ≥ 0 (q and −q are the same rotation; one sign keeps
// the files tidy).
Eigen::Quaterniond canonicalQuaternion(const Mat3& rotation) {
    Eigen::Quaterniond q(rotation);
    q.normalize();
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    return q;
}

// The node's local rotation with all joint angles 0 (see skeletonToScene).
Mat3 restLocalRotation(const Bone& bone) {
    const Mat3 rotation = kBoneFromNode.transpose() * bone.joint.rest * kBoneFromNode;
    return bone.parent < 0 ? Mat3(kInternalToGltf * kBoneFromNode * rotation) : rotation;
}

void appendJoint(std::string& out, const Bone& bone) {
    const Eigen::Quaterniond rest = canonicalQuaternion(restLocalRotation(bone));
    const double q[4] = {rest.x(), rest.y(), rest.z(), rest.w()};
    out += "\"joint\":{\"rest_rotation\":";
    appendVector(out, q, 4);
    out += ",\"dofs\":[";
    for (int i = 0; i < bone.joint.dofCount; ++i) {
        const JointDof& dof = bone.joint.dofs[i];
        const Vec3 axis = kBoneFromNode.transpose() * dof.axis.normalized();
        out += i > 0 ? ",{\"axis\":" : "{\"axis\":";
        appendVector(out, axis.data(), 3);
        out += ",\"angle_deg\":";
        appendNumber(out, dof.angleDeg);
        out += ",\"min_deg\":";
        appendNumber(out, dof.minDeg);
        out += ",\"max_deg\":";
        appendNumber(out, dof.maxDeg);
        out += '}';
    }
    out += "]}";
}

std::string boneExtras(const Bone& bone, double metresPerPixel) {
    std::string out;
    out.reserve(448);
    out += '{';
    appendField(out, "kind", boneKindName(bone.kind));
    appendField(out, "side", sideName(bone.side));
    if (bone.region != SpineRegion::None) appendField(out, "region", spineRegionName(bone.region));
    if (bone.index > 0) {
        out += "\"index\":";
        appendNumber(out, bone.index);
        out += ',';
    }
    if (bone.limb != LimbKind::None) {
        appendField(out, "limb", limbKindName(bone.limb));
        appendField(out, "attachment", attachmentName(bone.attachment));
    }
    if (bone.doubleJoint) out += "\"double_joint\":true,";
    const Vec3 extents = bone.extents * metresPerPixel;
    out += "\"extents_m\":";
    appendVector(out, extents.data(), 3);
    out += ',';
    appendJoint(out, bone);
    out += '}';
    return out;
}

std::string sceneExtras(const Skeleton& skeleton) {
    std::string out = "{\"ground_height_px\":";
    appendNumber(out, skeleton.groundHeight);
    out += ",\"metres_per_pixel\":";
    appendNumber(out, skeleton.metresPerPixel);
    out += skeleton.heelContact ? ",\"heel_contact\":true}" : ",\"heel_contact\":false}";
    return out;
}

// ---- nodes and skin --------------------------------------------------------------------------

// Joint node i for bone i: rigid local transforms, extras; world matrices → inverse binds.
// local[i] = bones[i].joint.transform().
void addJointNodes(const Skeleton& skeleton, const std::vector<Mat4>& local, Scene& scene) {
    const double s = skeleton.metresPerPixel;
    const Mat4 toGltf = skeletonToGltf(skeleton);
    const std::size_t n = skeleton.bones.size();
    Skin skin;
    skin.joints.reserve(n);
    skin.inverseBindMatrices.reserve(n);
    scene.nodes.reserve(n + 1);
    std::vector<Mat4> world(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Bone& bone = skeleton.bones[i];
        const Mat4& joint = local[i];
        SceneNode node;
        node.name = bone.name();
        node.parent = bone.parent;
        if (bone.parent < 0) {
            const Mat3 rotation = kInternalToGltf * joint.topLeftCorner<3, 3>() * kBoneFromNode;
            node.rotation = canonicalQuaternion(rotation);
            node.translation = (toGltf * joint.col(3)).head<3>();
        } else {
            const Mat3 rotation =
                kBoneFromNode.transpose() * joint.topLeftCorner<3, 3>() * kBoneFromNode;
            node.rotation = canonicalQuaternion(rotation);
            node.translation = s * (kBoneFromNode.transpose() * bone.joint.position);
        }
        node.extrasJson = boneExtras(bone, s);
        // World matrix exactly as the file states it (Scene::worldTransform's formula).
        const Eigen::Isometry3d nodeLocal = Eigen::Translation3d(node.translation) * node.rotation;
        world[i] =
            bone.parent < 0 ? nodeLocal.matrix() : Mat4(world[bone.parent] * nodeLocal.matrix());
        skin.joints.push_back(static_cast<int>(i));
        skin.inverseBindMatrices.push_back(Eigen::Isometry3d(world[i]).inverse().matrix());
        scene.nodes.push_back(std::move(node));
    }
    skin.skeleton = 0;
    scene.skins.push_back(std::move(skin));
}

// ---- the skinned mesh ------------------------------------------------------------------------

// Collects the bind-pose vertices of every bone and its triangles per bone kind.
class SkeletonMeshBuilder {
public:
    // world: Skeleton::worldTransforms(); vertexHint, indexHint: expected totals (reserved).
    SkeletonMeshBuilder(const Skeleton& skeleton, std::vector<Mat4> world, std::size_t vertexHint,
                        const std::array<std::size_t, kBoneKindCount>& indexHint)
        : toGltf_(skeletonToGltf(skeleton)), world_(std::move(world)) {
        mesh_.positions.reserve(vertexHint);
        mesh_.normals.reserve(vertexHint);
        mesh_.joints.reserve(vertexHint);
        mesh_.weights.reserve(vertexHint);
        for (int k = 0; k < kBoneKindCount; ++k) kindIndices_[k].reserve(indexHint[k]);
    }

    /// boneBoxMesh's box of `bone` (nothing for boxes without volume).
    void addBox(std::size_t bone, BoneKind kind, const Vec3& extents);
    void addMesh(std::size_t bone, BoneKind kind, const Mesh& mesh);
    Mesh finish(const SkeletonSceneParams& params);

private:
    std::uint32_t addVertices(std::size_t bone, const Vec3f* positions, const Vec3f* normals,
                              std::size_t count);

    Mat4 toGltf_;
    std::vector<Mat4> world_;
    Mesh mesh_;
    std::array<std::vector<std::uint32_t>, kBoneKindCount> kindIndices_;
    bool normals_ = true, tangents_ = true, uvs_ = true;
};

// Appends positions (and normals when given) transformed to glTF world, bound to `bone`;
// returns the first new vertex.
std::uint32_t SkeletonMeshBuilder::addVertices(std::size_t bone, const Vec3f* positions,
                                               const Vec3f* normals, std::size_t count) {
    const Mat4 m = toGltf_ * world_[bone];
    const Mat3 linear = m.topLeftCorner<3, 3>();
    const Mat3 rotation = linear / linear.col(0).norm();  // s·R·R_b without the scale
    const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
    const auto joint = static_cast<std::uint16_t>(bone);
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 p = linear * positions[i].cast<double>() + m.topRightCorner<3, 1>();
        mesh_.positions.push_back(p.cast<float>());
        if (normals != nullptr) {
            mesh_.normals.push_back((rotation * normals[i].cast<double>()).cast<float>());
        }
        mesh_.joints.push_back({joint, 0, 0, 0});
        mesh_.weights.push_back(Vec4f(1.0f, 0.0f, 0.0f, 0.0f));
    }
    return base;
}

// The same vertices as addVertices(makeBox(extents)), from the box's 8 transformed corners
// and 6 turned face normals.
void SkeletonMeshBuilder::addBox(std::size_t bone, BoneKind kind, const Vec3& extents) {
    Vec3f lo, hi;
    if (!boxBounds(extents, lo, hi)) return;
    const Mat4 m = toGltf_ * world_[bone];
    const Mat3 linear = m.topLeftCorner<3, 3>();
    const Mat3 rotation = linear / linear.col(0).norm();
    std::array<Vec3f, 8> corners;
    for (int c = 0; c < 8; ++c) {
        const Vec3f p((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(),
                      (c & 4) ? hi.z() : lo.z());
        corners[c] = (linear * p.cast<double>() + m.topRightCorner<3, 1>()).cast<float>();
    }
    std::array<Vec3f, 6> faceNormals;
    for (int f = 0; f < 6; ++f) {
        Vec3 n = Vec3::Zero();
        n[f / 2] = f % 2 == 0 ? 1.0 : -1.0;
        faceNormals[f] = (rotation * n).cast<float>();
    }
    const std::size_t base = mesh_.positions.size();
    const auto joint = static_cast<std::uint16_t>(bone);
    mesh_.positions.resize(base + kBoxVertices);
    mesh_.normals.resize(base + kBoxVertices);
    mesh_.joints.resize(base + kBoxVertices, {joint, 0, 0, 0});
    mesh_.weights.resize(base + kBoxVertices, Vec4f(1.0f, 0.0f, 0.0f, 0.0f));
    Vec3f* positions = mesh_.positions.data() + base;
    Vec3f* normals = mesh_.normals.data() + base;
    for (int v = 0; v < kBoxVertices; ++v) {
        positions[v] = corners[kBoxCornerOf[v]];
        normals[v] = faceNormals[v / 4];
    }
    std::vector<std::uint32_t>& indices = kindIndices_[static_cast<int>(kind)];
    const std::size_t first = indices.size();
    indices.resize(first + kBoxIndices);
    for (int k = 0; k < kBoxIndices; ++k) {
        indices[first + k] = static_cast<std::uint32_t>(base) + kBoxIndexPattern[k];
    }
}

void SkeletonMeshBuilder::addMesh(std::size_t bone, BoneKind kind, const Mesh& mesh) {
    const std::size_t n = mesh.positions.size();
    if (n == 0 || mesh.indices.empty()) return;
    // An attribute survives only if every bone mesh has it.
    normals_ = normals_ && mesh.normals.size() == n;
    tangents_ = tangents_ && mesh.tangents.size() == n;
    uvs_ = uvs_ && mesh.uvs.size() == n;
    if (!normals_) mesh_.normals.clear();
    if (!tangents_) mesh_.tangents.clear();
    if (!uvs_) mesh_.uvs.clear();
    const std::uint32_t base =
        addVertices(bone, mesh.positions.data(), normals_ ? mesh.normals.data() : nullptr, n);
    if (tangents_ || uvs_) {
        const Mat4 m = toGltf_ * world_[bone];
        const Mat3 rotation = m.topLeftCorner<3, 3>() / m.col(0).head<3>().norm();
        for (std::size_t i = 0; tangents_ && i < n; ++i) {
            const Vec3 t = rotation * mesh.tangents[i].head<3>().cast<double>();
            mesh_.tangents.push_back(Vec4f(static_cast<float>(t.x()), static_cast<float>(t.y()),
                                           static_cast<float>(t.z()), mesh.tangents[i].w()));
        }
        if (uvs_) mesh_.uvs.insert(mesh_.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
    }
    std::vector<std::uint32_t>& indices = kindIndices_[static_cast<int>(kind)];
    for (std::uint32_t i : mesh.indices) indices.push_back(base + i);
}

// Index buffer in BoneKind order, one primitive and material per kind present.
Mesh SkeletonMeshBuilder::finish(const SkeletonSceneParams& params) {
    mesh_.name = params.meshName;
    std::size_t indexCount = 0;
    for (const std::vector<std::uint32_t>& indices : kindIndices_) indexCount += indices.size();
    mesh_.indices.reserve(indexCount);
    for (int k = 0; k < kBoneKindCount; ++k) {
        const std::vector<std::uint32_t>& indices = kindIndices_[k];
        if (indices.empty()) continue;
        const std::string kind(boneKindName(static_cast<BoneKind>(k)));
        Material material = params.material;
        material.name += "_" + kind;
        mesh_.primitives.push_back(MeshPrimitive{static_cast<std::uint32_t>(mesh_.indices.size()),
                                                 static_cast<std::uint32_t>(indices.size()),
                                                 static_cast<std::uint32_t>(mesh_.materials.size()),
                                                 kind});
        mesh_.materials.push_back(std::move(material));
        mesh_.indices.insert(mesh_.indices.end(), indices.begin(), indices.end());
    }
    return std::move(mesh_);
}

}  // namespace

Mesh boneBoxMesh(const Bone& bone) {
    Mesh mesh;
    mesh.name = bone.name();
    BoxVertices box;
    if (!makeBox(bone.extents, box)) return mesh;
    mesh.positions.assign(box.positions.begin(), box.positions.end());
    mesh.normals.assign(box.normals.begin(), box.normals.end());
    mesh.indices.assign(kBoxIndexPattern.begin(), kBoxIndexPattern.end());
    return mesh;
}

Material boneMaterial() {
    Material m;
    m.name = "bone";
    m.baseColor = Vec4f(0.80f, 0.74f, 0.60f, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 0.7f;
    return m;
}

Mat4 skeletonToGltf(const Skeleton& skeleton) {
    const double s = skeleton.metresPerPixel;
    Mat4 m = Mat4::Identity();
    m.topLeftCorner<3, 3>() = s * kInternalToGltf;
    m.topRightCorner<3, 1>() = -s * (kInternalToGltf * Vec3(0.0, skeleton.groundHeight, 0.0));
    return m;
}

Mat3 boneFromNode() { return kBoneFromNode; }

Scene skeletonToScene(const Skeleton& skeleton, const SkeletonSceneParams& params) {
    Scene scene;
    if (skeleton.bones.empty()) return scene;
    RAMUS_ASSERT(skeleton.bones.size() <= 65536);  // joint indices are 16-bit
    const std::size_t n = skeleton.bones.size();
    std::vector<Mat4> local(n), world(n);
    for (std::size_t i = 0; i < n; ++i) {
        const int parent = skeleton.bones[i].parent;
        local[i] = skeleton.bones[i].joint.transform();
        world[i] = parent < 0 ? local[i] : Mat4(world[static_cast<std::size_t>(parent)] * local[i]);
    }
    addJointNodes(skeleton, local, scene);
    // Space for a box per bone (exact for boxes, a first guess for bone meshes).
    std::array<std::size_t, kBoneKindCount> indexHint{};
    for (const Bone& bone : skeleton.bones) indexHint[static_cast<int>(bone.kind)] += kBoxIndices;
    SkeletonMeshBuilder builder(skeleton, std::move(world), n * kBoxVertices, indexHint);
    for (std::size_t i = 0; i < n; ++i) {
        const Bone& bone = skeleton.bones[i];
        if (params.boneMesh) {
            builder.addMesh(i, bone.kind, params.boneMesh(static_cast<int>(i), bone));
        } else {
            builder.addBox(i, bone.kind, bone.extents);
        }
    }
    Mesh mesh = builder.finish(params);
    scene.skins[0].name = params.meshName;
    scene.extrasJson = sceneExtras(skeleton);
    if (mesh.indices.empty()) return scene;  // no bone has a mesh: joints only
    scene.meshes.push_back(std::move(mesh));
    SceneNode meshNode;
    meshNode.name = params.meshName;
    meshNode.mesh = 0;
    meshNode.skin = 0;
    scene.nodes.push_back(std::move(meshNode));
    return scene;
}

}  // namespace ramus
