// Leaves and other turtle polygons: ear clipping in the Newell plane, normals, UVs, tangents.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "ramus/export.hpp"
#include "ramus/scene.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus {
namespace {

struct Polygons {
    std::vector<Vec3> vertices;
    std::vector<std::uint32_t> offsets{0};

    Polygons& add(const std::vector<Vec3>& polygon) {
        vertices.insert(vertices.end(), polygon.begin(), polygon.end());
        offsets.push_back(static_cast<std::uint32_t>(vertices.size()));
        return *this;
    }
    Mesh mesh() const { return buildPolygonMesh(vertices, offsets); }
};

double signedArea(const Mesh& mesh, std::size_t t, const Vec3& normal) {
    const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    return 0.5 * (b - a).cross(c - a).dot(normal);
}

TEST(PolygonMesh, SquareBecomesTwoTrianglesFacingItsNewellNormal) {
    const Mesh mesh =
        Polygons{}.add({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}).mesh();
    EXPECT_EQ(mesh.name, "leaves");
    ASSERT_EQ(mesh.vertexCount(), 4u);
    ASSERT_EQ(mesh.triangleCount(), 2u);
    for (const Vec3f& n : mesh.normals) EXPECT_EQ(n, Vec3f(0, 0, 1));
    for (std::size_t t = 0; t < 2; ++t) EXPECT_NEAR(signedArea(mesh, t, Vec3::UnitZ()), 0.5, 1e-9);
    ASSERT_EQ(mesh.primitives.size(), 1u);
    EXPECT_EQ(mesh.primitives[0].name, "leaves");
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_TRUE(mesh.materials[0].doubleSided);
}

TEST(PolygonMesh, ClockwisePolygonFacesTheOtherWay) {
    const Mesh mesh =
        Polygons{}.add({Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(1, 0, 0)}).mesh();
    ASSERT_EQ(mesh.triangleCount(), 2u);
    for (const Vec3f& n : mesh.normals) EXPECT_EQ(n, Vec3f(0, 0, -1));
    for (std::size_t t = 0; t < 2; ++t) EXPECT_GT(signedArea(mesh, t, -Vec3::UnitZ()), 0.0);
}

TEST(PolygonMesh, ConcavePolygonIsTriangulatedWithoutOverlap) {
    // An L of three unit squares in the xz-plane; x then z, so counter-clockwise around -y.
    const std::vector<Vec3> l{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 1),
                              Vec3(1, 0, 1), Vec3(1, 0, 2), Vec3(0, 0, 2)};
    const Mesh mesh = Polygons{}.add(l).mesh();
    ASSERT_EQ(mesh.triangleCount(), 4u);
    const Vec3 normal = mesh.normals[0].cast<double>();
    EXPECT_NEAR(normal.dot(-Vec3::UnitY()), 1.0, 1e-9);
    double total = 0.0;
    for (std::size_t t = 0; t < 4; ++t) {
        const double area = signedArea(mesh, t, normal);
        EXPECT_GT(area, 0.0);
        total += area;
    }
    EXPECT_NEAR(total, 3.0, 1e-9);  // all positive and summing to the area: no overlap
    // No triangle covers the notch (centre of the missing square).
    const Vec3 notch(1.5, 0, 1.5);
    for (std::size_t t = 0; t < 4; ++t) {
        const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
        const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
        const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
        const bool inside = (b - a).cross(notch - a).dot(normal) > 0 &&
                            (c - b).cross(notch - b).dot(normal) > 0 &&
                            (a - c).cross(notch - c).dot(normal) > 0;
        EXPECT_FALSE(inside) << "triangle " << t;
    }
}

TEST(PolygonMesh, CollinearAndRepeatedVerticesAddNoDegenerateTriangles) {
    const Mesh mesh = Polygons{}
                          .add({Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0),
                                Vec3(1, 1, 0), Vec3(0, 1, 0)})
                          .mesh();
    ASSERT_GE(mesh.triangleCount(), 2u);
    double total = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const double area = signedArea(mesh, t, Vec3::UnitZ());
        EXPECT_GT(area, 1e-9);
        total += area;
    }
    EXPECT_NEAR(total, 1.0, 1e-9);
}

TEST(PolygonMesh, PolygonsWithoutAreaAreSkipped) {
    Polygons polygons;
    polygons.add({Vec3(0, 0, 0), Vec3(1, 0, 0)});                 // two vertices
    polygons.add({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)});  // collinear
    polygons.add({Vec3(5, 5, 5), Vec3(5, 5, 5), Vec3(5, 5, 5)});  // one point
    const Mesh mesh = polygons.mesh();
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.indices.empty());
    EXPECT_TRUE(mesh.primitives.empty());
    EXPECT_TRUE(mesh.materials.empty());
}

TEST(PolygonMesh, NoPolygonsGiveAnEmptyMesh) {
    EXPECT_TRUE(buildPolygonMesh({}, {}).positions.empty());
    const std::vector<std::uint32_t> offsets{0};
    EXPECT_TRUE(buildPolygonMesh({}, offsets).positions.empty());
}

TEST(PolygonMesh, TriangleCountsAddUpOverSeveralPolygons) {
    Polygons polygons;
    polygons.add({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)});
    std::vector<Vec3> hexagon;
    for (int i = 0; i < 6; ++i) {
        hexagon.emplace_back(std::cos(kPi / 3 * i), 2.0, std::sin(kPi / 3 * i));
    }
    polygons.add(hexagon);
    const Mesh mesh = polygons.mesh();
    EXPECT_EQ(mesh.vertexCount(), 9u);
    EXPECT_EQ(mesh.triangleCount(), 1u + 4u);
}

// The leaf axis (first vertex → farthest vertex) runs up the image: v from 1 to 0; u spans
// 0..1 across. Tangent = increasing u, glTF bitangent cross(n, t) · w = decreasing v.
TEST(PolygonMesh, UvsSpanTheBoundsAlongTheLeafAxisWithAGltfTangentFrame) {
    const std::vector<Vec3> leaf{Vec3(0, 0, 0), Vec3(0.5, 1, 0), Vec3(0, 3, 0), Vec3(-0.5, 1, 0)};
    const Mesh mesh = Polygons{}.add(leaf).mesh();
    ASSERT_EQ(mesh.vertexCount(), 4u);
    EXPECT_NEAR(mesh.uvs[0].y(), 1.0f, 1e-6f);  // base
    EXPECT_NEAR(mesh.uvs[2].y(), 0.0f, 1e-6f);  // tip
    EXPECT_NEAR(mesh.uvs[0].x(), 0.5f, 1e-6f);
    EXPECT_NEAR(std::min(mesh.uvs[1].x(), mesh.uvs[3].x()), 0.0f, 1e-6f);
    EXPECT_NEAR(std::max(mesh.uvs[1].x(), mesh.uvs[3].x()), 1.0f, 1e-6f);
    for (std::size_t i = 0; i < 4; ++i) {
        const Vec3 n = mesh.normals[i].cast<double>();
        const Vec3 t = mesh.tangents[i].head<3>().cast<double>();
        EXPECT_NEAR(t.norm(), 1.0, 1e-6);
        EXPECT_NEAR(n.dot(t), 0.0, 1e-6);
        EXPECT_EQ(mesh.tangents[i].w(), 1.0f);
        const Vec3 bitangent = n.cross(t) * mesh.tangents[i].w();
        EXPECT_NEAR(bitangent.dot(Vec3::UnitY()), 1.0, 1e-6);  // toward the tip: v decreases
    }
    // u increases along the tangent.
    const Vec3 across = (mesh.positions[1] - mesh.positions[3]).cast<double>();
    EXPECT_EQ(across.dot(mesh.tangents[0].head<3>().cast<double>()) > 0,
              mesh.uvs[1].x() > mesh.uvs[3].x());
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir != nullptr && *dir != '\0') {
        writeGlb(makeSingleMeshScene(mesh, "leaf"), std::string(dir) + "/polygon_mesh_leaf.glb");
    }
}

TEST(PolygonMesh, KeepsTheGivenMaterialButMakesItDoubleSided) {
    Material material{"maple", {0.9f, 0.3f, 0.1f, 1.0f}, 0.0f, 0.7f, false};
    const std::vector<Vec3> vertices{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const std::vector<std::uint32_t> offsets{0, 3};
    const Mesh mesh = buildPolygonMesh(vertices, offsets, material);
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].name, "maple");
    EXPECT_EQ(mesh.materials[0].baseColor, material.baseColor);
    EXPECT_TRUE(mesh.materials[0].doubleSided);
}

}  // namespace
}  // namespace ramus
