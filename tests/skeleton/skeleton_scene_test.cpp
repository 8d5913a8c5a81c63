// skeletonToScene: joint nodes, skin, skinned bind-pose bone meshes and the px → glTF conversion,
// on small skeletons built by hand (root, spine, a rib pair and a leg pair mirrored across z = 0).
#include "ramus/skeleton_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {
namespace {

using nlohmann::json;

const Mat3 kMirror = Vec3(1.0, 1.0, -1.0).asDiagonal();  // M = S = diag(1, 1, −1)
const Mat3 kGltfMirror = Vec3(-1.0, 1.0, 1.0).asDiagonal();

Mat3 linearPart(const Mat4& m) { return m.block(0, 0, 3, 3); }

Mat3 rotation(const Vec3& axis, double degrees) {
    return Eigen::AngleAxisd(degToRad(degrees), axis).toRotationMatrix();
}

Bone makeBone(BoneKind kind, int parent, const Vec3& position, const Mat3& rest,
              const Vec3& extents) {
    Bone bone;
    bone.kind = kind;
    bone.parent = parent;
    bone.joint.position = position;
    bone.joint.rest = rest;
    bone.extents = extents;
    return bone;
}

void addDof(Bone& bone, const Vec3& axis, double angle, double lo, double hi) {
    bone.joint.dofs[bone.joint.dofCount++] = JointDof{axis, angle, lo, hi};
}

// The right twin of left bone `left`: joint S·J·S (position z negated, rest S·rest·S, axes
// −S·a), so that its world transform is M·W·S.
Bone mirrored(const Skeleton& skeleton, int left, const std::map<int, int>& twinOf) {
    Bone bone = skeleton.bones[left];
    bone.side = Side::Right;
    bone.twin = left;
    const auto parent = twinOf.find(bone.parent);
    if (parent != twinOf.end()) bone.parent = parent->second;
    bone.joint.position = kMirror * bone.joint.position;
    bone.joint.rest = kMirror * bone.joint.rest * kMirror;
    for (int i = 0; i < bone.joint.dofCount; ++i) {
        bone.joint.dofs[i].axis = -(kMirror * bone.joint.dofs[i].axis);
    }
    return bone;
}

// Root at (500, 300, 0) px; back vertebrae 1, 2 along +x (towards the tail); a neck vertebra
// towards −x (the head); a rib pair on back vertebra 1; a leg pair (pelvis, thigh, shank, foot)
// on back vertebra 2. Ground at the lowest box corner.
Skeleton makeSkeleton(double metresPerPixel = 0.001) {
    Skeleton s;
    s.metresPerPixel = metresPerPixel;
    s.bones.push_back(makeBone(BoneKind::Root, -1, {500, 300, 0}, Mat3::Identity(), {0, 0, 0}));
    Bone back1 = makeBone(BoneKind::Vertebra, 0, {0, 0, 0}, Mat3::Identity(), {40, 30, 30});
    back1.region = SpineRegion::Back;
    back1.index = 1;
    Bone back2 = back1;
    back2.parent = 1;
    back2.joint.position = {40, 0, 0};
    back2.joint.rest = rotation(Vec3::UnitZ(), -10.0);
    back2.index = 2;
    Bone neck =
        makeBone(BoneKind::Vertebra, 0, {0, 0, 0}, rotation(Vec3::UnitY(), 180.0), {35, 25, 25});
    neck.region = SpineRegion::Neck;
    neck.index = 1;
    s.bones.insert(s.bones.end(), {back1, back2, neck});
    // Left side (+z): bone x points outwards (+z), then down for the leg.
    Bone rib = makeBone(BoneKind::Rib, 1, {20, 0, 15}, rotation(Vec3::UnitY(), -90.0), {30, 6, 4});
    rib.region = SpineRegion::Back;
    rib.index = 1;
    Bone pelvis =
        makeBone(BoneKind::Pelvis, 2, {40, 0, 15}, rotation(Vec3::UnitY(), -90.0), {20, 12, 10});
    Bone thigh =
        makeBone(BoneKind::Thigh, -1, {20, 0, 0}, rotation(Vec3::UnitZ(), -90.0), {60, 10, 10});
    addDof(thigh, Vec3::UnitZ(), 10.0, -30.0, 60.0);
    Bone shank = makeBone(BoneKind::Shank, -1, {60, 0, 0}, Mat3::Identity(), {50, 8, 8});
    addDof(shank, Vec3::UnitZ(), -20.0, -90.0, 0.0);
    addDof(shank, Vec3::UnitY(), 5.0, -10.0, 10.0);
    Bone foot =
        makeBone(BoneKind::Foot, -1, {50, 0, 0}, rotation(Vec3::UnitZ(), 80.0), {25, 5, 12});
    for (Bone* b : {&rib, &pelvis, &thigh, &shank, &foot}) {
        b->side = Side::Left;
        if (b != &rib) {
            b->limb = LimbKind::Leg;
            b->attachment = Attachment::Hip;
        }
    }
    const int base = static_cast<int>(s.bones.size());  // 4: rib, 5: pelvis, 6…8: leg
    thigh.parent = base + 1;
    shank.parent = base + 2;
    foot.parent = base + 3;
    s.bones.insert(s.bones.end(), {rib, pelvis, thigh, shank, foot});
    std::map<int, int> twinOf;
    for (int left = base; left < base + 5; ++left) {
        twinOf[left] = static_cast<int>(s.bones.size());
        s.bones[left].twin = twinOf[left];
        s.bones.push_back(mirrored(s, left, twinOf));
    }
    // Ground: the lowest box corner.
    const std::vector<Mat4> world = s.worldTransforms();
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        for (const Vec3f& p : boneBoxMesh(s.bones[i]).positions) {
            lowest = std::min(lowest, (world[i] * p.cast<double>().homogeneous()).y());
        }
    }
    s.groundHeight = lowest;
    return s;
}

void exportForValidator(const Scene& scene, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir == nullptr || *dir == '\0') return;
    std::filesystem::create_directories(dir);
    writeGlb(scene, (std::filesystem::path(dir) / ("skeleton_scene_" + name + ".glb")).string());
}

// Signed volume of the triangles of `mesh` in [first, first + count) (> 0 when the winding is
// outward for a closed surface), measured from its first vertex to avoid cancellation.
double signedVolume(const Mesh& mesh, std::size_t first, std::size_t count) {
    double volume = 0.0;
    const Vec3 o = mesh.positions[mesh.indices[first]].cast<double>();
    for (std::size_t k = first; k < first + count; k += 3) {
        const Vec3 a = mesh.positions[mesh.indices[k]].cast<double>() - o;
        const Vec3 b = mesh.positions[mesh.indices[k + 1]].cast<double>() - o;
        const Vec3 c = mesh.positions[mesh.indices[k + 2]].cast<double>() - o;
        volume += a.dot(b.cross(c)) / 6.0;
    }
    return volume;
}

// Triangles of `mesh` whose vertices are bound to joint `joint`.
Mesh trianglesOfJoint(const Mesh& mesh, int joint) {
    Mesh out;
    out.positions = mesh.positions;
    for (std::size_t k = 0; k < mesh.indices.size(); k += 3) {
        if (mesh.joints[mesh.indices[k]][0] != joint) continue;
        out.indices.insert(out.indices.end(),
                           {mesh.indices[k], mesh.indices[k + 1], mesh.indices[k + 2]});
    }
    return out;
}

// All bone meshes of the scene as one mesh (joints kept: vertex → bone).
Mesh allBones(const Scene& scene) {
    Mesh all;
    for (const Mesh& mesh : scene.meshes) appendMesh(all, mesh);
    return all;
}

int nodeNamed(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        if (scene.nodes[i].name == name) return static_cast<int>(i);
    }
    ADD_FAILURE() << "no node " << name;
    return 0;
}

TEST(SkeletonScene, FixtureTwinsAreMirrorImages) {
    const Skeleton s = makeSkeleton();
    const std::vector<Mat4> world = s.worldTransforms();
    Mat4 m = Mat4::Identity();
    m.topLeftCorner<3, 3>() = kMirror;
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        if (s.bones[i].side != Side::Right) continue;
        EXPECT_TRUE(world[i].isApprox(m * world[s.bones[i].twin] * m, 1e-12)) << i;
        EXPECT_NEAR(linearPart(world[i]).determinant(), 1.0, 1e-12);
    }
}

TEST(SkeletonScene, OneJointNodePerBoneThenOneMeshNodePerBoneWithABox) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    exportForValidator(scene, "hand_built");
    const std::size_t n = s.bones.size();
    ASSERT_EQ(scene.nodes.size(), n + (n - 1));  // the zero-size root has no box
    ASSERT_EQ(scene.meshes.size(), n - 1);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(scene.nodes[i].name, s.bones[i].name());
        EXPECT_EQ(scene.nodes[i].parent, s.bones[i].parent);
        EXPECT_EQ(scene.nodes[i].mesh, -1);
        EXPECT_EQ(scene.nodes[i].scale, Vec3::Ones());
    }
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const std::size_t bone = m + 1;
        const SceneNode& meshNode = scene.nodes[n + m];
        EXPECT_EQ(scene.meshes[m].name, s.bones[bone].name());
        EXPECT_EQ(meshNode.name, s.bones[bone].name() + "_mesh");
        EXPECT_EQ(meshNode.parent, -1);  // a root: not a joint, not below one
        EXPECT_EQ(meshNode.mesh, static_cast<int>(m));
        EXPECT_EQ(meshNode.skin, 0);
        EXPECT_EQ(meshNode.translation, Vec3::Zero());
        EXPECT_TRUE(meshNode.rotation.coeffs().isApprox(Eigen::Quaterniond::Identity().coeffs()));
        // Bound to its own bone's joint alone.
        for (const auto& j : scene.meshes[m].joints) EXPECT_EQ(j[0], bone);
    }
    EXPECT_EQ(scene.nodes[0].name, "root");
    EXPECT_EQ(scene.nodes[8].name, "foot_L");
    EXPECT_EQ(scene.nodes[13].name, "foot_R");
    EXPECT_EQ(scene.nodes[9].name, "rib_back_01_R");
}

TEST(SkeletonScene, OneSkinOverAllBonesWithInverseBindMatrices) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    ASSERT_EQ(scene.skins.size(), 1u);
    const Skin& skin = scene.skins[0];
    EXPECT_EQ(skin.skeleton, 0);
    ASSERT_EQ(skin.joints.size(), s.bones.size());
    ASSERT_EQ(skin.inverseBindMatrices.size(), s.bones.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        EXPECT_EQ(skin.joints[j], static_cast<int>(j));
        const Mat4 product = skin.inverseBindMatrices[j] * scene.worldTransform(skin.joints[j]);
        EXPECT_TRUE(product.isApprox(Mat4::Identity(), 1e-12)) << j << "\n" << product;
        EXPECT_EQ(skin.inverseBindMatrices[j].row(3), Eigen::RowVector4d(0, 0, 0, 1));
    }
}

TEST(SkeletonScene, EveryJointPointsItsYAxisAtItsChild) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    int checked = 0;
    for (std::size_t c = 1; c < s.bones.size(); ++c) {
        const Bone& child = s.bones[c];
        const Bone& parent = s.bones[child.parent];
        // Children on the parent's axis (the next bone of a chain) sit at the end of the bone.
        if (child.joint.position.tail<2>().norm() > 0.0 || parent.kind == BoneKind::Root) continue;
        const Mat4 pw = scene.worldTransform(child.parent);
        const Vec3 toChild =
            scene.worldTransform(static_cast<int>(c)).col(3).head<3>() - pw.col(3).head<3>();
        EXPECT_TRUE(toChild.normalized().isApprox(pw.col(1).head<3>(), 1e-12)) << c;
        EXPECT_NEAR(toChild.norm(), child.joint.position.x() * s.metresPerPixel, 1e-12);
        ++checked;
    }
    EXPECT_EQ(checked, 7);  // back 1→2, thigh, shank, foot on both sides
}

TEST(SkeletonScene, NodeFramesAreTheBoneFramesInGltfAxes) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    const std::vector<Mat4> bone = s.worldTransforms();
    const Mat4 toGltf = skeletonToGltf(s);
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        const Mat4 node = scene.worldTransform(static_cast<int>(i));
        // node +Y = bone +x, node +X = bone −y, node +Z = bone +z, origin at the joint.
        const Mat4 expected = toGltf * bone[i];
        const double sc = s.metresPerPixel;
        EXPECT_TRUE(node.col(1).head<3>().isApprox(expected.col(0).head<3>() / sc, 1e-12)) << i;
        EXPECT_TRUE(node.col(0).head<3>().isApprox(-expected.col(1).head<3>() / sc, 1e-12)) << i;
        EXPECT_TRUE(node.col(2).head<3>().isApprox(expected.col(2).head<3>() / sc, 1e-12)) << i;
        EXPECT_TRUE(node.col(3).isApprox(expected.col(3), 1e-12)) << i;
    }
}

TEST(SkeletonScene, GltfAxesPutTheHeadAtPlusZAndTheLeftSideAtPlusX) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    const Vec3 root = scene.worldTransform(0).col(3).head<3>();
    // The neck vertebra points towards the head: internal −x, glTF +Z.
    const Vec3 neckAxis =
        scene.worldTransform(nodeNamed(scene, "vertebra_neck_01")).col(1).head<3>();
    EXPECT_TRUE(neckAxis.isApprox(Vec3::UnitZ(), 1e-12));
    // Left pelvis points to +X, from a joint left of the mid-plane.
    const Mat4 pelvisL = scene.worldTransform(nodeNamed(scene, "pelvis_L"));
    EXPECT_TRUE(pelvisL.col(1).head<3>().isApprox(Vec3::UnitX(), 1e-12));
    EXPECT_NEAR(pelvisL(0, 3), 0.015, 1e-12);
    EXPECT_NEAR(root.x(), 0.0, 1e-15);
    EXPECT_NEAR(root.z(), -0.5, 1e-12);  // internal x = 500 px → Z = −0.5 m
}

TEST(SkeletonScene, TwinsAreMirroredAcrossTheYzPlane) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    int pairs = 0;
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        if (s.bones[i].side != Side::Left) continue;
        const Mat4 left = scene.worldTransform(static_cast<int>(i));
        const Mat4 right = scene.worldTransform(s.bones[i].twin);
        EXPECT_GT(left(0, 3), 0.0) << s.bones[i].name();
        EXPECT_TRUE(right.col(3).head<3>().isApprox(kGltfMirror * left.col(3).head<3>(), 1e-12));
        // Frames: M_g · Q · diag(1, 1, −1), still right-handed.
        const Mat3 expected = kGltfMirror * left.topLeftCorner<3, 3>() * kMirror;
        EXPECT_TRUE(linearPart(right).isApprox(expected, 1e-12)) << s.bones[i].name();
        EXPECT_NEAR(linearPart(right).determinant(), 1.0, 1e-12);
        ++pairs;
    }
    EXPECT_EQ(pairs, 5);
}

TEST(SkeletonScene, MeshStandsOnTheGroundAtYZero) {
    const Scene scene = skeletonToScene(makeSkeleton());
    const Aabb box = allBones(scene).bounds();
    EXPECT_NEAR(box.min.y(), 0.0, 1e-6);
    EXPECT_GE(box.min.y(), -1e-7);
}

TEST(SkeletonScene, GroundHeightMovesTheSkeletonVertically) {
    Skeleton s = makeSkeleton();
    s.groundHeight = 100.0;
    const Scene scene = skeletonToScene(s);
    // Root at internal y = 300 px, ground 100 px → 0.2 m.
    EXPECT_NEAR(scene.worldTransform(0)(1, 3), 0.2, 1e-12);
}

TEST(SkeletonScene, MetresPerPixelScalesPositionsButNotRotations) {
    const Scene small = skeletonToScene(makeSkeleton(0.001));
    const Scene large = skeletonToScene(makeSkeleton(0.004));
    for (std::size_t i = 0; i < small.nodes.size(); ++i) {
        EXPECT_TRUE(large.nodes[i].translation.isApprox(4.0 * small.nodes[i].translation, 1e-12))
            << i;
        EXPECT_TRUE(large.nodes[i].rotation.isApprox(small.nodes[i].rotation, 1e-12)) << i;
    }
    const Aabb a = allBones(small).bounds(), b = allBones(large).bounds();
    EXPECT_TRUE((4.0 * a.extent()).isApprox(b.extent(), 1e-6));
    // The thigh is 60 px long: 0.06 m at 1 mm/px.
    const json extras = json::parse(small.nodes[nodeNamed(small, "thigh_L")].extrasJson);
    ASSERT_EQ(extras["extents_m"].size(), 3u);
    EXPECT_NEAR(extras["extents_m"][0].get<double>(), 0.06, 1e-15);
    EXPECT_NEAR(extras["extents_m"][1].get<double>(), 0.01, 1e-15);
    EXPECT_NEAR(extras["extents_m"][2].get<double>(), 0.01, 1e-15);
}

TEST(SkeletonScene, EveryBoneBoxIsWoundOutwardsIncludingMirroredOnes) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    const Mesh mesh = allBones(scene);
    for (std::size_t i = 1; i < s.bones.size(); ++i) {  // the zero-size root has no box
        const Mesh box = trianglesOfJoint(mesh, static_cast<int>(i));
        ASSERT_EQ(box.indices.size(), 36u) << i;
        const Vec3 e = s.bones[i].extents * s.metresPerPixel;
        EXPECT_NEAR(signedVolume(box, 0, 36), e.prod(), 1e-3 * e.prod()) << s.bones[i].name();
    }
    EXPECT_EQ(trianglesOfJoint(mesh, 0).indices.size(), 0u);
}

TEST(SkeletonScene, VerticesAreRigidlyBoundAndSitInTheirBoneInBindPose) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    const Mesh mesh = allBones(scene);
    ASSERT_EQ(mesh.joints.size(), mesh.positions.size());
    ASSERT_EQ(mesh.positions.size(), 24u * (s.bones.size() - 1));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto j = mesh.joints[v];
        EXPECT_EQ(mesh.weights[v], Vec4f(1, 0, 0, 0));
        EXPECT_EQ(j[1] + j[2] + j[3], 0);
        // In the joint's node frame the box spans y ∈ [0, length], x and z centred.
        const Vec3 local = (scene.skins[0].inverseBindMatrices[j[0]] *
                            mesh.positions[v].cast<double>().homogeneous())
                               .head<3>();
        const Vec3 e = s.bones[j[0]].extents * s.metresPerPixel;
        EXPECT_NEAR(std::abs(local.x()), e.y() / 2, 1e-6) << v;
        EXPECT_NEAR(std::abs(local.z()), e.z() / 2, 1e-6) << v;
        EXPECT_TRUE(std::abs(local.y()) < 1e-6 || std::abs(local.y() - e.x()) < 1e-6) << v;
    }
}

// Boxes have no normals (readers compute flat ones, glTF §3.7.2.1): each face's winding must
// then point out of its box, and no vertex is shared between faces (so even per-vertex normal
// averaging stays flat).
TEST(SkeletonScene, BoxFacesWindOutwardWithoutNormals) {
    const Scene scene = skeletonToScene(makeSkeleton());
    ASSERT_FALSE(scene.meshes.empty());
    for (const Mesh& mesh : scene.meshes) {
        EXPECT_TRUE(mesh.normals.empty()) << mesh.name;
        ASSERT_EQ(mesh.positions.size(), 24u);
        Vec3f centre = Vec3f::Zero();
        for (const Vec3f& p : mesh.positions) centre += p / 24.0f;
        std::vector<int> faceOf(24, -1);
        for (std::size_t k = 0; k < mesh.indices.size(); k += 3) {
            const Vec3f a = mesh.positions[mesh.indices[k]];
            const Vec3f b = mesh.positions[mesh.indices[k + 1]];
            const Vec3f c = mesh.positions[mesh.indices[k + 2]];
            const Vec3f face = (b - a).cross(c - a).normalized();
            EXPECT_GT(face.dot(((a + b + c) / 3.0f - centre).normalized()), 0.0f) << k;
            for (int i = 0; i < 3; ++i) {
                int& owner = faceOf[mesh.indices[k + i]];
                if (owner < 0) owner = static_cast<int>(k / 6);
                EXPECT_EQ(owner, static_cast<int>(k / 6)) << mesh.name << " vertex shared";
            }
        }
    }
}

TEST(SkeletonScene, EachBoneMeshHasOnePrimitiveWithItsKindsMaterial) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const std::string kind(boneKindName(s.bones[m + 1].kind));
        ASSERT_EQ(mesh.primitives.size(), 1u);
        ASSERT_EQ(mesh.materials.size(), 1u);
        EXPECT_EQ(mesh.primitives[0].name, kind);
        EXPECT_EQ(mesh.primitives[0].indexCount, 36u);
        EXPECT_EQ(mesh.materials[0].name, "bone_" + kind);
        EXPECT_EQ(mesh.materials[0].roughness, 0.7f);
    }
}

// The GLB writes what bones share once: one material per kind, one index buffer for all boxes,
// one view of rigid weights; each bone mesh has 16-bit indices and byte joints.
TEST(SkeletonScene, GlbSharesMaterialsIndicesAndWeightsBetweenBones) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    const std::string glb = encodeGlb(scene);
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    const json doc = json::parse(glb.substr(20, jsonLength));
    std::vector<std::string> materials;
    for (const json& m : doc["materials"]) materials.push_back(m["name"]);
    EXPECT_EQ(materials, std::vector<std::string>({"bone_vertebra", "bone_rib", "bone_pelvis",
                                                   "bone_thigh", "bone_shank", "bone_foot"}));
    ASSERT_EQ(doc["meshes"].size(), scene.meshes.size());
    std::set<int> indexAccessors, weightViews, positionViews;
    for (const json& mesh : doc["meshes"]) {
        ASSERT_EQ(mesh["primitives"].size(), 1u);
        const json& prim = mesh["primitives"][0];
        const json& indices = doc["accessors"][prim["indices"].get<int>()];
        EXPECT_EQ(indices["componentType"], 5123);  // UNSIGNED_SHORT
        indexAccessors.insert(prim["indices"].get<int>());
        const json& joints = doc["accessors"][prim["attributes"]["JOINTS_0"].get<int>()];
        EXPECT_EQ(joints["componentType"], 5121);  // UNSIGNED_BYTE
        const json& weights = doc["accessors"][prim["attributes"]["WEIGHTS_0"].get<int>()];
        EXPECT_EQ(weights["componentType"], 5121);
        EXPECT_EQ(weights["normalized"], true);
        weightViews.insert(weights["bufferView"].get<int>());
        positionViews.insert(
            doc["accessors"][prim["attributes"]["POSITION"].get<int>()]["bufferView"].get<int>());
    }
    EXPECT_EQ(indexAccessors.size(), 1u);
    EXPECT_EQ(weightViews.size(), 1u);
    // Every bone's positions in one view (12-byte elements), each mesh at its own offset; the
    // weights share the 4-byte view with the joints. Views: 4, 12 bytes, indices, IBMs.
    EXPECT_EQ(positionViews.size(), 1u);
    EXPECT_EQ(doc["bufferViews"][*positionViews.begin()]["byteStride"], 12);
    EXPECT_EQ(doc["bufferViews"][*weightViews.begin()]["byteStride"], 4);
    EXPECT_EQ(doc["bufferViews"].size(), 4u);
    std::set<std::size_t> positionOffsets;
    for (const json& mesh : doc["meshes"]) {
        const json& position =
            doc["accessors"][mesh["primitives"][0]["attributes"]["POSITION"].get<int>()];
        positionOffsets.insert(position.value("byteOffset", std::size_t{0}));
    }
    EXPECT_EQ(positionOffsets.size(), scene.meshes.size());
}

TEST(SkeletonScene, ExtrasNameKindSideRegionLimbAndJoint) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    const json vertebra = json::parse(scene.nodes[nodeNamed(scene, "vertebra_back_02")].extrasJson);
    EXPECT_EQ(vertebra["kind"], "vertebra");
    EXPECT_EQ(vertebra["side"], "center");
    EXPECT_EQ(vertebra["region"], "back");
    EXPECT_EQ(vertebra["index"], 2);
    EXPECT_FALSE(vertebra.contains("limb"));
    EXPECT_EQ(vertebra["joint"]["dofs"], json::array());
    const json shank = json::parse(scene.nodes[nodeNamed(scene, "shank_R")].extrasJson);
    EXPECT_EQ(shank["kind"], "shank");
    EXPECT_EQ(shank["side"], "right");
    EXPECT_EQ(shank["limb"], "leg");
    EXPECT_EQ(shank["attachment"], "hip");
    EXPECT_FALSE(shank.contains("region"));
    const json& dofs = shank["joint"]["dofs"];
    ASSERT_EQ(dofs.size(), 2u);
    // Bone z stays node z; bone y becomes node −X.
    EXPECT_EQ(dofs[0]["axis"], json::parse("[0, 0, 1]"));
    EXPECT_EQ(dofs[1]["axis"], json::parse("[1, 0, 0]"));  // −S·(0, 1, 0) = bone −y = node +X
    EXPECT_EQ(dofs[0]["angle_deg"], -20.0);
    EXPECT_EQ(dofs[0]["min_deg"], -90.0);
    EXPECT_EQ(dofs[0]["max_deg"], 0.0);
    EXPECT_EQ(dofs[1]["angle_deg"], 5.0);
    const json root = json::parse(scene.nodes[0].extrasJson);
    EXPECT_EQ(root["kind"], "root");
    const json sceneExtras = json::parse(scene.extrasJson);
    EXPECT_DOUBLE_EQ(sceneExtras["ground_height_px"].get<double>(), s.groundHeight);
    EXPECT_EQ(sceneExtras["metres_per_pixel"], 0.001);
}

TEST(SkeletonScene, RestRotationTimesDofRotationsGivesTheNodeRotation) {
    const Skeleton s = makeSkeleton();
    const Scene scene = skeletonToScene(s);
    for (std::size_t i = 0; i < s.bones.size(); ++i) {
        const json joint = json::parse(scene.nodes[i].extrasJson)["joint"];
        const json& q = joint["rest_rotation"];
        Eigen::Quaterniond rotation(q[3].get<double>(), q[0].get<double>(), q[1].get<double>(),
                                    q[2].get<double>());
        for (const json& dof : joint["dofs"]) {
            const Vec3 axis(dof["axis"][0].get<double>(), dof["axis"][1].get<double>(),
                            dof["axis"][2].get<double>());
            rotation = rotation * Eigen::AngleAxisd(degToRad(dof["angle_deg"].get<double>()), axis);
        }
        // Extras are written at float precision.
        EXPECT_NEAR(std::abs(rotation.dot(scene.nodes[i].rotation)), 1.0, 1e-6)
            << s.bones[i].name();
    }
}

TEST(SkeletonScene, GlbIsDeterministicAndReadsBack) {
    const Scene scene = skeletonToScene(makeSkeleton());
    const std::string bytes = encodeGlb(scene);
    EXPECT_EQ(bytes, encodeGlb(skeletonToScene(makeSkeleton())));
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "ramus_skeleton_scene_read";
    std::filesystem::create_directories(dir);
    writeFileAtomic((dir / "s.glb").string(), bytes);
    const Scene read = readGltf((dir / "s.glb").string());
    ASSERT_EQ(read.nodes.size(), scene.nodes.size());
    // readGltf orders nodes depth-first: compare names as sets.
    std::vector<std::string> written, readBack;
    for (const SceneNode& n : scene.nodes) written.push_back(n.name);
    for (const SceneNode& n : read.nodes) readBack.push_back(n.name);
    std::sort(written.begin(), written.end());
    std::sort(readBack.begin(), readBack.end());
    EXPECT_EQ(readBack, written);
    ASSERT_EQ(read.meshes.size(), scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        EXPECT_EQ(read.meshes[m].positions, scene.meshes[m].positions) << m;
        EXPECT_EQ(read.meshes[m].indices, scene.meshes[m].indices) << m;
    }
}

TEST(SkeletonScene, ObjShowsOneGroupPerBoneWithItsKindsMaterial) {
    const Skeleton skeleton = makeSkeleton();
    const Scene scene = skeletonToScene(skeleton);
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "ramus_skeleton_scene_obj";
    std::filesystem::create_directories(dir);
    writeObj(scene, (dir / "s.obj").string());
    const std::string obj = readFile((dir / "s.obj").string());
    EXPECT_EQ(obj.find("o skeleton\n"), std::string::npos);  // the bones, not the skinned mesh
    for (const Bone& bone : skeleton.bones) {
        if (bone.extents.minCoeff() <= 0.0) continue;  // no box
        EXPECT_NE(obj.find("o " + bone.name() + "\ng " + bone.name() + "\n"), std::string::npos)
            << bone.name();
    }
    for (const char* kind : {"vertebra", "rib", "pelvis", "thigh", "shank", "foot"}) {
        EXPECT_NE(obj.find(std::string("usemtl bone_") + kind + "\n"), std::string::npos) << kind;
    }
    std::size_t vertices = 0;
    for (std::size_t p = obj.find("\nv "); p != std::string::npos; p = obj.find("\nv ", p + 1)) {
        ++vertices;
    }
    EXPECT_EQ(vertices, allBones(scene).positions.size());
}

TEST(SkeletonScene, CustomBoneMeshSourceReplacesTheBoxes) {
    const Skeleton s = makeSkeleton();
    SkeletonSceneParams params;
    // A tetrahedron along the bone (no normals), none for vertebrae.
    params.boneMesh = [](int, const Bone& bone) {
        Mesh m;
        if (bone.kind == BoneKind::Vertebra || bone.kind == BoneKind::Root) return m;
        const float l = static_cast<float>(bone.extents.x());
        m.positions = {{0, 0, 0}, {l, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
        return m;
    };
    params.skinName = "bones";
    const Scene scene = skeletonToScene(s, params);
    exportForValidator(scene, "custom_bone_meshes");
    EXPECT_EQ(scene.skins[0].name, "bones");
    ASSERT_EQ(scene.meshes.size(), 10u);  // rib, pelvis, thigh, shank, foot × 2
    EXPECT_EQ(scene.nodes.back().name, "foot_R_mesh");
    const Mesh mesh = allBones(scene);
    EXPECT_EQ(mesh.positions.size(), 4u * 10u);
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_EQ(scene.meshes.front().name, "rib_back_01_L");
    EXPECT_EQ(scene.meshes.front().primitives.front().name, "rib");
    for (std::size_t i = 4; i < s.bones.size(); ++i) {
        const Mesh tetra = trianglesOfJoint(mesh, static_cast<int>(i));
        const double volume = s.bones[i].extents.x() / 6.0 * 1e-9;  // l · 1 · 1 / 6 px³ in m³
        EXPECT_NEAR(signedVolume(tetra, 0, 12), volume, 1e-3 * volume) << i;
    }
    EXPECT_NO_THROW(encodeGlb(scene));
}

TEST(SkeletonScene, SkeletonWithoutBoneMeshesHasJointsButNoMesh) {
    Skeleton s;
    s.bones.push_back(makeBone(BoneKind::Root, -1, {0, 0, 0}, Mat3::Identity(), {0, 0, 0}));
    const Scene scene = skeletonToScene(s);
    EXPECT_EQ(scene.nodes.size(), 1u);
    EXPECT_TRUE(scene.meshes.empty());
    EXPECT_EQ(scene.skins.size(), 1u);
    EXPECT_NO_THROW(encodeGlb(scene));
    EXPECT_TRUE(skeletonToScene(Skeleton{}).nodes.empty());
}

TEST(BoneBoxMesh, BoxSpansTheBoneFrameWithOutwardFaces) {
    Bone bone;
    bone.extents = Vec3(4, 2, 1);
    const Mesh box = boneBoxMesh(bone);
    ASSERT_EQ(box.positions.size(), 24u);
    ASSERT_EQ(box.indices.size(), 36u);
    const Aabb b = box.bounds();
    EXPECT_EQ(b.min, Vec3(0, -1, -0.5));
    EXPECT_EQ(b.max, Vec3(4, 1, 0.5));
    EXPECT_DOUBLE_EQ(signedVolume(box, 0, 36), 8.0);
    for (std::size_t v = 0; v < 24; ++v) {
        EXPECT_EQ(box.normals[v].norm(), 1.0f);
        // Each vertex lies on the face its normal belongs to.
        const Vec3 p = box.positions[v].cast<double>();
        const Vec3 n = box.normals[v].cast<double>();
        const Vec3 face = n.cwiseMax(0.0).cwiseProduct(b.max) + n.cwiseMin(0.0).cwiseProduct(b.min);
        EXPECT_NEAR(p.dot(n), face.sum(), 1e-12) << v;
    }
}

TEST(BoneBoxMesh, BoneWithoutVolumeHasNoBox) {
    Bone bone;
    EXPECT_TRUE(boneBoxMesh(bone).positions.empty());
    bone.extents = Vec3(3, 0, 1);
    EXPECT_TRUE(boneBoxMesh(bone).indices.empty());
}

TEST(SkeletonToGltf, IsAScaledRotationThatPutsTheGroundAtZero) {
    Skeleton s;
    s.metresPerPixel = 0.01;
    s.groundHeight = 50.0;
    const Mat4 m = skeletonToGltf(s);
    EXPECT_NEAR(linearPart(m).determinant(), 1e-6, 1e-18);
    EXPECT_TRUE((m * Vec4(0, 50, 0, 1)).isApprox(Vec4(0, 0, 0, 1)));
    EXPECT_TRUE((m * Vec4(-100, 50, 0, 1)).isApprox(Vec4(0, 0, 1, 1)));  // front → +Z
    EXPECT_TRUE((m * Vec4(0, 50, 100, 1)).isApprox(Vec4(1, 0, 0, 1)));   // left → +X
    EXPECT_NEAR(boneFromNode().determinant(), 1.0, 1e-15);
}

}  // namespace
}  // namespace ramus
