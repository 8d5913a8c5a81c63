// Custom vertex attributes and textures in the writers: GLB accessors and images, OBJ texture
// files and MTL maps, scene checks, the preview's alpha mask, appendMesh and primitive merging.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/io_fixtures.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/render.hpp"

namespace ramus {
namespace {

using nlohmann::json;
using testing::exportForValidator;
using testing::makeCube;

json glbJson(const std::string& bytes) {
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return json::parse(bytes.substr(20, length));
}

// The cube with a VEC4 and a SCALAR custom attribute whose values encode the vertex index.
Mesh attributedCube() {
    Mesh mesh = makeCube();
    VertexAttribute wind{"_WIND", 4, {}};
    VertexAttribute one{"_ONE", 1, {}};
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        for (int k = 0; k < 4; ++k) wind.values.push_back(static_cast<float>(10 * v + k));
        one.values.push_back(static_cast<float>(v));
    }
    mesh.attributes = {wind, one};
    return mesh;
}

std::shared_ptr<const Image> checker(int size) {
    Image image{size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size * 4)};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(y) * size + x) * 4;
            p[0] = (x + y) % 2 ? 255 : 0;
            p[1] = 128;
            p[2] = 0;
            p[3] = x < size / 2 ? 255 : 0;  // left half opaque: the mask cuts the right half
        }
    }
    return std::make_shared<const Image>(std::move(image));
}

TEST(CustomAttributes, GlbWritesThemAsFloatAccessorsUnderTheirNames) {
    const Scene scene = makeSingleMeshScene(attributedCube());
    const std::string bytes = encodeGlb(scene);
    const json doc = glbJson(bytes);
    const json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
    ASSERT_TRUE(attributes.contains("_WIND"));
    ASSERT_TRUE(attributes.contains("_ONE"));
    const json& wind = doc["accessors"][attributes["_WIND"].get<int>()];
    EXPECT_EQ(wind["type"], "VEC4");
    EXPECT_EQ(wind["componentType"], 5126);
    EXPECT_EQ(wind["count"], 24);
    EXPECT_EQ(doc["accessors"][attributes["_ONE"].get<int>()]["type"], "SCALAR");
    // The values themselves: vertex 5, component 2 of _WIND is 52.
    // Vertex data shares views by element size: the accessor starts at its byteOffset.
    const json& view = doc["bufferViews"][wind["bufferView"].get<int>()];
    EXPECT_EQ(view["byteStride"], 16);
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, bytes.data() + 12, 4);
    const std::size_t bin = 20 + jsonLength + 8 + view["byteOffset"].get<std::size_t>() +
                            wind.value("byteOffset", std::size_t{0});
    float value = 0.0f;
    std::memcpy(&value, bytes.data() + bin + (5 * 4 + 2) * 4, 4);
    EXPECT_EQ(value, 52.0f);
    exportForValidator(scene, "custom_attributes");
}

TEST(CustomAttributes, BadNamesSizesAndValuesAreErrors) {
    Mesh mesh = attributedCube();
    mesh.attributes[0].name = "WIND";  // glTF needs the leading underscore
    EXPECT_THROW(encodeGlb(makeSingleMeshScene(mesh)), Error);
    mesh = attributedCube();
    mesh.attributes[1].name = "_WIND";
    EXPECT_THROW(encodeGlb(makeSingleMeshScene(mesh)), Error);
    mesh = attributedCube();
    mesh.attributes[0].values.pop_back();
    EXPECT_THROW(encodeGlb(makeSingleMeshScene(mesh)), Error);
    mesh = attributedCube();
    mesh.attributes[0].components = 5;
    EXPECT_THROW(encodeGlb(makeSingleMeshScene(mesh)), Error);
    mesh = attributedCube();
    mesh.attributes[1].values[3] = std::nanf("");
    EXPECT_THROW(encodeGlb(makeSingleMeshScene(mesh)), Error);
}

TEST(CustomAttributes, AppendKeepsAttributesBothSidesHaveAndDropsTheRest) {
    Mesh a = attributedCube();
    Mesh b = attributedCube();
    b.attributes.pop_back();  // no _ONE
    appendMesh(a, b);
    ASSERT_EQ(a.attributes.size(), 1u);
    EXPECT_EQ(a.attributes[0].name, "_WIND");
    EXPECT_EQ(a.attributes[0].values.size(), 4 * a.vertexCount());
    EXPECT_EQ(a.attributes[0].values[4 * 24], 0.0f);  // b's vertex 0 follows a's
    Mesh empty;
    appendMesh(empty, b);
    EXPECT_EQ(empty.attributes.size(), 1u);
}

TEST(CustomAttributes, ObjExportIgnoresThem) {
    const std::string dir = ::testing::TempDir() + "ramus_obj_attributes";
    std::filesystem::create_directories(dir);
    writeObj(makeSingleMeshScene(attributedCube()), dir + "/cube.obj");
    const std::string obj = readFile(dir + "/cube.obj");
    EXPECT_EQ(obj.find("_WIND"), std::string::npos);
    EXPECT_NE(obj.find("\nf "), std::string::npos);
}

TEST(MergePrimitives, SameMaterialsBecomeOnePrimitiveInFirstUseOrder) {
    Mesh a = makeCube();
    a.materials = {Material{"bark"}};
    a.primitives = {MeshPrimitive{0, 36, 0, "bark"}};
    Mesh leaves = makeCube(0.2f);
    leaves.materials = {Material{"leaves"}};
    leaves.primitives = {MeshPrimitive{0, 36, 0, "leaves"}};
    Mesh mesh = a;
    appendMesh(mesh, leaves);
    appendMesh(mesh, a);
    appendMesh(mesh, leaves);
    ASSERT_EQ(mesh.primitives.size(), 4u);
    const std::size_t triangles = mesh.triangleCount();
    mergePrimitivesByMaterial(mesh);
    ASSERT_EQ(mesh.primitives.size(), 2u);
    ASSERT_EQ(mesh.materials.size(), 2u);
    EXPECT_EQ(mesh.primitives[0].name, "bark");
    EXPECT_EQ(mesh.primitives[0].indexCount, 72u);
    EXPECT_EQ(mesh.primitives[1].firstIndex, 72u);
    EXPECT_EQ(mesh.triangleCount(), triangles);
    // The second bark cube's triangles (vertices 48..71) now follow the first's.
    EXPECT_EQ(mesh.indices[36], 48u);
}

TEST(Textures, GlbEmbedsPngImagesOnceWithASamplerAndTheMaskMode) {
    Mesh mesh = makeCube();
    Material m{"leaf"};
    m.baseColorTexture = checker(8);
    m.normalTexture = checker(4);
    m.alphaMask = true;
    m.alphaCutoff = 0.4f;
    Material other = m;  // another material, the same images
    other.name = "leaf2";
    mesh.materials = {m, other};
    mesh.primitives = {MeshPrimitive{0, 18, 0, "a"}, MeshPrimitive{18, 18, 1, "b"}};
    const Scene scene = makeSingleMeshScene(mesh);
    const json doc = glbJson(encodeGlb(scene));
    ASSERT_EQ(doc["images"].size(), 2u);
    ASSERT_EQ(doc["textures"].size(), 2u);
    ASSERT_EQ(doc["samplers"].size(), 1u);
    EXPECT_EQ(doc["images"][0]["mimeType"], "image/png");
    const json& mat = doc["materials"][0];
    EXPECT_EQ(mat["alphaMode"], "MASK");
    EXPECT_FLOAT_EQ(mat["alphaCutoff"].get<float>(), 0.4f);
    EXPECT_EQ(mat["pbrMetallicRoughness"]["baseColorTexture"]["index"], 0);
    EXPECT_EQ(mat["normalTexture"]["index"], 1);
    EXPECT_EQ(doc["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["index"], 0);
    exportForValidator(scene, "textures");
}

TEST(Textures, ObjWritesThePngNextToItAndMapsItInTheMtl) {
    const std::string dir = ::testing::TempDir() + "ramus_obj_textures";
    std::filesystem::create_directories(dir);
    Mesh mesh = makeCube();
    Material m{"bark leaf"};
    m.baseColorTexture = checker(8);
    m.alphaMask = true;
    mesh.materials = {m};
    writeObj(makeSingleMeshScene(mesh), dir + "/tree.obj");
    const std::string mtl = readFile(dir + "/tree.mtl");
    EXPECT_NE(mtl.find("map_Kd tree_bark_leaf.png\n"), std::string::npos);
    EXPECT_NE(mtl.find("map_d tree_bark_leaf.png\n"), std::string::npos);
    const std::string png = readFile(dir + "/tree_bark_leaf.png");
    EXPECT_EQ(png, encodePng(*m.baseColorTexture));
}

TEST(Textures, InvalidImagesAreErrors) {
    Mesh mesh = makeCube();
    Material m;
    m.baseColorTexture = std::make_shared<const Image>(Image{4, 4, std::vector<std::uint8_t>(10)});
    mesh.materials = {m};
    EXPECT_THROW(encodeGlb(makeSingleMeshScene(mesh)), Error);
}

// A front-facing quad over the whole view, textured with the half-transparent checker.
TEST(Textures, PreviewCutsOutMaskedTexelsAndShowsTheTexture) {
    Mesh quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    quad.normals.assign(4, Vec3f::UnitZ());
    quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    Material m;
    m.baseColor = Vec4f::Ones();
    m.baseColorTexture = checker(2);
    m.alphaMask = true;
    quad.materials = {m};
    RenderParams params;
    params.width = params.height = 64;
    params.view = View::Front;
    params.background = Vec4f(0, 0, 1, 1);
    const Image image = renderScene(makeSingleMeshScene(quad), params);
    auto pixel = [&](int x, int y) { return image.rgba.data() + (y * 64 + x) * 4; };
    EXPECT_GT(pixel(16, 32)[1], 50);  // left half: the texture's green
    EXPECT_LT(pixel(16, 32)[2], 50);
    EXPECT_EQ(pixel(48, 32)[2], 255);  // right half: masked out, background blue
}

}  // namespace
}  // namespace ramus
