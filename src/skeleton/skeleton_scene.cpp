// Based on: the glTF 2.0 specification (Khronos), §3.5 nodes and hierarchy, §3.7.3 skins
// (joints, inverse bind matrices, skeleton root); DESIGN.md "glTF" (axes, node names, extras);
// seed 000 §5.2 (bones as boxes in their own frames, joints with degrees of freedom).
#include "ramus/skeleton_scene.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <memory>

#include "core/float_text.hpp"
#include "core/text_builder.hpp"
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

// The extras' numbers are written at float precision, as glTF readers store them: the shortest
// text that reads back as the same float (shorter and faster to write than a double's 17
// digits); −0 is written as 0. `floats` remembers the texts: twins and rest rotations repeat
// most numbers.

// "joint": rest rotation and degrees of freedom. nodeRotation: the node's rotation, which is
// the rest rotation when every joint angle is 0.
void appendJoint(detail::TextBuilder& t, const Bone& bone, const Eigen::Quaterniond& nodeRotation,
                 detail::FloatTextCache& floats) {
    bool posed = false;
    for (int i = 0; i < bone.joint.dofCount; ++i)
        posed = posed || bone.joint.dofs[i].angleDeg != 0.0;
    const Eigen::Quaterniond rest =
        posed ? canonicalQuaternion(restLocalRotation(bone)) : nodeRotation;
    const double q[4] = {rest.x(), rest.y(), rest.z(), rest.w()};
    t.text(R"("joint":{"rest_rotation":)").floats(q, 4, floats).text(R"(,"dofs":[)");
    for (int i = 0; i < bone.joint.dofCount; ++i) {
        const JointDof& dof = bone.joint.dofs[i];
        const Vec3 axis = kBoneFromNode.transpose() * dof.axis.normalized();
        t.text(i > 0 ? R"(,{"axis":)" : R"({"axis":)").floats(axis.data(), 3, floats);
        t.text(R"(,"angle_deg":)").number(static_cast<float>(dof.angleDeg), floats);
        t.text(R"(,"min_deg":)").number(static_cast<float>(dof.minDeg), floats);
        t.text(R"(,"max_deg":)").number(static_cast<float>(dof.maxDeg), floats).text("}");
    }
    t.text("]}");
}

// "key":"value", (names from the vocabulary: no characters that need escaping).
void appendField(detail::TextBuilder& t, std::string_view key, std::string_view value) {
    t.text("\"").text(key).text(R"(":")").text(value).text("\",");
}

std::string boneExtras(const Bone& bone, double metresPerPixel,
                       const Eigen::Quaterniond& nodeRotation, detail::FloatTextCache& floats) {
    // Vocabulary names (≤ 20 characters), an index, 7 + 2 · 6 floats (≤ 15 each), the keys.
    char buffer[1024];
    detail::TextBuilder t(buffer, buffer + sizeof buffer);
    t.text("{");
    appendField(t, "kind", boneKindName(bone.kind));
    appendField(t, "side", sideName(bone.side));
    if (bone.region != SpineRegion::None) appendField(t, "region", spineRegionName(bone.region));
    if (bone.index > 0) {
        t.text(R"("index":)").number(static_cast<std::uint64_t>(bone.index)).text(",");
    }
    if (bone.limb != LimbKind::None) {
        appendField(t, "limb", limbKindName(bone.limb));
        appendField(t, "attachment", attachmentName(bone.attachment));
    }
    if (bone.doubleJoint) t.text(R"("double_joint":true,)");
    const Vec3 extents = bone.extents * metresPerPixel;
    t.text(R"("extents_m":)").floats(extents.data(), 3, floats).text(",");
    appendJoint(t, bone, nodeRotation, floats);
    t.text("}");
    return std::string(t.view());
}

std::string sceneExtras(const Skeleton& skeleton) {
    std::string out = "{\"ground_height_px\":";
    detail::appendShortest(out, skeleton.groundHeight);
    out += ",\"metres_per_pixel\":";
    detail::appendShortest(out, skeleton.metresPerPixel);
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
    const auto floats = std::make_unique<detail::FloatTextCache>();
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
        node.extrasJson = boneExtras(bone, s, node.rotation, *floats);
        node.extrasCompact = true;
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

// ---- one skinned mesh per bone ---------------------------------------------------------------

// Turns bone-frame meshes into bind-pose glTF meshes, one per bone, every vertex rigidly bound
// to the bone's joint, with one material per bone kind.
class BoneMeshBuilder {
public:
    // world: Skeleton::worldTransforms().
    BoneMeshBuilder(const Skeleton& skeleton, std::vector<Mat4> world,
                    const SkeletonSceneParams& params)
        : skeleton_(skeleton), toGltf_(skeletonToGltf(skeleton)), world_(std::move(world)) {
        for (int k = 0; k < kBoneKindCount; ++k) {
            materials_[k] = params.material;
            materials_[k].name.append("_").append(boneKindName(static_cast<BoneKind>(k)));
        }
    }

    /// The mesh of bone i from its box (false for boxes without volume).
    bool box(std::size_t bone, Mesh& mesh) const;
    /// The mesh of bone i from `source` in the bone frame, transformed in place (false when it
    /// has no triangles).
    bool fit(std::size_t bone, Mesh& source) const;

private:
    // Binds the mesh's vertices to the joint and gives it its kind's material.
    void finish(std::size_t bone, Mesh& mesh) const;

    const Skeleton& skeleton_;
    Mat4 toGltf_;
    std::vector<Mat4> world_;
    std::array<Material, kBoneKindCount> materials_;
};

void BoneMeshBuilder::finish(std::size_t bone, Mesh& mesh) const {
    const Bone& b = skeleton_.bones[bone];
    const std::size_t n = mesh.positions.size();
    mesh.joints.assign(n, {static_cast<std::uint16_t>(bone), 0, 0, 0});
    mesh.weights.assign(n, Vec4f(1.0f, 0.0f, 0.0f, 0.0f));
    mesh.attributes.clear();
    const auto kind = static_cast<std::size_t>(b.kind);
    mesh.materials.assign(1, materials_[kind]);
    mesh.primitives.assign(1, MeshPrimitive{0, static_cast<std::uint32_t>(mesh.indices.size()), 0,
                                            std::string(boneKindName(b.kind))});
}

// The same vertices as makeBox(extents) transformed, from the box's 8 transformed corners, and
// no normals: a box is flat-shaded, and glTF readers compute flat normals for a mesh without
// them (glTF 2.0 §3.7.2.1: "client implementations MUST calculate flat normals"), as OBJ
// readers do for faces without vn — the 24 unshared vertices keep every face flat even for a
// reader that averages normals per vertex. A third less data to write per box.
bool BoneMeshBuilder::box(std::size_t bone, Mesh& mesh) const {
    Vec3f lo, hi;
    if (!boxBounds(skeleton_.bones[bone].extents, lo, hi)) return false;
    const Mat4 m = toGltf_ * world_[bone];
    const Mat3 linear = m.topLeftCorner<3, 3>();
    std::array<Vec3f, 8> corners;
    for (int c = 0; c < 8; ++c) {
        const Vec3f p((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(),
                      (c & 4) ? hi.z() : lo.z());
        corners[c] = (linear * p.cast<double>() + m.topRightCorner<3, 1>()).cast<float>();
    }
    mesh.positions.resize(kBoxVertices);
    for (int v = 0; v < kBoxVertices; ++v) mesh.positions[v] = corners[kBoxCornerOf[v]];
    mesh.indices.assign(kBoxIndexPattern.begin(), kBoxIndexPattern.end());
    finish(bone, mesh);
    return true;
}

bool BoneMeshBuilder::fit(std::size_t bone, Mesh& mesh) const {
    const std::size_t n = mesh.positions.size();
    if (n == 0 || mesh.indices.empty()) return false;
    const Mat4 m = toGltf_ * world_[bone];
    const Mat3 linear = m.topLeftCorner<3, 3>();
    const Mat3 rotation = linear / linear.col(0).norm();
    for (Vec3f& p : mesh.positions) {
        p = (linear * p.cast<double>() + m.topRightCorner<3, 1>()).cast<float>();
    }
    // An attribute that does not cover every vertex is dropped (Mesh's invariant).
    if (mesh.normals.size() != n) mesh.normals.clear();
    if (mesh.tangents.size() != n) mesh.tangents.clear();
    if (mesh.uvs.size() != n) mesh.uvs.clear();
    for (Vec3f& normal : mesh.normals) normal = (rotation * normal.cast<double>()).cast<float>();
    for (Vec4f& t : mesh.tangents) {
        const Vec3 turned = rotation * t.head<3>().cast<double>();
        t.head<3>() = turned.cast<float>();
    }
    finish(bone, mesh);
    return true;
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
    scene.skins[0].name = params.skinName;
    scene.extrasJson = sceneExtras(skeleton);
    const BoneMeshBuilder builder(skeleton, std::move(world), params);
    scene.meshes.reserve(n);
    scene.nodes.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Bone& bone = skeleton.bones[i];
        Mesh mesh;
        if (params.boneMesh) {
            mesh = params.boneMesh(static_cast<int>(i), bone);
            if (!builder.fit(i, mesh)) continue;
        } else if (!builder.box(i, mesh)) {
            continue;
        }
        mesh.name = scene.nodes[i].name;  // joint node i is bone i's
        SceneNode meshNode;
        meshNode.name.reserve(mesh.name.size() + 5);
        meshNode.name.append(mesh.name).append("_mesh");
        meshNode.mesh = static_cast<int>(scene.meshes.size());
        meshNode.skin = 0;
        scene.meshes.push_back(std::move(mesh));
        scene.nodes.push_back(std::move(meshNode));
    }
    return scene;
}

}  // namespace ramus
