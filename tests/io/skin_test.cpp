// glTF skins: JOINTS_0 / WEIGHTS_0 attributes, skins with inverse bind matrices, node.skin, and
// the checks a skinned scene must pass before it is written.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/gltf_accessors.hpp"
#include "io/io_fixtures.hpp"
#include "io/scene_check.hpp"
#include "io/tinygltf_config.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {
namespace {

using nlohmann::json;
using testing::exportForValidator;
using testing::makeCube;
using testing::scratchDir;

// A unit cube (y ∈ [0, 1]) bent by two joints: "hip" at the origin and "knee" at y = 0.5,
// turned 30° about +Z. Vertices with y < 0.5 follow the hip, the others are shared 25/75 between
// hip and knee. The mesh sits on its own root node (node 2), as glTF recommends.
Scene makeSkinnedScene() {
    Scene scene;
    Mesh mesh = makeCube(0.5f, Vec3f(0.0f, 0.5f, 0.0f));
    mesh.name = "leg";
    for (const Vec3f& p : mesh.positions) {
        if (p.y() < 0.5f) {
            mesh.joints.push_back({0, 0, 0, 0});
            mesh.weights.push_back(Vec4f(1.0f, 0.0f, 0.0f, 0.0f));
        } else {
            mesh.joints.push_back({0, 1, 0, 0});
            mesh.weights.push_back(Vec4f(0.25f, 0.75f, 0.0f, 0.0f));
        }
    }
    scene.meshes.push_back(std::move(mesh));
    SceneNode hip;
    hip.name = "hip";
    SceneNode knee;
    knee.name = "knee";
    knee.parent = 0;
    knee.translation = Vec3(0.0, 0.5, 0.0);
    knee.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(degToRad(30.0), Vec3::UnitZ()));
    SceneNode body;
    body.name = "leg_mesh";
    body.mesh = 0;
    body.skin = 0;
    scene.nodes = {hip, knee, body};
    Skin skin;
    skin.name = "leg_skin";
    skin.joints = {0, 1};
    skin.skeleton = 0;
    for (int j : skin.joints) {
        skin.inverseBindMatrices.push_back(scene.worldTransform(j).inverse());
        skin.inverseBindMatrices.back().row(3) = Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0);
    }
    scene.skins.push_back(std::move(skin));
    return scene;
}

struct LoadedGltf {
    tinygltf::Model model;
    std::string path;
};

LoadedGltf loadGlb(const std::string& path) {
    LoadedGltf loaded;
    loaded.path = path;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&loaded.model, &err, &warn, path)) << err;
    return loaded;
}

// The JSON chunk of a GLB.
json glbJson(const std::string& bytes) {
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return json::parse(bytes.substr(20, length));
}

std::string checkMessage(const Scene& scene) {
    try {
        io::checkScene(scene, "out.glb");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Skin, SkinnedSceneRoundTripsJointsWeightsAndInverseBindMatrices) {
    const Scene scene = makeSkinnedScene();
    const std::string path = (scratchDir("skin_round_trip") / "leg.glb").string();
    writeGlb(scene, path);
    exportForValidator(scene, "skinned_leg");
    const LoadedGltf gltf = loadGlb(path);
    const tinygltf::Model& model = gltf.model;
    ASSERT_EQ(model.skins.size(), 1u);
    EXPECT_EQ(model.skins[0].name, "leg_skin");
    EXPECT_EQ(model.skins[0].joints, std::vector<int>({0, 1}));
    EXPECT_EQ(model.skins[0].skeleton, 0);
    ASSERT_EQ(model.nodes.size(), 3u);
    EXPECT_EQ(model.nodes[2].skin, 0);
    EXPECT_EQ(model.nodes[2].mesh, 0);
    EXPECT_EQ(model.nodes[0].skin, -1);

    const io::Reader reader{model, gltf.path};
    const std::vector<double> ibm =
        io::readAccessor(reader, model.skins[0].inverseBindMatrices, 16, "inverse bind matrices");
    ASSERT_EQ(ibm.size(), 32u);
    for (int j = 0; j < 2; ++j) {
        for (int k = 0; k < 16; ++k) {
            EXPECT_NEAR(ibm[j * 16 + k], scene.skins[0].inverseBindMatrices[j](k % 4, k / 4), 1e-7)
                << j << "," << k;
        }
    }
    const tinygltf::Primitive& prim = model.meshes[0].primitives[0];
    const std::vector<double> joints =
        io::readAccessor(reader, prim.attributes.at("JOINTS_0"), 4, "JOINTS_0");
    const std::vector<double> weights =
        io::readAccessor(reader, prim.attributes.at("WEIGHTS_0"), 4, "WEIGHTS_0");
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(joints.size(), mesh.joints.size() * 4);
    ASSERT_EQ(weights.size(), mesh.weights.size() * 4);
    for (std::size_t v = 0; v < mesh.joints.size(); ++v) {
        for (int k = 0; k < 4; ++k) {
            EXPECT_EQ(joints[v * 4 + k], mesh.joints[v][k]) << v;
            EXPECT_EQ(weights[v * 4 + k], mesh.weights[v][k]) << v;
        }
    }
}

TEST(Skin, JointsAreBytesAndTheMatricesHaveNoBufferTarget) {
    const json doc = glbJson(encodeGlb(makeSkinnedScene()));
    const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
    const json& joints = doc["accessors"][attributes["JOINTS_0"].get<int>()];
    EXPECT_EQ(joints["componentType"], 5121);  // UNSIGNED_BYTE: every joint index < 256
    EXPECT_EQ(joints["type"], "VEC4");
    const json& weights = doc["accessors"][attributes["WEIGHTS_0"].get<int>()];
    EXPECT_EQ(weights["componentType"], 5126);
    EXPECT_EQ(weights["type"], "VEC4");
    const json& ibm = doc["accessors"][doc["skins"][0]["inverseBindMatrices"].get<int>()];
    EXPECT_EQ(ibm["type"], "MAT4");
    EXPECT_EQ(ibm["count"], 2);
    EXPECT_FALSE(doc["bufferViews"][ibm["bufferView"].get<int>()].contains("target"));
    EXPECT_EQ(doc["nodes"][2]["skin"], 0);
    EXPECT_EQ(doc["scenes"][0]["nodes"], json::array({0, 2}));
}

TEST(Skin, RigidWeightsAreNormalizedBytesThatReadBackExactly) {
    Scene scene = makeSkinnedScene();
    Mesh& mesh = scene.meshes[0];
    for (std::size_t v = 0; v < mesh.weights.size(); ++v) {  // every vertex on one joint
        mesh.joints[v] = {static_cast<std::uint16_t>(v % 2), 0, 0, 0};
        mesh.weights[v] = Vec4f(1.0f, 0.0f, 0.0f, 0.0f);
    }
    const std::string path = (scratchDir("skin_rigid") / "rigid.glb").string();
    writeGlb(scene, path);
    exportForValidator(scene, "skinned_rigid");
    const json doc = glbJson(readFile(path));
    const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
    const json& weights = doc["accessors"][attributes["WEIGHTS_0"].get<int>()];
    EXPECT_EQ(weights["componentType"], 5121);  // UNSIGNED_BYTE
    EXPECT_EQ(weights["normalized"], true);
    const LoadedGltf gltf = loadGlb(path);
    const io::Reader reader{gltf.model, gltf.path};
    const std::vector<double> read = io::readAccessor(
        reader, gltf.model.meshes[0].primitives[0].attributes.at("WEIGHTS_0"), 4, "W");
    ASSERT_EQ(read.size(), 4 * mesh.weights.size());
    for (std::size_t i = 0; i < read.size(); ++i) EXPECT_EQ(read[i], i % 4 == 0 ? 1.0 : 0.0) << i;
}

TEST(Skin, BlendedWeightsStayFloats) {
    const json doc = glbJson(encodeGlb(makeSkinnedScene()));  // 0.25 / 0.75 on some vertices
    const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
    const json& weights = doc["accessors"][attributes["WEIGHTS_0"].get<int>()];
    EXPECT_EQ(weights["componentType"], 5126);
    EXPECT_FALSE(weights.contains("normalized"));
}

TEST(Skin, EncodingTwiceGivesIdenticalBytes) {
    const Scene scene = makeSkinnedScene();
    EXPECT_EQ(encodeGlb(scene), encodeGlb(scene));
    EXPECT_EQ(encodeGlb(scene), encodeGlb(Scene(scene)));
}

TEST(Skin, ManyJointsAreWrittenAsUnsignedShorts) {
    Scene scene = makeSkinnedScene();
    Skin& skin = scene.skins[0];
    // A chain of 300 more joints below the knee; the top vertices bind to the last one.
    for (int i = 0; i < 300; ++i) {
        SceneNode node;
        node.name = "segment_" + std::to_string(i);
        node.parent = i == 0 ? 1 : static_cast<int>(scene.nodes.size()) - 1;
        node.translation = Vec3(0.0, 0.01, 0.0);
        scene.nodes.push_back(node);
        skin.joints.push_back(static_cast<int>(scene.nodes.size()) - 1);
        skin.inverseBindMatrices.push_back(Mat4::Identity());
        skin.inverseBindMatrices.back()(1, 3) = -0.5 - 0.01 * (i + 1);
    }
    for (auto& j : scene.meshes[0].joints) {
        if (j[1] == 1) j[1] = 301;
    }
    const std::string bytes = encodeGlb(scene);
    const json doc = glbJson(bytes);
    const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
    EXPECT_EQ(doc["accessors"][attributes["JOINTS_0"].get<int>()]["componentType"], 5123);
    const std::string path = (scratchDir("skin_short_joints") / "chain.glb").string();
    writeFileAtomic(path, bytes);
    const LoadedGltf gltf = loadGlb(path);
    const std::vector<double> joints =
        io::readAccessor(io::Reader{gltf.model, gltf.path},
                         gltf.model.meshes[0].primitives[0].attributes.at("JOINTS_0"), 4, "J");
    double maxJoint = 0.0;
    for (double j : joints) maxJoint = std::max(maxJoint, j);
    EXPECT_EQ(maxJoint, 301.0);
    exportForValidator(scene, "skinned_chain_short_joints");
}

TEST(Skin, WeightsAreNormalizedDuplicatesMergedAndUnusedJointsZeroed) {
    Scene scene = makeSkinnedScene();
    Mesh& mesh = scene.meshes[0];
    mesh.weights[0] = Vec4f(0.5f, 0.5004f, 0.0f, 0.0f);  // sums to 1.0004: within tolerance
    mesh.joints[0] = {1, 0, 0, 0};
    mesh.joints[1] = {1, 1, 0, 0};  // joint 1 twice: one slot of weight 1
    mesh.weights[1] = Vec4f(0.5f, 0.5f, 0.0f, 0.0f);
    mesh.joints[2] = {0, 1, 1, 1};  // unused slots that name joint 1
    mesh.weights[2] = Vec4f(1.0f, 0.0f, 0.0f, 0.0f);
    const std::string path = (scratchDir("skin_normalize") / "leg.glb").string();
    writeGlb(scene, path);
    exportForValidator(scene, "skinned_normalized_weights");
    const LoadedGltf gltf = loadGlb(path);
    const io::Reader reader{gltf.model, gltf.path};
    const auto& attributes = gltf.model.meshes[0].primitives[0].attributes;
    const std::vector<double> joints = io::readAccessor(reader, attributes.at("JOINTS_0"), 4, "J");
    const std::vector<double> weights =
        io::readAccessor(reader, attributes.at("WEIGHTS_0"), 4, "W");
    EXPECT_FLOAT_EQ(static_cast<float>(weights[0]), 0.5f / 1.0004f);
    EXPECT_FLOAT_EQ(static_cast<float>(weights[1]), 0.5004f / 1.0004f);
    EXPECT_EQ(std::vector<double>(joints.begin() + 4, joints.begin() + 12),
              std::vector<double>({1, 0, 0, 0, 0, 0, 0, 0}));
    EXPECT_EQ(std::vector<double>(weights.begin() + 4, weights.begin() + 12),
              std::vector<double>({1, 0, 0, 0, 1, 0, 0, 0}));
}

TEST(Skin, ReadGltfReadsTheGeometryOfASkinnedFile) {
    const Scene scene = makeSkinnedScene();
    const std::string path = (scratchDir("skin_read") / "leg.glb").string();
    writeGlb(scene, path);
    const Scene read = readGltf(path);
    ASSERT_EQ(read.meshes.size(), 1u);
    EXPECT_EQ(read.meshes[0].positions, scene.meshes[0].positions);
    ASSERT_EQ(read.nodes.size(), 3u);
    EXPECT_EQ(read.nodes[2].name, "leg_mesh");
    EXPECT_EQ(read.nodes[2].mesh, 0);
}

TEST(Skin, ObjWriterWritesTheBindPoseWithOneGroupPerJoint) {
    const Scene scene = makeSkinnedScene();
    const std::filesystem::path dir = scratchDir("skin_obj");
    writeObj(scene, (dir / "leg.obj").string());
    const std::string obj = readFile((dir / "leg.obj").string());
    EXPECT_NE(obj.find("v -0.5 1 0.5\n"), std::string::npos);  // a top corner, not bent
    EXPECT_EQ(obj.find("o leg_mesh\n"), std::string::npos);    // groups per joint instead
    // Groups in skin order; every face uses only the vertices of its own group, which follow
    // the group's "o" line (OBJ indices are global and 1-based).
    std::vector<std::string> groups;
    std::size_t faces = 0, vertices = 0, groupStart = 0;
    std::istringstream in(obj);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("o ", 0) == 0) {
            groups.push_back(line.substr(2));
            groupStart = vertices;
        }
        if (line.rfind("v ", 0) == 0) ++vertices;
        if (line.rfind("usemtl ", 0) == 0) EXPECT_FALSE(groups.empty());
        if (line.rfind("f ", 0) != 0) continue;
        ++faces;
        std::istringstream corners(line.substr(2));
        for (std::string corner; corners >> corner;) {
            const std::size_t v = std::stoul(corner.substr(0, corner.find('/')));
            EXPECT_GT(v, groupStart) << line;
            EXPECT_LE(v, vertices) << line;
        }
    }
    EXPECT_EQ(groups, (std::vector<std::string>{"hip", "knee"}));
    EXPECT_EQ(faces, 12u);
    // The bottom face (y = 0) is all hip and the top face (y = 1) all knee.
    EXPECT_LT(obj.find("v -0.5 0 -0.5\n"), obj.find("o knee\n"));
    EXPECT_GT(obj.rfind("v 0.5 1 0.5\n"), obj.find("o knee\n"));
}

TEST(Skin, AppendMeshKeepsJointsAndWeightsWhenBothSidesHaveThem) {
    Mesh a = makeSkinnedScene().meshes[0];
    const Mesh b = a;
    appendMesh(a, b);
    ASSERT_EQ(a.joints.size(), 48u);
    ASSERT_EQ(a.weights.size(), 48u);
    EXPECT_EQ(a.joints[24 + 5], b.joints[5]);  // joint indices are not re-based
    EXPECT_EQ(a.weights[24 + 5], b.weights[5]);
    appendMesh(a, makeCube());
    EXPECT_TRUE(a.joints.empty());
    EXPECT_TRUE(a.weights.empty());
    EXPECT_EQ(a.positions.size(), 72u);
}

// ---- checks: one test per rejected case ------------------------------------------------------

TEST(SkinCheck, ValidSkinnedScenePasses) { EXPECT_EQ(checkMessage(makeSkinnedScene()), ""); }

TEST(SkinCheck, WeightsNotSummingToOneAreRejected) {
    Scene scene = makeSkinnedScene();
    scene.meshes[0].weights[3] = Vec4f(0.5f, 0.25f, 0.0f, 0.0f);
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('leg'): weights of vertex 3 are (0.5, 0.25, 0, 0); expected "
              "non-negative weights summing to 1");
}

TEST(SkinCheck, NegativeWeightsAreRejected) {
    Scene scene = makeSkinnedScene();
    scene.meshes[0].weights[3] = Vec4f(1.5f, -0.5f, 0.0f, 0.0f);
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('leg'): weights of vertex 3 are (1.5, -0.5, 0, 0); expected "
              "non-negative weights summing to 1");
}

TEST(SkinCheck, JointsWithoutWeightsAreRejected) {
    Scene scene = makeSkinnedScene();
    scene.meshes[0].weights.clear();
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('leg'): has 24 joints and 0 weights; expected both or neither "
              "(skinning needs both)");
}

TEST(SkinCheck, JointCountOtherThanVertexCountIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.meshes[0].joints.pop_back();
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('leg'): joints has 23 entries; expected 0 or 24 (one per vertex)");
}

TEST(SkinCheck, VertexJointOutsideTheSkinIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.meshes[0].joints[7][1] = 2;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: node 2 ('leg_mesh'): vertex 7 of mesh 'leg' uses joint 2; expected < 2 "
              "(the joints of skin 0)");
}

TEST(SkinCheck, NodeSkinOutOfRangeIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.nodes[2].skin = 1;
    EXPECT_EQ(checkMessage(scene), "out.glb: node 2 ('leg_mesh'): skin is 1; expected -1 or < 1");
}

TEST(SkinCheck, SkinOnANodeWithoutMeshIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.nodes[1].skin = 0;
    EXPECT_EQ(checkMessage(scene), "out.glb: node 1 ('knee'): has skin 0 but no mesh");
}

TEST(SkinCheck, SkinOnAMeshWithoutJointsIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.meshes.push_back(makeCube());
    scene.nodes[2].mesh = 1;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: node 2 ('leg_mesh'): has skin 0 but its mesh 'cube' has no joints and "
              "weights");
}

TEST(SkinCheck, SkinnedMeshOnANodeWithoutSkinIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.nodes[2].skin = -1;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: node 2 ('leg_mesh'): holds the skinned mesh 'leg' but has no skin");
}

TEST(SkinCheck, SkinnedMeshInASceneWithoutNodesIsRejected) {
    Scene scene;
    scene.meshes.push_back(makeSkinnedScene().meshes[0]);
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('leg'): is skinned but the scene has no nodes; expected a node "
              "with a skin");
}

TEST(SkinCheck, SkinWithoutJointsIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].joints.clear();
    scene.skins[0].inverseBindMatrices.clear();
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): has no joints; expected at least one joint node");
}

TEST(SkinCheck, MissingJointNodeIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].joints[1] = 5;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): joint node 5 does not exist; expected < 3");
}

TEST(SkinCheck, DuplicateJointIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].joints[1] = 0;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): lists node 0 twice; expected distinct joints");
}

TEST(SkinCheck, SkeletonOutOfRangeIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].skeleton = 3;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): skeleton is 3; expected -1 or < 3");
}

TEST(SkinCheck, SkeletonThatIsNotACommonRootIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].skeleton = 1;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): joint node 0 is not below the skeleton root 1");
}

TEST(SkinCheck, InverseBindMatrixCountOtherThanJointCountIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].inverseBindMatrices.pop_back();
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): has 1 inverse bind matrices; expected 0 or 2 (one "
              "per joint)");
}

TEST(SkinCheck, ProjectiveInverseBindMatrixIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].inverseBindMatrices[1](3, 0) = 0.5;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): inverse bind matrix 1 is not an invertible affine "
              "matrix with bottom row (0, 0, 0, 1)");
}

TEST(SkinCheck, SingularInverseBindMatrixIsRejected) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].inverseBindMatrices[0].col(2).setZero();
    EXPECT_EQ(checkMessage(scene),
              "out.glb: skin 0 ('leg_skin'): inverse bind matrix 0 is not an invertible affine "
              "matrix with bottom row (0, 0, 0, 1)");
}

TEST(SkinCheck, WriterRejectsAnInvalidSkinBeforeWriting) {
    Scene scene = makeSkinnedScene();
    scene.skins[0].joints[1] = 0;
    EXPECT_THROW(encodeGlb(scene), Error);
}

}  // namespace
}  // namespace ramus
