#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <nlohmann/json.hpp>

#include "io/io_fixtures.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {
namespace {

using nlohmann::json;
using testing::exportForValidator;
using testing::makeCube;
using testing::makeHierarchyScene;

std::uint32_t u32(const std::string& bytes, std::size_t offset) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;
}

// The parts of a GLB, checked for the structure the spec requires (§4.4).
struct Glb {
    json doc;
    std::string bin;
};

Glb splitGlb(const std::string& bytes) {
    Glb glb;
    EXPECT_GE(bytes.size(), 20u);
    EXPECT_EQ(u32(bytes, 0), 0x46546C67u);  // "glTF"
    EXPECT_EQ(u32(bytes, 4), 2u);
    EXPECT_EQ(u32(bytes, 8), bytes.size());
    const std::uint32_t jsonLength = u32(bytes, 12);
    EXPECT_EQ(u32(bytes, 16), 0x4E4F534Au);  // "JSON"
    EXPECT_EQ(jsonLength % 4, 0u);
    glb.doc = json::parse(bytes.substr(20, jsonLength));
    const std::size_t binStart = 20 + jsonLength;
    if (binStart < bytes.size()) {
        const std::uint32_t binLength = u32(bytes, binStart);
        EXPECT_EQ(u32(bytes, binStart + 4), 0x004E4942u);  // "BIN\0"
        EXPECT_EQ(binLength % 4, 0u);
        EXPECT_EQ(binStart + 8 + binLength, bytes.size());
        glb.bin = bytes.substr(binStart + 8, binLength);
    }
    return glb;
}

std::vector<float> accessorFloats(const Glb& glb, int accessor) {
    const json& a = glb.doc["accessors"][accessor];
    const json& view = glb.doc["bufferViews"][a["bufferView"].get<int>()];
    const std::size_t offset = view["byteOffset"].get<std::size_t>() + a.value("byteOffset", 0);
    const int components = a["type"] == "VEC2" ? 2 : a["type"] == "VEC3" ? 3 : 4;
    std::vector<float> values(a["count"].get<std::size_t>() * components);
    std::memcpy(values.data(), glb.bin.data() + offset, values.size() * 4);
    return values;
}

TEST(GlbWriter, HeaderAndChunksAreAlignedAndSized) {
    const std::string bytes = encodeGlb(makeSingleMeshScene(makeCube()));
    EXPECT_EQ(bytes.size() % 4, 0u);
    const Glb glb = splitGlb(bytes);
    // JSON chunk padding is spaces (0x20), never zeros.
    const std::uint32_t jsonLength = u32(bytes, 12);
    EXPECT_NE(bytes[20 + jsonLength - 1], '\0');
    // The buffer's byteLength fits the BIN chunk, with less than 4 bytes of padding after it.
    const std::size_t declared = glb.doc["buffers"][0]["byteLength"].get<std::size_t>();
    EXPECT_LE(declared, glb.bin.size());
    EXPECT_LT(glb.bin.size() - declared, 4u);
    exportForValidator(makeSingleMeshScene(makeCube()), "cube");
}

TEST(GlbWriter, JsonHasAssetSceneAndOneMeshNode) {
    const Scene scene = makeSingleMeshScene(makeCube(), "box");
    const Glb glb = splitGlb(encodeGlb(scene));
    exportForValidator(scene, "box");
    EXPECT_EQ(glb.doc["asset"]["version"], "2.0");
    EXPECT_EQ(glb.doc["asset"]["generator"], "ramus 0.1.0");
    EXPECT_EQ(glb.doc["scene"], 0);
    EXPECT_EQ(glb.doc["scenes"][0]["nodes"], json::array({0}));
    ASSERT_EQ(glb.doc["nodes"].size(), 1u);
    EXPECT_EQ(glb.doc["nodes"][0]["name"], "box");
    EXPECT_EQ(glb.doc["nodes"][0]["mesh"], 0);
    EXPECT_FALSE(glb.doc["nodes"][0].contains("translation"));  // defaults are omitted
    EXPECT_FALSE(glb.doc["nodes"][0].contains("rotation"));
    const json& prim = glb.doc["meshes"][0]["primitives"][0];
    for (const char* attribute : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0"}) {
        EXPECT_TRUE(prim["attributes"].contains(attribute)) << attribute;
    }
    EXPECT_EQ(glb.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"],
              json::parse("[0.8, 0.8, 0.8, 1]"));
    EXPECT_EQ(glb.doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"], 0.9);
}

TEST(GlbWriter, AccessorCountsAndPositionBoundsMatchTheCube) {
    const Scene scene = makeSingleMeshScene(makeCube(0.5f, {1.0f, 2.0f, 3.0f}));
    const Glb glb = splitGlb(encodeGlb(scene));
    exportForValidator(scene, "offset_cube");
    const json& prim = glb.doc["meshes"][0]["primitives"][0];
    const json& position = glb.doc["accessors"][prim["attributes"]["POSITION"].get<int>()];
    EXPECT_EQ(position["count"], 24);
    EXPECT_EQ(position["componentType"], 5126);
    EXPECT_EQ(position["type"], "VEC3");
    EXPECT_EQ(position["min"], json::parse("[0.5, 1.5, 2.5]"));
    EXPECT_EQ(position["max"], json::parse("[1.5, 2.5, 3.5]"));
    const json& indices = glb.doc["accessors"][prim["indices"].get<int>()];
    EXPECT_EQ(indices["count"], 36);
    EXPECT_EQ(indices["componentType"], 5123);  // UNSIGNED_SHORT below 65535 vertices
    const json& indexView = glb.doc["bufferViews"][indices["bufferView"].get<int>()];
    EXPECT_EQ(indexView["target"], 34963);
    EXPECT_FALSE(indexView.contains("byteStride"));
    for (const json& view : glb.doc["bufferViews"]) EXPECT_EQ(view["byteOffset"].get<int>() % 4, 0);
}

TEST(GlbWriter, BufferHoldsThePositionsExactly) {
    const Mesh cube = makeCube(0.3f);
    const Glb glb = splitGlb(encodeGlb(makeSingleMeshScene(cube)));
    exportForValidator(makeSingleMeshScene(cube), "small_cube");
    const json& prim = glb.doc["meshes"][0]["primitives"][0];
    const std::vector<float> positions = accessorFloats(glb, prim["attributes"]["POSITION"]);
    ASSERT_EQ(positions.size(), 72u);
    for (std::size_t i = 0; i < cube.positions.size(); ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(positions[i * 3 + c], cube.positions[i][c]);
    }
}

TEST(GlbWriter, NormalsAndTangentsAreWrittenNormalized) {
    Mesh cube = makeCube();
    cube.normals[0] *= 3.0f;          // not unit length
    cube.normals[1] = Vec3f::Zero();  // degenerate
    cube.tangents[2] = Vec4f(0.0f, 0.0f, -2.0f, -0.25f);
    const Scene scene = makeSingleMeshScene(cube);
    const Glb glb = splitGlb(encodeGlb(scene));
    const json& attrs = glb.doc["meshes"][0]["primitives"][0]["attributes"];
    const std::vector<float> normals = accessorFloats(glb, attrs["NORMAL"]);
    const std::vector<float> tangents = accessorFloats(glb, attrs["TANGENT"]);
    for (std::size_t i = 0; i < 24; ++i) {
        const Vec3f n(normals[i * 3], normals[i * 3 + 1], normals[i * 3 + 2]);
        EXPECT_NEAR(n.norm(), 1.0f, 1e-6f) << i;
        const Vec3f t(tangents[i * 4], tangents[i * 4 + 1], tangents[i * 4 + 2]);
        EXPECT_NEAR(t.norm(), 1.0f, 1e-6f) << i;
        EXPECT_EQ(std::abs(tangents[i * 4 + 3]), 1.0f) << i;
    }
    EXPECT_EQ(Vec3f(normals[0], normals[1], normals[2]), Vec3f::UnitX());
    EXPECT_EQ(Vec4f(tangents[8], tangents[9], tangents[10], tangents[11]), Vec4f(0, 0, -1, -1));
    exportForValidator(scene, "fixed_normals");
}

TEST(GlbWriter, EncodingTwiceGivesIdenticalBytes) {
    const Scene scene = makeHierarchyScene();
    EXPECT_EQ(encodeGlb(scene), encodeGlb(scene));
    EXPECT_EQ(encodeGlb(scene), encodeGlb(Scene(scene)));
}

TEST(GlbWriter, PrimitivesShareVerticesAndGetTheirOwnIndicesAndMaterials) {
    const Scene scene = makeHierarchyScene();
    const Glb glb = splitGlb(encodeGlb(scene));
    exportForValidator(scene, "hierarchy_two_primitives");
    const json& prims = glb.doc["meshes"][0]["primitives"];
    ASSERT_EQ(prims.size(), 2u);
    EXPECT_EQ(prims[0]["attributes"], prims[1]["attributes"]);
    EXPECT_NE(prims[0]["indices"], prims[1]["indices"]);
    EXPECT_EQ(glb.doc["accessors"][prims[0]["indices"].get<int>()]["count"], 24);
    EXPECT_EQ(glb.doc["accessors"][prims[1]["indices"].get<int>()]["count"], 12);
    EXPECT_EQ(glb.doc["accessors"][prims[1]["indices"].get<int>()]["byteOffset"], 24 * 2);
    EXPECT_EQ(prims[1]["extras"]["name"], "leaves");
    const json& leaves = glb.doc["materials"][prims[1]["material"].get<int>()];
    EXPECT_EQ(leaves["name"], "leaves");
    EXPECT_EQ(leaves["doubleSided"], true);
    EXPECT_EQ(leaves["alphaMode"], "BLEND");
    EXPECT_EQ(leaves["pbrMetallicRoughness"]["baseColorFactor"],
              json::parse("[0.2, 0.6, 0.15, 0.5]"));
    // The twig has no materials: it gets the default material once.
    EXPECT_EQ(glb.doc["materials"].size(), 3u);
}

TEST(GlbWriter, NodesKeepHierarchyTransformsAndExtras) {
    const Glb glb = splitGlb(encodeGlb(makeHierarchyScene()));
    const json& nodes = glb.doc["nodes"];
    ASSERT_EQ(nodes.size(), 4u);
    EXPECT_EQ(glb.doc["scenes"][0]["nodes"], json::array({0}));
    EXPECT_EQ(glb.doc["scenes"][0]["extras"], json::parse(R"({"seed":7})"));
    EXPECT_EQ(nodes[0]["children"], json::array({1, 2}));
    EXPECT_EQ(nodes[2]["children"], json::array({3}));
    EXPECT_FALSE(nodes[0].contains("mesh"));
    EXPECT_EQ(nodes[3]["mesh"], 1);
    EXPECT_EQ(nodes[0]["extras"], json::parse(R"({"kind":"root","side":"center"})"));
    EXPECT_EQ(nodes[2]["extras"]["limits"], json::parse("[-0.5, 1.25]"));
    EXPECT_EQ(nodes[1]["translation"], json::parse("[0, 0.5, 0]"));
    EXPECT_EQ(nodes[3]["scale"], json::parse("[1, 2, 1]"));
    // [x, y, z, w] of 0.5 rad about +Z, written at float precision (as readers store it).
    const json& r = nodes[2]["rotation"];
    EXPECT_EQ(r[2].get<float>(), static_cast<float>(std::sin(0.25)));
    EXPECT_EQ(r[3].get<float>(), static_cast<float>(std::cos(0.25)));
}

TEST(GlbWriter, SceneWithoutNodesGetsOneNodePerMesh) {
    Scene scene;
    scene.meshes = {makeCube(), makeCube(0.2f)};
    scene.meshes[1].name = "small";
    const Glb glb = splitGlb(encodeGlb(scene));
    ASSERT_EQ(glb.doc["nodes"].size(), 2u);
    EXPECT_EQ(glb.doc["nodes"][1]["name"], "small");
    EXPECT_EQ(glb.doc["nodes"][1]["mesh"], 1);
    EXPECT_EQ(glb.doc["scenes"][0]["nodes"], json::array({0, 1}));
    exportForValidator(scene, "meshes_without_nodes");
}

TEST(GlbWriter, MeshWithoutTrianglesIsLeftOutButItsNodeStays) {
    Scene scene = makeSingleMeshScene(Mesh{}, "empty");
    const Glb glb = splitGlb(encodeGlb(scene));
    EXPECT_FALSE(glb.doc.contains("meshes"));
    EXPECT_FALSE(glb.doc.contains("buffers"));
    EXPECT_TRUE(glb.bin.empty());
    EXPECT_EQ(glb.doc["nodes"][0]["name"], "empty");
    EXPECT_FALSE(glb.doc["nodes"][0].contains("mesh"));
    exportForValidator(scene, "empty_mesh");
}

TEST(GlbWriter, EmptyPrimitivesAreSkipped) {
    Mesh cube = makeCube();
    cube.materials = {Material{}, Material{"unused"}};
    cube.primitives = {MeshPrimitive{0, 36, 0, "all"}, MeshPrimitive{36, 0, 1, "none"}};
    const Scene scene = makeSingleMeshScene(cube);
    const Glb glb = splitGlb(encodeGlb(scene));
    EXPECT_EQ(glb.doc["meshes"][0]["primitives"].size(), 1u);
    EXPECT_EQ(glb.doc["materials"].size(), 1u);
    exportForValidator(scene, "empty_primitive");
}

TEST(GlbWriter, EmptySceneIsAValidAssetWithoutBuffers) {
    const Scene scene;
    const Glb glb = splitGlb(encodeGlb(scene));
    EXPECT_EQ(glb.doc["asset"]["version"], "2.0");
    EXPECT_EQ(glb.doc["scenes"], json::parse("[{}]"));
    EXPECT_FALSE(glb.doc.contains("nodes"));
    EXPECT_FALSE(glb.doc.contains("accessors"));
    exportForValidator(scene, "empty_scene");
}

// The indices of one accessor, read back from the BIN chunk (UNSIGNED_SHORT or UNSIGNED_INT).
std::vector<std::uint32_t> accessorIndices(const Glb& glb, int accessor) {
    const json& a = glb.doc["accessors"][accessor];
    const json& view = glb.doc["bufferViews"][a["bufferView"].get<int>()];
    const std::size_t offset = view["byteOffset"].get<std::size_t>() + a.value("byteOffset", 0);
    const bool shortIndices = a["componentType"] == 5123;
    std::vector<std::uint32_t> values(a["count"].get<std::size_t>());
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::uint16_t s = 0;
        if (shortIndices) {
            std::memcpy(&s, glb.bin.data() + offset + 2 * i, 2);
            values[i] = s;
        } else {
            std::memcpy(&values[i], glb.bin.data() + offset + 4 * i, 4);
        }
    }
    return values;
}

// Meshes with equal index buffers share one index accessor, whether the equal one came just
// before (a run of boxes) or earlier with other meshes in between; every mesh reads back its
// own indices.
TEST(GlbWriter, EqualIndexBuffersAreWrittenOnce) {
    const Mesh a = makeCube(0.5f);
    Mesh b = makeCube(0.25f);
    std::reverse(b.indices.begin(), b.indices.end());  // other indices, same vertex count
    Scene scene;
    const std::vector<const Mesh*> order = {&a, &a, &b, &a, &b, &b};
    for (const Mesh* m : order) scene.meshes.push_back(*m);
    const Glb glb = splitGlb(encodeGlb(scene));
    ASSERT_EQ(glb.doc["meshes"].size(), 6u);
    std::vector<int> accessors;
    for (const json& mesh : glb.doc["meshes"]) {
        accessors.push_back(mesh["primitives"][0]["indices"].get<int>());
    }
    EXPECT_EQ(accessors[0], accessors[1]);
    EXPECT_EQ(accessors[0], accessors[3]);
    EXPECT_EQ(accessors[2], accessors[4]);
    EXPECT_EQ(accessors[2], accessors[5]);
    EXPECT_NE(accessors[0], accessors[2]);
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        EXPECT_EQ(accessorIndices(glb, accessors[m]), scene.meshes[m].indices) << "mesh " << m;
    }
    exportForValidator(scene, "shared_index_buffers");
}

TEST(GlbWriter, LargeMeshesUseUnsignedIntIndices) {
    Mesh grid;
    grid.name = "grid";
    const int n = 300;  // 90000 vertices
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) grid.positions.emplace_back(x * 0.01f, 0.0f, y * 0.01f);
    }
    for (int y = 0; y + 1 < n; ++y) {
        for (int x = 0; x + 1 < n; ++x) {
            const auto i = static_cast<std::uint32_t>(y * n + x);
            const auto m = static_cast<std::uint32_t>(n);
            grid.indices.insert(grid.indices.end(), {i, i + m, i + 1, i + 1, i + m, i + m + 1});
        }
    }
    const Scene scene = makeSingleMeshScene(grid, "grid");
    const Glb glb = splitGlb(encodeGlb(scene));
    const json& prim = glb.doc["meshes"][0]["primitives"][0];
    EXPECT_EQ(glb.doc["accessors"][prim["indices"].get<int>()]["componentType"], 5125);
    EXPECT_FALSE(prim["attributes"].contains("NORMAL"));
    exportForValidator(scene, "grid_uint_indices");
}

TEST(GlbWriter, CustomGeneratorIsWrittenVerbatim) {
    Scene scene = makeSingleMeshScene(makeCube());
    scene.generator = "ramus lsystem 0.1.0";
    EXPECT_EQ(splitGlb(encodeGlb(scene)).doc["asset"]["generator"], "ramus lsystem 0.1.0");
    exportForValidator(scene, "custom_generator");
}

TEST(GlbWriter, WriteGlbWritesTheEncodedBytes) {
    const std::filesystem::path dir = testing::scratchDir("write_glb");
    const Scene scene = makeHierarchyScene();
    const std::string path = (dir / "tree.glb").string();
    writeGlb(scene, path);
    EXPECT_EQ(readFile(path), encodeGlb(scene));
    exportForValidator(scene, "write_glb");
}

TEST(GlbWriter, InvalidExtrasJsonIsAnErrorNamingTheNode) {
    Scene scene = makeHierarchyScene();
    scene.nodes[2].extrasJson = "{\"limb\": ";
    try {
        encodeGlb(scene);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("node 2 ('branch')"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos) << e.what();
    }
}

TEST(GlbWriter, ExtrasThatAreNotAnObjectAreAnError) {
    Scene scene = makeHierarchyScene();
    scene.extrasJson = "[1, 2]";
    EXPECT_THROW(encodeGlb(scene), Error);
}

TEST(GlbWriter, WriteGlbErrorsNameThePath) {
    Scene scene = makeSingleMeshScene(makeCube());
    scene.meshes[0].indices[5] = 99;
    try {
        writeGlb(scene, "/tmp/ramus_io_bad.glb");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "/tmp/ramus_io_bad.glb: mesh 0 ('cube'): index 5 is 99; expected < 24 (the "
                  "vertex count)");
    }
    EXPECT_FALSE(std::filesystem::exists("/tmp/ramus_io_bad.glb"));
}

}  // namespace
}  // namespace ramus
