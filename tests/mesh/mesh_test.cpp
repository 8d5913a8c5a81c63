// appendMesh: re-basing of indices, primitives and materials; attribute arrays.
// removeUnusedVertices: compaction of every vertex array.
#include "ramus/mesh.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "same_mesh.hpp"

namespace ramus {
namespace {

Mesh triangle(float x, bool attributes) {
    Mesh mesh;
    mesh.positions = {Vec3f(x, 0, 0), Vec3f(x + 1, 0, 0), Vec3f(x, 1, 0)};
    if (attributes) {
        mesh.normals.assign(3, Vec3f(0, 0, 1));
        mesh.tangents.assign(3, Vec4f(1, 0, 0, 1));
        mesh.uvs.assign(3, Vec2f(0, 0));
    }
    mesh.indices = {0, 1, 2};
    return mesh;
}

TEST(AppendMesh, RebasesIndicesPrimitivesAndMaterials) {
    Mesh a = triangle(0, true);
    a.materials.push_back(Material{"bark"});
    a.primitives.push_back(MeshPrimitive{0, 3, 0, "bark"});
    Mesh b = triangle(5, true);
    b.materials.push_back(Material{"leaves"});
    b.primitives.push_back(MeshPrimitive{0, 3, 0, "leaves"});
    appendMesh(a, b);
    EXPECT_EQ(a.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    ASSERT_EQ(a.primitives.size(), 2u);
    EXPECT_EQ(a.primitives[1].firstIndex, 3u);
    EXPECT_EQ(a.primitives[1].material, 1u);
    ASSERT_EQ(a.materials.size(), 2u);
    EXPECT_EQ(a.materials[1].name, "leaves");
    EXPECT_EQ(a.normals.size(), 6u);
    EXPECT_EQ(a.tangents.size(), 6u);
    EXPECT_EQ(a.uvs.size(), 6u);
}

TEST(AppendMesh, MeshWithoutMaterialsKeepsItsDefaultAndTheOtherMaterialStaysApart) {
    Mesh a = triangle(0, false);  // drawn, but no materials: implicit default material
    Mesh b = triangle(5, false);
    b.materials.push_back(Material{"leaves"});
    b.primitives.push_back(MeshPrimitive{0, 3, 0, "leaves"});
    appendMesh(a, b);
    ASSERT_EQ(a.materials.size(), 2u);
    ASSERT_EQ(a.primitives.size(), 2u);
    EXPECT_EQ(a.primitives[0].material, 0u);
    EXPECT_EQ(a.primitives[1].material, 1u);
    EXPECT_EQ(a.materials[a.primitives[1].material].name, "leaves");
}

TEST(AppendMesh, AttributesMissingOnOneSideAreDropped) {
    Mesh a = triangle(0, true);
    appendMesh(a, triangle(5, false));
    EXPECT_EQ(a.positions.size(), 6u);
    EXPECT_TRUE(a.normals.empty());
    EXPECT_TRUE(a.tangents.empty());
    EXPECT_TRUE(a.uvs.empty());
}

TEST(AppendMesh, AppendingToAnEmptyMeshKeepsTheOthersAttributes) {
    Mesh a;
    appendMesh(a, triangle(5, true));
    EXPECT_EQ(a.positions.size(), 3u);
    EXPECT_EQ(a.normals.size(), 3u);
    EXPECT_EQ(a.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(AppendMesh, AppendingAnEmptyMeshChangesNothing) {
    Mesh a = triangle(0, true);
    a.materials.push_back(Material{"bark"});
    a.primitives.push_back(MeshPrimitive{0, 3, 0, "bark"});
    a.attributes.push_back(VertexAttribute{"_WIND", 4, std::vector<float>(12, 0.5f)});
    appendMesh(a, Mesh{});
    EXPECT_EQ(a.positions.size(), 3u);
    EXPECT_EQ(a.normals.size(), 3u);
    EXPECT_EQ(a.primitives.size(), 1u);
    EXPECT_EQ(a.materials.size(), 1u);
    // Custom attributes too (bark with wind data, then a tree without leaves).
    ASSERT_EQ(a.attributes.size(), 1u);
    EXPECT_EQ(a.attributes[0].values.size(), 12u);
}

// Appending a mesh that is dropped afterwards (Mesh&&: its arrays are taken where the target
// has none) gives the same mesh as appending a copy, on every combination of an empty or drawn
// target, with or without materials, attributes, custom attributes and skins.
TEST(AppendMesh, TakingAMeshGivesTheSameAsCopyingIt) {
    std::vector<std::pair<std::string, Mesh>> meshes;
    meshes.emplace_back("empty", Mesh{});
    meshes.emplace_back("plain", triangle(0, false));
    meshes.emplace_back("attributes", triangle(1, true));
    Mesh dressed = triangle(2, true);
    dressed.name = "dressed";
    dressed.materials.push_back(Material{"leaves"});
    dressed.primitives.push_back(MeshPrimitive{0, 3, 0, "leaves"});
    dressed.attributes.push_back(VertexAttribute{"_WIND", 2, std::vector<float>(6, 0.25f)});
    dressed.joints.assign(3, {0, 1, 0, 0});
    dressed.weights.assign(3, Vec4f(0.5f, 0.5f, 0, 0));
    meshes.emplace_back("dressed", dressed);
    Mesh positionsOnly;
    positionsOnly.positions = {Vec3f(1, 2, 3)};
    meshes.emplace_back("positions only", positionsOnly);
    for (const auto& [targetName, target] : meshes) {
        for (const auto& [otherName, other] : meshes) {
            Mesh copied = target;
            appendMesh(copied, other);
            Mesh taken = target;
            appendMesh(taken, Mesh(other));
            test::expectSameMesh(taken, copied, otherName + " appended to " + targetName);
        }
    }
    // The arrays are taken, not copied, where the target has none.
    Mesh empty;
    Mesh source = dressed;
    const Vec3f* positions = source.positions.data();
    appendMesh(empty, std::move(source));
    EXPECT_EQ(empty.positions.data(), positions);
}

TEST(RemoveUnusedVertices, KeepsUsedVerticesInOrderWithAllTheirArrays) {
    Mesh mesh = triangle(0.0f, true);
    appendMesh(mesh, triangle(5.0f, true));
    mesh.uvs[4] = Vec2f(0.25f, 0.75f);
    mesh.attributes.push_back({"_X", 2, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}});
    mesh.indices = {4, 1, 5};  // vertices 0, 2 and 3 unused
    removeUnusedVertices(mesh);
    ASSERT_EQ(mesh.vertexCount(), 3u);
    EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{1, 0, 2}));
    EXPECT_EQ(mesh.positions[0], Vec3f(1, 0, 0));
    EXPECT_EQ(mesh.positions[1], Vec3f(6, 0, 0));
    EXPECT_EQ(mesh.positions[2], Vec3f(5, 1, 0));
    EXPECT_EQ(mesh.uvs[1], Vec2f(0.25f, 0.75f));
    EXPECT_EQ(mesh.normals.size(), 3u);
    EXPECT_EQ(mesh.tangents.size(), 3u);
    EXPECT_TRUE(mesh.joints.empty());
    EXPECT_EQ(mesh.attributes[0].values, (std::vector<float>{2, 3, 8, 9, 10, 11}));
}

// Runs of used vertices move down over the unused ones, overlapping where a run is longer than
// the gap before it.
TEST(RemoveUnusedVertices, MovesLongRunsOverShortGaps) {
    Mesh mesh;
    std::vector<float> values;
    for (int i = 0; i < 10; ++i) {
        mesh.positions.emplace_back(static_cast<float>(i), 0.0f, 0.0f);
        mesh.uvs.emplace_back(static_cast<float>(i), 1.0f);
        values.insert(values.end(), {static_cast<float>(i), -static_cast<float>(i)});
    }
    mesh.attributes.push_back({"_X", 2, values});
    mesh.indices = {0, 1, 3, 4, 5, 6, 8, 9, 9};  // vertices 2 and 7 unused
    removeUnusedVertices(mesh);
    const std::vector<float> kept = {0, 1, 3, 4, 5, 6, 8, 9};
    ASSERT_EQ(mesh.vertexCount(), kept.size());
    EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 7}));
    EXPECT_TRUE(mesh.normals.empty());
    for (std::size_t i = 0; i < kept.size(); ++i) {
        EXPECT_EQ(mesh.positions[i], Vec3f(kept[i], 0, 0));
        EXPECT_EQ(mesh.uvs[i], Vec2f(kept[i], 1));
        EXPECT_EQ(mesh.attributes[0].values[2 * i], kept[i]);
        EXPECT_EQ(mesh.attributes[0].values[2 * i + 1], -kept[i]);
    }
}

}  // namespace
}  // namespace ramus
