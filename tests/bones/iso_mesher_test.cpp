// Marching-tetrahedra isosurface mesher (src/bones/iso_mesher.hpp) on shapes with known answers.
#include "bones/iso_mesher.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "bones/mesh_checks.hpp"
#include "bones/sdf.hpp"

namespace ramus {
namespace {

const DistanceFunction kSphere = [](const Vec3& p) {
    return sdf::sphere(p, Vec3(0.1, -0.2, 0.3), 0.8);
};

TEST(IsoMesher, SphereIsClosedManifold) {
    const Mesh mesh =
        meshIsosurface(kSphere, Vec3(-0.8, -1.1, -0.6), Vec3(1.0, 0.7, 1.2), {24, 24, 24});
    ASSERT_GT(mesh.triangleCount(), 100u);
    EXPECT_TRUE(isClosedManifold(mesh));
}

TEST(IsoMesher, SphereVolumeIsNearAnalytic) {
    const Mesh mesh =
        meshIsosurface(kSphere, Vec3(-0.8, -1.1, -0.6), Vec3(1.0, 0.7, 1.2), {30, 30, 30});
    const double expected = 4.0 / 3.0 * std::numbers::pi * 0.8 * 0.8 * 0.8;
    EXPECT_NEAR(signedVolume(mesh), expected, 0.03 * expected);
}

TEST(IsoMesher, SphereTrianglesFaceOutwards) {
    const Mesh mesh =
        meshIsosurface(kSphere, Vec3(-0.8, -1.1, -0.6), Vec3(1.0, 0.7, 1.2), {20, 20, 20});
    const Vec3 centre(0.1, -0.2, 0.3);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 a = mesh.positions[mesh.indices[3 * t]].cast<double>();
        const Vec3 b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
        const Vec3 c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
        ASSERT_GT((b - a).cross(c - a).dot((a + b + c) / 3.0 - centre), 0.0) << "triangle " << t;
    }
}

TEST(IsoMesher, SphereVerticesLieOnSurfaceWithUnitOutwardNormals) {
    const Mesh mesh =
        meshIsosurface(kSphere, Vec3(-0.8, -1.1, -0.6), Vec3(1.0, 0.7, 1.2), {20, 20, 20});
    const double cell = 1.8 / 20.0;
    const Vec3 centre(0.1, -0.2, 0.3);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3 p = mesh.positions[i].cast<double>();
        EXPECT_LT(std::abs((p - centre).norm() - 0.8), 0.1 * cell);
        const Vec3 n = mesh.normals[i].cast<double>();
        EXPECT_NEAR(n.norm(), 1.0, 1e-5);
        EXPECT_GT(n.dot((p - centre).normalized()), 0.99);
    }
}

TEST(IsoMesher, TrianglesAreNotDegenerate) {
    // A box aligned with the grid puts many crossings close to grid corners.
    const DistanceFunction box = [](const Vec3& p) {
        return sdf::roundBox(p, Vec3::Zero(), Vec3(0.5, 0.5, 0.5), 0.0);
    };
    const Mesh mesh = meshIsosurface(box, Vec3::Constant(-0.6), Vec3::Constant(0.6), {12, 12, 12});
    ASSERT_GT(mesh.triangleCount(), 0u);
    EXPECT_TRUE(isClosedManifold(mesh));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1],
                            i2 = mesh.indices[3 * t + 2];
        ASSERT_TRUE(i0 != i1 && i1 != i2 && i0 != i2);
        const Vec3 a = mesh.positions[i0].cast<double>();
        const Vec3 b = mesh.positions[i1].cast<double>();
        const Vec3 c = mesh.positions[i2].cast<double>();
        ASSERT_GT((b - a).cross(c - a).norm() * 0.5, 1e-9) << "triangle " << t;
    }
}

TEST(IsoMesher, EmptyZeroSetGivesEmptyMesh) {
    const DistanceFunction far = [](const Vec3& p) { return sdf::sphere(p, Vec3(9, 9, 9), 1.0); };
    const Mesh mesh = meshIsosurface(far, Vec3::Constant(-1), Vec3::Constant(1), {8, 8, 8});
    EXPECT_EQ(mesh.triangleCount(), 0u);
    EXPECT_EQ(mesh.vertexCount(), 0u);
}

TEST(IsoMesher, BudgetedMeshStaysWithinBudgetAndIsClosed) {
    for (int budget : {200, 400, 2000}) {
        const Mesh mesh = meshIsosurfaceWithinBudget(kSphere, Vec3(-0.8, -1.1, -0.6),
                                                     Vec3(1.0, 0.7, 1.2), budget, 64);
        EXPECT_LE(static_cast<int>(mesh.triangleCount()), budget);
        EXPECT_GT(static_cast<int>(mesh.triangleCount()), budget / 4);
        EXPECT_TRUE(isClosedManifold(mesh));
    }
}

}  // namespace
}  // namespace ramus
