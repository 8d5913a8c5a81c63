// Geometry of the tube mesh: normals, winding, rotation-minimizing frames, bark UVs and glTF
// tangent frames.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ramus/rng.hpp"
#include "ramus/tube_mesher.hpp"
#include "tube_test_util.hpp"

namespace ramus {
namespace {

using test::chainTree;
using test::fixedSegments;

std::vector<Vec3> helix(int nodes, double turnDegrees, double rise) {
    std::vector<Vec3> points;
    for (int i = 0; i < nodes; ++i) {
        const double a = degToRad(turnDegrees * i);
        points.emplace_back(3.0 * std::cos(a), rise * i, 3.0 * std::sin(a));
    }
    return points;
}

// A bushy random tree with some hidden edges and a few coincident nodes.
BranchTree randomTree(std::uint64_t seed, int nodes) {
    BranchTree tree;
    Rng rng(seed);
    tree.addRoot(Vec3::Zero());
    for (int i = 1; i < nodes; ++i) {
        const auto parent = static_cast<NodeId>(
            rng.uniform01() < 0.75 ? i - 1 : rng.uniformInt(static_cast<std::uint32_t>(i)));
        const double step = rng.uniform01() < 0.02 ? 0.0 : rng.uniform(0.2, 1.0);
        const Vec3 dir = Vec3(rng.gauss(0, 0.5), 1.0, rng.gauss(0, 0.5)).normalized();
        const NodeId id = tree.addChild(parent, tree.node(parent).position + step * dir);
        tree.node(id).hidden = rng.uniform01() < 0.03;
    }
    return tree;
}

// Unit normals, unit tangents perpendicular to them with w = ±1, finite UVs, indices in range.
void expectValidAttributes(const Mesh& mesh) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.tangents.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.vertexCount());
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        ASSERT_TRUE(mesh.positions[i].allFinite());
        ASSERT_TRUE(mesh.uvs[i].allFinite());
        const Vec3f& n = mesh.normals[i];
        const Vec3f t = mesh.tangents[i].head<3>();
        EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
        EXPECT_NEAR(t.norm(), 1.0f, 1e-5f);
        EXPECT_NEAR(n.dot(t), 0.0f, 1e-5f);
        EXPECT_EQ(std::abs(mesh.tangents[i].w()), 1.0f);
    }
}

// Per triangle: face normal agrees with its vertex normals (counter-clockwise from outside);
// the tangent points to increasing u and the glTF bitangent cross(n, t) · w to decreasing v
// (UV origin at the image's top-left, normal maps +Y up).
void expectWindingAndTangentFrames(const Mesh& mesh) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t i0 = mesh.indices[3 * t];
        const std::uint32_t i1 = mesh.indices[3 * t + 1];
        const std::uint32_t i2 = mesh.indices[3 * t + 2];
        const Vec3 p0 = mesh.positions[i0].cast<double>();
        const Vec3 e1 = mesh.positions[i1].cast<double>() - p0;
        const Vec3 e2 = mesh.positions[i2].cast<double>() - p0;
        const Vec3 face = e1.cross(e2);
        ASSERT_GT(face.norm(), 0.0) << "degenerate triangle " << t;
        const Vec3 n = (mesh.normals[i0] + mesh.normals[i1] + mesh.normals[i2]).cast<double>();
        EXPECT_GT(face.normalized().dot(n.normalized()), 0.0) << "triangle " << t;

        const Vec2 uv0 = mesh.uvs[i0].cast<double>();
        const Vec2 d1 = mesh.uvs[i1].cast<double>() - uv0;
        const Vec2 d2 = mesh.uvs[i2].cast<double>() - uv0;
        const double det = d1.x() * d2.y() - d2.x() * d1.y();
        ASSERT_GT(std::abs(det), 0.0) << "triangle " << t << " has no UV area";
        const Vec3 dPdu = (d2.y() * e1 - d1.y() * e2) / det;
        const Vec3 dPdv = (d1.x() * e2 - d2.x() * e1) / det;
        for (std::uint32_t i : {i0, i1, i2}) {
            const Vec3 tangent = mesh.tangents[i].head<3>().cast<double>();
            const Vec3 bitangent =
                mesh.normals[i].cast<double>().cross(tangent) * mesh.tangents[i].w();
            EXPECT_GT(tangent.dot(dPdu), 0.0) << "triangle " << t;
            EXPECT_LT(bitangent.dot(dPdv), 0.0) << "triangle " << t;
        }
    }
}

TEST(TubeGeometry, RandomTreeHasValidAttributesWindingAndTangentFrames) {
    const BranchTree tree = randomTree(3, 3000);
    TubeMeshParams params;
    params.curveReduction = 0.995;
    const Mesh mesh = buildTubeMesh(tree, params);
    ASSERT_GT(mesh.triangleCount(), 0u);
    expectValidAttributes(mesh);
    expectWindingAndTangentFrames(mesh);
}

TEST(TubeGeometry, NormalsAreRadialAndPointAwayFromTheRingCentre) {
    const std::vector<Vec3> points = helix(40, 12.0, 0.4);
    TubeMeshParams params = fixedSegments(8, false);
    params.leafRadius = 0.05;
    const Mesh mesh = buildTubeMesh(chainTree(points), params);
    ASSERT_EQ(mesh.vertexCount(), points.size() * 9);
    for (std::size_t k = 0; k < points.size(); ++k) {
        for (std::size_t i = 0; i < 9; ++i) {
            const std::size_t v = 9 * k + i;
            const Vec3 offset = mesh.positions[v].cast<double>() - points[k];
            EXPECT_NEAR(offset.norm(), 0.05, 1e-5);
            EXPECT_NEAR(offset.normalized().dot(mesh.normals[v].cast<double>()), 1.0, 1e-5);
        }
    }
}

TEST(TubeGeometry, RingsOnAHelixDoNotTwist) {
    const std::vector<Vec3> points = helix(120, 9.0, 0.3);
    const Mesh mesh = buildTubeMesh(chainTree(points), fixedSegments(6, false));
    ASSERT_EQ(mesh.vertexCount(), points.size() * 7);
    // Ring plane normal k = the cross product of two radial normals of that ring.
    auto ringAxis = [&](std::size_t k) {
        return mesh.normals[7 * k]
            .cast<double>()
            .cross(mesh.normals[7 * k + 2].cast<double>())
            .normalized();
    };
    // A rotation-minimizing frame turns the reference by no more than the axis turns.
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        const double axisTurn = std::acos(std::clamp(ringAxis(k).dot(ringAxis(k + 1)), -1.0, 1.0));
        const double refTurn = std::acos(std::clamp(
            mesh.normals[7 * k].cast<double>().dot(mesh.normals[7 * (k + 1)].cast<double>()), -1.0,
            1.0));
        EXPECT_LE(refTurn, axisTurn + 1e-3) << "ring " << k;
    }
}

TEST(TubeGeometry, BarkVRunsOnAlongAChainAndKeepsTexelsSquare) {
    const std::vector<Vec3> points{Vec3::Zero(), Vec3(0, 1, 0), Vec3(0, 3, 0), Vec3(1, 4, 0)};
    TubeMeshParams params = fixedSegments(5, false);
    params.radiusMode = RadiusMode::Widths;
    params.uvAspect = 2.0;
    BranchTree tree = chainTree(points);
    const double radii[] = {0.4, 0.3, 0.2, 0.1};
    for (NodeId i = 0; i < 4; ++i) tree.node(i).radius = radii[i];
    const Mesh mesh = buildTubeMesh(tree, params);
    ASSERT_EQ(mesh.vertexCount(), 4u * 6u);
    double expected = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
        if (k > 0) {
            const double length = (points[k] - points[k - 1]).norm();
            expected -= length / (2.0 * kPi * (radii[k - 1] + radii[k]));
        }
        for (std::size_t i = 0; i < 6; ++i) {
            const Vec2f uv = mesh.uvs[6 * k + i];
            EXPECT_NEAR(uv.y(), expected, 1e-6) << "ring " << k;
            EXPECT_NEAR(uv.x(), static_cast<float>(i) / 5.0f, 1e-6f);
        }
    }
}

TEST(TubeGeometry, CappedChainsHaveValidCapFrames) {
    std::vector<Vec3> points = helix(10, 20.0, 0.5);
    const Mesh mesh = buildTubeMesh(chainTree(points), fixedSegments(7, true));
    expectValidAttributes(mesh);
    expectWindingAndTangentFrames(mesh);
    for (const Vec2f& uv : mesh.uvs) {
        EXPECT_GE(uv.x(), 0.0f);
        EXPECT_LE(uv.x(), 1.0f);
    }
}

}  // namespace
}  // namespace ramus
