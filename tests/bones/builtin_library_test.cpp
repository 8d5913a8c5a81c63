// The default bone library (BoneLibrary::builtin, boneTriangleBudget): every model at Low and
// High is a closed, outward, non-degenerate mesh within its budget that fills the unit cube.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "bones/bone_shapes.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"

namespace ramus {
namespace {

constexpr BoneResolution kResolutions[] = {BoneResolution::Low, BoneResolution::High};

std::string label(BoneModelKind kind, BoneResolution resolution) {
    return std::string(boneModelKindName(kind)) + "/" + std::string(boneResolutionName(resolution));
}

Vec3 corner(const Mesh& mesh, std::size_t t, int i) {
    return mesh.positions[mesh.indices[3 * t + i]].cast<double>();
}

TEST(BuiltinLibrary, EveryModelIsAClosedManifold) {
    for (BoneResolution resolution : kResolutions) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            const Mesh& mesh = BoneLibrary::builtin(resolution).model(kind, resolution).mesh;
            std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
            for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
                for (int e = 0; e < 3; ++e) {
                    ++directed[{mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]}];
                }
            }
            for (const auto& [edge, count] : directed) {
                ASSERT_EQ(count, 1) << label(kind, resolution);
                ASSERT_TRUE(directed.count({edge.second, edge.first})) << label(kind, resolution);
            }
        }
    }
}

TEST(BuiltinLibrary, EveryModelHasPositiveVolumeAndNoDegenerateTriangles) {
    for (BoneResolution resolution : kResolutions) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            const Mesh& mesh = BoneLibrary::builtin(resolution).model(kind, resolution).mesh;
            double volume = 0.0;
            for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
                const Vec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
                volume += a.dot(b.cross(c)) / 6.0;
                ASSERT_GT((b - a).cross(c - a).norm() * 0.5, 1e-9) << label(kind, resolution);
                ASSERT_NE(mesh.indices[3 * t], mesh.indices[3 * t + 1]);
                ASSERT_NE(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
                ASSERT_NE(mesh.indices[3 * t], mesh.indices[3 * t + 2]);
            }
            EXPECT_GT(volume, 0.02) << label(kind, resolution);
        }
    }
}

TEST(BuiltinLibrary, EveryModelStaysWithinItsTriangleBudget) {
    for (BoneResolution resolution : kResolutions) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            const Mesh& mesh = BoneLibrary::builtin(resolution).model(kind, resolution).mesh;
            EXPECT_LE(static_cast<int>(mesh.triangleCount()), boneTriangleBudget(kind, resolution))
                << label(kind, resolution);
            EXPECT_GT(static_cast<int>(mesh.triangleCount()),
                      boneTriangleBudget(kind, resolution) / 3)
                << label(kind, resolution);
        }
    }
}

TEST(BuiltinLibrary, EveryModelHasUnitNormals) {
    for (BoneResolution resolution : kResolutions) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            const Mesh& mesh = BoneLibrary::builtin(resolution).model(kind, resolution).mesh;
            ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << label(kind, resolution);
            for (const Vec3f& n : mesh.normals) {
                ASSERT_NEAR(n.norm(), 1.0f, 1e-5f) << label(kind, resolution);
            }
        }
    }
}

TEST(BuiltinLibrary, EveryModelRoughlyFillsTheUnitCube) {
    for (BoneResolution resolution : kResolutions) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            const Aabb box = BoneLibrary::builtin(resolution).model(kind, resolution).mesh.bounds();
            EXPECT_LT(box.min.x(), 0.15) << label(kind, resolution);
            // Coarse Low grids round off thin tips (digits, the rib's end) a little.
            const double minEnd = resolution == BoneResolution::Low ? 0.75 : 0.9;
            EXPECT_GT(box.max.x(), minEnd) << label(kind, resolution);
            EXPECT_GT(box.min.x(), -0.3) << label(kind, resolution);
            EXPECT_LT(box.max.x(), 1.2) << label(kind, resolution);
            EXPECT_GT(box.max.y() - box.min.y(), 0.25) << label(kind, resolution);
            EXPECT_LT(box.max.y() - box.min.y(), 1.6) << label(kind, resolution);
            EXPECT_GT(box.max.z() - box.min.z(), 0.25) << label(kind, resolution);
            EXPECT_LT(box.max.z() - box.min.z(), 1.6) << label(kind, resolution);
        }
    }
}

TEST(BuiltinLibrary, VertebraBodySpansTheCubeLength) {
    for (BoneResolution resolution : kResolutions) {
        const Aabb box = BoneLibrary::builtin(resolution)
                             .model(BoneModelKind::Vertebra, resolution)
                             .mesh.bounds();
        EXPECT_NEAR(box.min.x(), 0.0, 0.03) << boneResolutionName(resolution);
        EXPECT_NEAR(box.max.x(), 1.0, 0.03) << boneResolutionName(resolution);
    }
}

TEST(BuiltinLibrary, DoublePelvisListsItsTwoSocketsAfterTheEnd) {
    // The pelvis is one bone per side; the double one carries two hip sockets side by side
    // along its y axis (as bone_placement.cpp puts the two hip joints).
    const BoneModel& model = BoneLibrary::builtin(BoneResolution::Low)
                                 .model(BoneModelKind::PelvisDouble, BoneResolution::Low);
    ASSERT_EQ(model.childJoints.size(), 3u);
    EXPECT_EQ(model.childJoints[0], Vec3(1.0, 0.0, 0.0));
    EXPECT_LT(model.childJoints[1].y(), 0.0);
    EXPECT_GT(model.childJoints[2].y(), 0.0);
    const BoneModel& single =
        BoneLibrary::builtin(BoneResolution::Low).model(BoneModelKind::Pelvis, BoneResolution::Low);
    EXPECT_EQ(single.childJoints.size(), 1u);
}

TEST(BuiltinLibrary, BuildsAreDeterministic) {
    for (BoneResolution resolution : kResolutions) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            const BoneModel fresh = buildBoneModel(kind, resolution);
            const BoneModel& cached = BoneLibrary::builtin(resolution).model(kind, resolution);
            EXPECT_EQ(fresh.mesh.positions, cached.mesh.positions) << label(kind, resolution);
            EXPECT_EQ(fresh.mesh.normals, cached.mesh.normals) << label(kind, resolution);
            EXPECT_EQ(fresh.mesh.indices, cached.mesh.indices) << label(kind, resolution);
            EXPECT_EQ(fresh.childJoints, cached.childJoints) << label(kind, resolution);
        }
    }
}

TEST(BuiltinLibrary, BoxResolutionHasNoBuiltinLibrary) {
    EXPECT_THROW(BoneLibrary::builtin(BoneResolution::Box), Error);
}

TEST(BuiltinLibrary, BoxBudgetIsTwelveTriangles) {
    for (int k = 0; k < kBoneModelKindCount; ++k) {
        EXPECT_EQ(boneTriangleBudget(static_cast<BoneModelKind>(k), BoneResolution::Box), 12);
    }
}

TEST(BuiltinLibrary, HighBudgetExceedsLowBudget) {
    for (int k = 0; k < kBoneModelKindCount; ++k) {
        const auto kind = static_cast<BoneModelKind>(k);
        EXPECT_GE(boneTriangleBudget(kind, BoneResolution::High),
                  4 * boneTriangleBudget(kind, BoneResolution::Low));
    }
}

}  // namespace
}  // namespace ramus
