#include <gtest/gtest.h>

#include <sstream>

#include "io/io_fixtures.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {
namespace {

using testing::makeCube;
using testing::makeHierarchyScene;
using testing::scratchDir;

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::vector<std::string> linesStartingWith(const std::string& text, const std::string& tag) {
    std::vector<std::string> out;
    for (const std::string& line : lines(text)) {
        if (line.rfind(tag + " ", 0) == 0) out.push_back(line);
    }
    return out;
}

struct ObjFiles {
    std::string obj, mtl;
};

ObjFiles writeAndRead(const Scene& scene, const std::string& name) {
    const std::filesystem::path dir = scratchDir("obj_" + name);
    writeObj(scene, (dir / (name + ".obj")).string());
    return {readFile((dir / (name + ".obj")).string()), readFile((dir / (name + ".mtl")).string())};
}

TEST(ObjWriter, CubeHasItsVerticesFacesAndMaterialLibrary) {
    const ObjFiles files = writeAndRead(makeSingleMeshScene(makeCube(), "box"), "cube");
    EXPECT_EQ(lines(files.obj).at(1), "mtllib cube.mtl");
    EXPECT_EQ(linesStartingWith(files.obj, "o"), std::vector<std::string>{"o box"});
    EXPECT_EQ(linesStartingWith(files.obj, "g"), std::vector<std::string>{"g box"});
    EXPECT_EQ(linesStartingWith(files.obj, "v").size(), 24u);
    EXPECT_EQ(linesStartingWith(files.obj, "vt").size(), 24u);
    EXPECT_EQ(linesStartingWith(files.obj, "vn").size(), 24u);
    const std::vector<std::string> faces = linesStartingWith(files.obj, "f");
    ASSERT_EQ(faces.size(), 12u);
    EXPECT_EQ(faces.front(), "f 1/1/1 2/2/2 3/3/3");  // 1-based
    EXPECT_EQ(faces.back(), "f 21/21/21 23/23/23 24/24/24");
    EXPECT_EQ(linesStartingWith(files.obj, "usemtl"), std::vector<std::string>{"usemtl material"});
    // +X face, first corner: (1, -1, 1)·0.5 — shortest exact decimals.
    EXPECT_EQ(linesStartingWith(files.obj, "v").front(), "v 0.5 -0.5 0.5");
    EXPECT_EQ(linesStartingWith(files.obj, "vn").front(), "vn 1 0 0");
    EXPECT_EQ(linesStartingWith(files.obj, "vt").front(), "vt 0 1");  // v flipped for OBJ

    const std::vector<std::string> mtl = lines(files.mtl);
    const std::vector<std::string> expected = {"newmtl material",   "Ka 0 0 0", "Kd 0.8 0.8 0.8",
                                               "Ks 0.04 0.04 0.04", "Ns 9",     "d 1",
                                               "illum 2",           "Pr 0.9",   "Pm 0"};
    ASSERT_GE(mtl.size(), 11u);
    EXPECT_EQ(std::vector<std::string>(mtl.begin() + 2, mtl.begin() + 11), expected);
}

TEST(ObjWriter, NodeTransformsAreAppliedAndIndicesContinueAcrossGroups) {
    Scene scene;
    Mesh cube = makeCube();
    cube.normals.clear();
    cube.uvs.clear();
    scene.meshes = {cube};
    SceneNode a;
    a.name = "left cube";  // whitespace is not allowed in OBJ names
    a.mesh = 0;
    SceneNode b;
    b.name = "right";
    b.mesh = 0;
    b.translation = Vec3(10.0, 0.0, 0.0);
    b.scale = Vec3(2.0, 2.0, 2.0);
    scene.nodes = {a, b};
    const ObjFiles files = writeAndRead(scene, "two");
    EXPECT_EQ(linesStartingWith(files.obj, "o"),
              (std::vector<std::string>{"o left_cube", "o right"}));
    const std::vector<std::string> v = linesStartingWith(files.obj, "v");
    ASSERT_EQ(v.size(), 48u);
    EXPECT_EQ(v[24], "v 11 -1 1");
    const std::vector<std::string> faces = linesStartingWith(files.obj, "f");
    ASSERT_EQ(faces.size(), 24u);
    EXPECT_EQ(faces[12], "f 25 26 27");
}

TEST(ObjWriter, MirroringTransformsKeepFacesOutward) {
    Scene scene = makeSingleMeshScene(makeCube(), "mirrored");
    scene.nodes[0].scale = Vec3(-1.0, 1.0, 1.0);
    const ObjFiles files = writeAndRead(scene, "mirror");
    const std::vector<std::string> faces = linesStartingWith(files.obj, "f");
    EXPECT_EQ(faces.front(), "f 1/1/1 3/3/3 2/2/2");
    // The +X face moved to -X: its normal must follow (the inverse transpose, not the matrix).
    EXPECT_EQ(linesStartingWith(files.obj, "vn").front(), "vn -1 0 0");
    EXPECT_EQ(linesStartingWith(files.obj, "v").front(), "v -0.5 -0.5 0.5");
}

TEST(ObjWriter, NormalsUseTheInverseTransposeUnderNonUniformScale) {
    Mesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.normals = std::vector<Vec3f>(3, Vec3f(1.0f, 1.0f, 0.0f).normalized());
    tri.indices = {0, 1, 2};
    Scene scene = makeSingleMeshScene(tri, "tri");
    scene.nodes[0].scale = Vec3(2.0, 1.0, 1.0);
    const ObjFiles files = writeAndRead(scene, "scaled");
    // (1, 1, 0) under diag(2, 1, 1)^-T = diag(0.5, 1, 1) → (0.5, 1, 0) / |·|.
    const float nx = 0.5f / std::sqrt(1.25f), ny = 1.0f / std::sqrt(1.25f);
    std::istringstream in(linesStartingWith(files.obj, "vn").front().substr(3));
    float x = 0, y = 0, z = 0;
    in >> x >> y >> z;
    EXPECT_NEAR(x, nx, 1e-6f);
    EXPECT_NEAR(y, ny, 1e-6f);
    EXPECT_EQ(z, 0.0f);
}

TEST(ObjWriter, EachPrimitiveGetsItsMaterialAndNamesStayUnique) {
    Scene scene = makeHierarchyScene();
    scene.meshes[1].materials = {Material{"bark", {1.0f, 1.0f, 1.0f, 1.0f}}};  // same name
    const ObjFiles files = writeAndRead(scene, "materials");
    EXPECT_EQ(linesStartingWith(files.obj, "usemtl"),
              (std::vector<std::string>{"usemtl bark", "usemtl leaves", "usemtl bark_2"}));
    EXPECT_EQ(linesStartingWith(files.mtl, "newmtl"),
              (std::vector<std::string>{"newmtl bark", "newmtl leaves", "newmtl bark_2"}));
    EXPECT_NE(files.mtl.find("d 0.5\n"), std::string::npos);
    EXPECT_EQ(linesStartingWith(files.obj, "o"), (std::vector<std::string>{"o trunk", "o twig_L"}));
}

TEST(ObjWriter, OutputIsDeterministic) {
    const Scene scene = makeHierarchyScene();
    const ObjFiles a = writeAndRead(scene, "det_a");
    const ObjFiles b = writeAndRead(scene, "det_b");
    EXPECT_EQ(a.mtl, b.mtl);
    // Only the mtllib line differs (it names each file's own library).
    EXPECT_EQ(a.obj.substr(a.obj.find("\no ")), b.obj.substr(b.obj.find("\no ")));
}

TEST(ObjWriter, InvalidSceneIsAnErrorAndWritesNothing) {
    Scene scene = makeSingleMeshScene(makeCube());
    scene.meshes[0].indices[0] = 1000;
    const std::filesystem::path dir = scratchDir("obj_invalid");
    EXPECT_THROW(writeObj(scene, (dir / "bad.obj").string()), Error);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace ramus
