#include "io/scene_check.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/io_fixtures.hpp"
#include "ramus/error.hpp"

namespace ramus {
namespace {

using testing::makeCube;
using testing::makeHierarchyScene;

// The message checkScene throws for `scene`, or "" when it passes.
std::string checkMessage(const Scene& scene) {
    try {
        io::checkScene(scene, "out.glb");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(SceneCheck, ValidScenesPass) {
    EXPECT_EQ(checkMessage(makeHierarchyScene()), "");
    EXPECT_EQ(checkMessage(Scene{}), "");
    EXPECT_EQ(checkMessage(makeSingleMeshScene(Mesh{})), "");
}

TEST(SceneCheck, ParentAfterChildIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.nodes[1].parent = 3;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: node 1 ('trunk'): parent is 3; expected -1 or an earlier node (parents "
              "come before children)");
}

TEST(SceneCheck, NodeMeshOutOfRangeIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.nodes[3].mesh = 2;
    EXPECT_EQ(checkMessage(scene), "out.glb: node 3 ('twig_L'): mesh is 2; expected -1 or < 2");
}

TEST(SceneCheck, NonFiniteTranslationIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.nodes[1].translation.x() = std::nan("");
    EXPECT_EQ(checkMessage(scene),
              "out.glb: node 1 ('trunk'): translation or scale is not finite (or beyond the "
              "float range)");
}

// Writers store node transforms as floats: a double beyond the float range would become inf.
TEST(SceneCheck, ScaleBeyondFloatRangeIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.nodes[2].scale.y() = 1e39;
    EXPECT_NE(checkMessage(scene).find("node 2"), std::string::npos);
    EXPECT_NE(checkMessage(scene).find("beyond the float range"), std::string::npos);
}

TEST(SceneCheck, ZeroQuaternionIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.nodes[1].rotation = Eigen::Quaterniond(0, 0, 0, 0);
    EXPECT_NE(checkMessage(scene).find("rotation is not a valid quaternion"), std::string::npos);
}

TEST(SceneCheck, AttributeOfWrongLengthIsRejected) {
    Scene scene = makeSingleMeshScene(makeCube());
    scene.meshes[0].uvs.pop_back();
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('cube'): uvs has 23 entries; expected 0 or 24 (one per vertex)");
}

TEST(SceneCheck, NonFinitePositionIsRejected) {
    Scene scene = makeSingleMeshScene(makeCube());
    scene.meshes[0].positions[7].y() = INFINITY;
    EXPECT_EQ(checkMessage(scene), "out.glb: mesh 0 ('cube'): positions of vertex 7 is not finite");
}

TEST(SceneCheck, PartialTriangleIsRejected) {
    Scene scene = makeSingleMeshScene(makeCube());
    scene.meshes[0].indices.pop_back();
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('cube'): has 35 indices; expected a multiple of 3 (triangles)");
}

TEST(SceneCheck, IndexOutOfRangeIsRejected) {
    Scene scene = makeSingleMeshScene(makeCube());
    scene.meshes[0].indices[4] = 24;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('cube'): index 4 is 24; expected < 24 (the vertex count)");
}

TEST(SceneCheck, PrimitivePastTheIndicesIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.meshes[0].primitives[1].indexCount = 15;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('tree'): primitive 1 ('leaves') ends at index 39; expected at "
              "most 36");
}

TEST(SceneCheck, PrimitiveSplittingATriangleIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.meshes[0].primitives[1].firstIndex = 25;
    EXPECT_NE(checkMessage(scene).find("expected whole triangles"), std::string::npos);
}

TEST(SceneCheck, MissingMaterialIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.meshes[0].primitives[1].material = 2;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('tree'): primitive 1 ('leaves') uses material 2; expected < 2");
}

TEST(SceneCheck, MaterialFactorOutOfRangeIsRejected) {
    Scene scene = makeHierarchyScene();
    scene.meshes[0].materials[0].baseColor.y() = 1.5f;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('tree'): material 'bark': baseColor green is 1.5; expected a "
              "value in [0, 1]");
    scene.meshes[0].materials[0].baseColor.y() = 0.5f;
    scene.meshes[0].materials[0].roughness = -0.1f;
    EXPECT_EQ(checkMessage(scene),
              "out.glb: mesh 0 ('tree'): material 'bark': roughness is -0.1; expected a value in "
              "[0, 1]");
}

TEST(SceneCheck, InstancesComposeParentTransformsAndSkipEmptyMeshes) {
    Scene scene = makeHierarchyScene();
    scene.meshes.push_back(Mesh{});
    SceneNode empty;
    empty.mesh = 2;
    scene.nodes.push_back(empty);
    const std::vector<io::MeshInstance> instances = io::meshInstances(scene);
    ASSERT_EQ(instances.size(), 2u);
    EXPECT_EQ(instances[1].node, 3);
    EXPECT_TRUE(instances[1].world.isApprox(scene.worldTransform(3), 1e-12));
}

TEST(SceneCheck, FloatsAreFormattedShortestAndExact) {
    EXPECT_EQ(io::formatFloat(0.1f), "0.1");
    EXPECT_EQ(io::formatFloat(-2.0f), "-2");
    EXPECT_EQ(io::formatFloat(1e-8f), "1e-08");
    EXPECT_EQ(std::stof(io::formatFloat(0.3333333f)), 0.3333333f);
}

}  // namespace
}  // namespace ramus
