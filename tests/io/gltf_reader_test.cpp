#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "io/io_fixtures.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {
namespace {

using nlohmann::json;
using testing::makeCube;
using testing::makeHierarchyScene;
using testing::scratchDir;

Scene roundTrip(const Scene& scene, const std::string& name) {
    const std::string path = (scratchDir("reader_" + name) / (name + ".glb")).string();
    writeGlb(scene, path);
    testing::exportForValidator(scene, "roundtrip_" + name);
    return readGltf(path);
}

// Writes a .gltf with its binary data in `name`.bin next to it and returns the .gltf path.
std::string writeGltf(const std::string& name, json doc, const std::string& bin) {
    const std::filesystem::path dir = scratchDir("reader_" + name);
    writeFileAtomic((dir / (name + ".bin")).string(), bin);
    doc["asset"] = {{"version", "2.0"}};
    doc["buffers"] = json::array({{{"uri", name + ".bin"}, {"byteLength", bin.size()}}});
    const std::string path = (dir / (name + ".gltf")).string();
    writeFileAtomic(path, doc.dump());
    return path;
}

template <typename T>
void appendRaw(std::string& bin, std::initializer_list<T> values) {
    for (T v : values) bin.append(reinterpret_cast<const char*>(&v), sizeof v);
}

TEST(GltfReader, RoundTripKeepsGeometryExactly) {
    const Mesh cube = makeCube(0.7f, {0.1f, -0.2f, 0.3f});
    const Scene back = roundTrip(makeSingleMeshScene(cube, "box"), "cube");
    ASSERT_EQ(back.meshes.size(), 1u);
    const Mesh& m = back.meshes[0];
    EXPECT_EQ(m.name, "cube");
    EXPECT_EQ(m.positions, cube.positions);
    EXPECT_EQ(m.normals, cube.normals);
    EXPECT_EQ(m.tangents, cube.tangents);
    EXPECT_EQ(m.uvs, cube.uvs);
    EXPECT_EQ(m.indices, cube.indices);
    ASSERT_EQ(m.primitives.size(), 1u);
    EXPECT_EQ(m.primitives[0].indexCount, 36u);
    ASSERT_EQ(back.nodes.size(), 1u);
    EXPECT_EQ(back.nodes[0].name, "box");
    EXPECT_EQ(back.nodes[0].mesh, 0);
}

TEST(GltfReader, RoundTripKeepsPrimitivesMaterialsAndHierarchy) {
    const Scene scene = makeHierarchyScene();
    const Scene back = roundTrip(scene, "hierarchy");
    ASSERT_EQ(back.nodes.size(), scene.nodes.size());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const SceneNode& a = scene.nodes[i];
        const SceneNode& b = back.nodes[i];
        EXPECT_EQ(b.name, a.name);
        EXPECT_EQ(b.parent, a.parent);
        EXPECT_EQ(b.mesh, a.mesh);
        EXPECT_EQ(b.translation, a.translation);
        EXPECT_EQ(b.scale, a.scale);
        // Node transforms are written at float precision.
        EXPECT_TRUE(b.rotation.isApprox(a.rotation, 1e-7));
        EXPECT_EQ(b.extrasJson.empty() ? json() : json::parse(b.extrasJson),
                  a.extrasJson.empty() ? json() : json::parse(a.extrasJson));
    }
    EXPECT_EQ(json::parse(back.extrasJson), json::parse(scene.extrasJson));
    const Mesh& tree = back.meshes[0];
    EXPECT_EQ(tree.positions, scene.meshes[0].positions);
    EXPECT_EQ(tree.indices, scene.meshes[0].indices);
    ASSERT_EQ(tree.primitives.size(), 2u);
    EXPECT_EQ(tree.primitives[1].firstIndex, 24u);
    EXPECT_EQ(tree.primitives[1].indexCount, 12u);
    EXPECT_EQ(tree.primitives[1].name, "leaves");
    const Material& leaves = tree.materials[tree.primitives[1].material];
    EXPECT_EQ(leaves.name, "leaves");
    EXPECT_EQ(leaves.baseColor, scene.meshes[0].materials[1].baseColor);
    EXPECT_EQ(leaves.roughness, 0.6f);
    EXPECT_TRUE(leaves.doubleSided);
}

TEST(GltfReader, ReencodingARoundTripGivesTheSameBytes) {
    const Scene scene = makeHierarchyScene();
    const Scene back = roundTrip(scene, "reencode");
    EXPECT_EQ(encodeGlb(roundTrip(back, "reencode2")), encodeGlb(back));
}

TEST(GltfReader, ChildrenListedBeforeParentsAreReordered) {
    json doc;
    doc["nodes"] = json::parse(R"([{"name": "hand", "translation": [0, 1, 0]},
                                   {"name": "arm", "children": [0]},
                                   {"name": "body", "children": [1]}])");
    doc["scenes"] = json::parse(R"([{"nodes": [2]}])");
    doc["scene"] = 0;
    doc["asset"] = {{"version", "2.0"}};
    const std::filesystem::path path = scratchDir("reader_order") / "order.gltf";
    writeFileAtomic(path.string(), doc.dump());
    testing::exportGltfForValidator(path.string(), "order");
    const Scene scene = readGltf(path.string());
    ASSERT_EQ(scene.nodes.size(), 3u);
    EXPECT_EQ(scene.nodes[0].name, "body");
    EXPECT_EQ(scene.nodes[1].name, "arm");
    EXPECT_EQ(scene.nodes[1].parent, 0);
    EXPECT_EQ(scene.nodes[2].name, "hand");
    EXPECT_EQ(scene.nodes[2].parent, 1);
    EXPECT_EQ(scene.nodes[2].translation, Vec3(0, 1, 0));
}

TEST(GltfReader, MatrixIsSplitIntoTranslationRotationScale) {
    // T(1, 2, 3) · R(90° about +Y) · S(2, 3, 4), column-major: R maps x→-z, z→x.
    json doc;
    doc["nodes"] = json::array({{{"matrix", {0, 0, -2, 0, 0, 3, 0, 0, 4, 0, 0, 0, 1, 2, 3, 1}}}});
    doc["asset"] = {{"version", "2.0"}};
    const std::filesystem::path path = scratchDir("reader_matrix") / "matrix.gltf";
    writeFileAtomic(path.string(), doc.dump());
    testing::exportGltfForValidator(path.string(), "matrix");
    const SceneNode node = readGltf(path.string()).nodes.at(0);
    EXPECT_TRUE(node.translation.isApprox(Vec3(1, 2, 3)));
    EXPECT_TRUE(node.scale.isApprox(Vec3(2, 3, 4)));
    const Eigen::Quaterniond expected(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()));
    EXPECT_NEAR(std::abs(node.rotation.dot(expected)), 1.0, 1e-12);
}

TEST(GltfReader, StripsFansAndUnindexedPrimitivesBecomeTriangles) {
    std::string bin;
    appendRaw<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});  // 4 vertices
    appendRaw<std::uint8_t>(bin, {0, 1, 2, 3});
    json doc = json::parse(R"({
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 4}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                     "min": [0, 0, 0], "max": [1, 1, 0]},
                    {"bufferView": 1, "componentType": 5121, "count": 4, "type": "SCALAR"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 5},
                                 {"attributes": {"POSITION": 0}, "indices": 1, "mode": 6},
                                 {"attributes": {"POSITION": 0}, "mode": 4},
                                 {"attributes": {"POSITION": 0}, "mode": 1}]}]})");
    const std::string path = writeGltf("modes", doc, bin);
    testing::exportGltfForValidator(path, "modes");
    const Scene scene = readGltf(path);
    const Mesh& m = scene.meshes.at(0);
    EXPECT_EQ(m.positions.size(), 4u);   // one shared vertex set
    ASSERT_EQ(m.primitives.size(), 3u);  // the line primitive is left out
    const std::vector<std::uint32_t> expected = {0, 1, 2, 1, 3, 2,  // strip
                                                 1, 2, 0, 2, 3, 0,  // fan
                                                 0, 1, 2};          // list (4th vertex dropped)
    EXPECT_EQ(m.indices, expected);
    EXPECT_TRUE(m.normals.empty());
    EXPECT_EQ(m.materials.at(0).name, "default");
    EXPECT_TRUE(scene.nodes.empty());
}

TEST(GltfReader, InterleavedNormalizedAndSparseAccessorsAreDecoded) {
    std::string bin;
    // Interleaved: position (3 floats) + uv (2 normalized ushorts) + padding = 16-byte stride.
    for (int i = 0; i < 3; ++i) {
        appendRaw<float>(bin, {float(i), 0.0f, 0.0f});
        appendRaw<std::uint16_t>(bin, {static_cast<std::uint16_t>(i * 32767), 65535});
    }
    appendRaw<std::uint16_t>(bin, {1, 0});      // sparse index: vertex 1 (+2 bytes padding)
    appendRaw<float>(bin, {5.0f, 6.0f, 7.0f});  // its new position
    json doc = json::parse(R"({
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48, "byteStride": 16},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 4},
                      {"buffer": 0, "byteOffset": 52, "byteLength": 12}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                     "min": [0, 0, 0], "max": [5, 6, 7],
                     "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123},
                                "values": {"bufferView": 2}}},
                    {"bufferView": 0, "byteOffset": 12, "componentType": 5123,
                     "normalized": true, "count": 3, "type": "VEC2"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}}]}]})");
    const std::string path = writeGltf("interleaved", doc, bin);
    testing::exportGltfForValidator(path, "interleaved");
    const Mesh m = readGltf(path).meshes.at(0);
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[0], Vec3f(0, 0, 0));
    EXPECT_EQ(m.positions[1], Vec3f(5, 6, 7));
    EXPECT_EQ(m.positions[2], Vec3f(2, 0, 0));
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_FLOAT_EQ(m.uvs[1].x(), 32767.0f / 65535.0f);
    EXPECT_FLOAT_EQ(m.uvs[2].y(), 1.0f);
}

TEST(GltfReader, MissingFileIsAnErrorNamingIt) {
    try {
        readGltf("/nonexistent/tree.glb");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/tree.glb: cannot read file", 0), 0u)
            << e.what();
    }
}

TEST(GltfReader, MalformedFileIsAnErrorWithTinygltfsMessage) {
    const std::filesystem::path path = scratchDir("reader_bad") / "bad.glb";
    writeFileAtomic(path.string(), std::string("glTF\x02\0\0\0garbage", 15));
    try {
        readGltf(path.string());
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path.string() + ": cannot read glTF: ", 0), 0u) << what;
        EXPECT_GT(what.size(), path.string().size() + 22) << what;
    }
}

TEST(GltfReader, IndexOutOfRangeIsAnError) {
    std::string bin;
    appendRaw<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
    appendRaw<std::uint32_t>(bin, {0, 1, 3});
    json doc = json::parse(R"({
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36,
                                                        "byteLength": 12}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}]})");
    const std::string path = writeGltf("bad_index", doc, bin);
    try {
        readGltf(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), path + ": index 3 is out of range; expected < 3");
    }
}

TEST(GltfReader, AccessorPastTheBufferIsAnError) {
    std::string bin;
    appendRaw<float>(bin, {0, 0, 0, 1, 0, 0});
    json doc = json::parse(R"({
      "bufferViews": [{"buffer": 0, "byteLength": 24}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}]})");
    const std::string path = writeGltf("short_view", doc, bin);
    try {
        readGltf(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": buffer view 0 is too short for the data it holds");
    }
}

TEST(GltfReader, NonFiniteVertexDataIsAnError) {
    std::string bin;
    appendRaw<float>(bin, {0, 0, 0, 1, 0, 0, 0, NAN, 0});
    json doc = json::parse(R"({
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}]})");
    const std::string path = writeGltf("nan", doc, bin);
    try {
        readGltf(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": POSITION accessor 0 element 2 is not a finite number");
    }
}

TEST(GltfReader, NodeWithTwoParentsIsAnError) {
    json doc;
    doc["nodes"] = json::parse(R"([{"children": [2]}, {"children": [2]}, {}])");
    doc["asset"] = {{"version", "2.0"}};
    const std::filesystem::path path = scratchDir("reader_dag") / "dag.gltf";
    writeFileAtomic(path.string(), doc.dump());
    EXPECT_THROW(readGltf(path.string()), Error);
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

TEST(GltfReaderInput, ANodeTransformBeyondDoubleRangeIsAReadError) {
    // nlohmann::json cannot even hold the number, so it is put into the text afterwards.
    json doc = json::parse(R"({"nodes": [{"translation": [7777, 0, 0]}]})");
    const std::string path = writeGltf("huge_translation", doc, std::string(4, '\0'));
    std::string text = readFile(path);
    text.replace(text.find("7777"), 4, "1e999");
    writeFileAtomic(path, text);
    try {
        readGltf(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": cannot read glTF: ", 0), 0u) << e.what();
    }
}

TEST(GltfReaderInput, AFileLargerThanTheLimitIsRefused) {
    json doc = json::parse(R"({"nodes": [{}]})");
    const std::string path = writeGltf("size_limit", doc, std::string(4, '\0'));
    const std::size_t size = std::filesystem::file_size(path);
    EXPECT_NO_THROW(readGltf(path, size));
    try {
        readGltf(path, size - 1);
        FAIL() << "expected the size limit";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path + ": the file is larger than the input limit"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace ramus
