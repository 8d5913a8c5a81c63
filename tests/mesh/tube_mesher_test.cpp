// Structure of the tube mesh: rings per chain, chains at branchings and hidden edges, radii,
// segment counts, curve reduction, caps, empty input, determinism.
#include "ramus/tube_mesher.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "ramus/export.hpp"
#include "ramus/rng.hpp"
#include "ramus/scene.hpp"
#include "tube_test_util.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

using test::chainTree;

// Writes `mesh` as GLB into $RAMUS_TEST_OUTPUT (for the glTF validator) when it is set.
void writeForValidator(const Mesh& mesh, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir == nullptr || *dir == '\0' || mesh.positions.empty()) return;
    writeGlb(makeSingleMeshScene(mesh), std::string(dir) + "/tube_mesher_" + name + ".glb");
}

// Exactly `n` ring segments, tips open unless `caps`, and a leaf radius of 0.1.
TubeMeshParams thinTipSegments(int n, bool caps = false) {
    TubeMeshParams params = test::fixedSegments(n, caps);
    params.leafRadius = 0.1;
    return params;
}

// Centre of the ring of n (+1 seam) vertices starting at `first`.
Vec3 ringCentre(const Mesh& mesh, std::size_t first, int n) {
    Vec3 sum = Vec3::Zero();
    for (int i = 0; i < n; ++i) sum += mesh.positions[first + i].cast<double>();
    return sum / n;
}

TEST(TubeMesh, SingleEdgeGivesTwoRingsAndTwoTrianglesPerSegment) {
    const BranchTree tree = chainTree({Vec3(0, 0, 0), Vec3(0, 2, 0)});
    const Mesh mesh = buildTubeMesh(tree, thinTipSegments(6));
    ASSERT_EQ(mesh.vertexCount(), 2u * 7u);
    EXPECT_EQ(mesh.triangleCount(), 12u);
    EXPECT_NEAR((ringCentre(mesh, 0, 6) - Vec3(0, 0, 0)).norm(), 0.0, 1e-6);
    EXPECT_NEAR((ringCentre(mesh, 7, 6) - Vec3(0, 2, 0)).norm(), 0.0, 1e-6);
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        const Vec3 p = mesh.positions[i].cast<double>();
        EXPECT_NEAR(std::hypot(p.x(), p.z()), 0.1, 1e-6);  // Murray: both ends are r_0
        EXPECT_NEAR(p.y(), i < 7 ? 0.0 : 2.0, 1e-6);
    }
    // The seam vertex repeats the first one exactly, with u = 1 instead of 0.
    EXPECT_EQ(mesh.positions[6], mesh.positions[0]);
    EXPECT_EQ(mesh.uvs[0].x(), 0.0f);
    EXPECT_EQ(mesh.uvs[6].x(), 1.0f);
}

TEST(TubeMesh, StraightChainOfEqualBranchDepthSharesRings) {
    std::vector<Vec3> points;
    for (int i = 0; i <= 5; ++i) points.emplace_back(0, i, 0);
    const Mesh mesh = buildTubeMesh(chainTree(points), thinTipSegments(5));
    EXPECT_EQ(mesh.vertexCount(), 6u * 6u);     // k + 1 rings for k edges
    EXPECT_EQ(mesh.triangleCount(), 5u * 10u);  // 2n per edge
}

TEST(TubeMesh, BranchingNodeStartsANewChainInsideTheParentTube) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    const NodeId a = tree.addChild(root, Vec3(0, 1, 0));
    tree.addChild(a, Vec3(0, 2, 0));                   // first child: same branch depth
    const NodeId c = tree.addChild(a, Vec3(1, 2, 0));  // second child: new chain
    ASSERT_NE(tree.node(c).branchDepth, tree.node(a).branchDepth);
    const Mesh mesh = buildTubeMesh(tree, thinTipSegments(4));
    ASSERT_EQ(mesh.vertexCount(), (3u + 2u) * 5u);
    EXPECT_EQ(mesh.triangleCount(), 3u * 8u);
    // The side chain's first ring sits at a with the side branch's own (smaller) radius.
    const Vec3 centre = ringCentre(mesh, 15, 4);
    EXPECT_NEAR((centre - tree.node(a).position).norm(), 0.0, 1e-6);
    const std::vector<double> radii = computeEdgeRadii(tree, thinTipSegments(4));
    EXPECT_NEAR((mesh.positions[15].cast<double>() - centre).norm(), radii[c], 1e-6);
    EXPECT_LT(radii[c], radii[a]);
}

TEST(TubeMesh, HiddenEdgesAreNotMeshedAndTheirChildrenStartNewChains) {
    BranchTree tree;
    NodeId node = tree.addRoot(Vec3::Zero());
    node = tree.addChild(node, Vec3(0, 1, 0));
    node = tree.addChild(node, Vec3(0, 3, 0));  // gap from y = 1 to y = 3
    tree.node(node).hidden = true;
    tree.addChild(node, Vec3(0, 4, 0));
    const Mesh mesh = buildTubeMesh(tree, thinTipSegments(4));
    EXPECT_EQ(mesh.vertexCount(), 4u * 5u);  // two chains of two rings each
    EXPECT_EQ(mesh.triangleCount(), 2u * 8u);
    for (const Vec3f& p : mesh.positions) {
        EXPECT_TRUE(p.y() < 1.001f || p.y() > 2.999f) << "vertex inside the hidden gap: " << p.y();
    }
}

TEST(TubeMesh, EmptyTreeAndRootOnlyTreeGiveEmptyMeshes) {
    const Mesh empty = buildTubeMesh(BranchTree{});
    EXPECT_TRUE(empty.positions.empty());
    EXPECT_TRUE(empty.indices.empty());
    EXPECT_TRUE(empty.primitives.empty());
    BranchTree rootOnly;
    rootOnly.addRoot(Vec3(1, 2, 3));
    const Mesh single = buildTubeMesh(rootOnly);
    EXPECT_TRUE(single.positions.empty());
    EXPECT_TRUE(single.indices.empty());
    EXPECT_EQ(single.name, "tree");
}

TEST(TubeMesh, OnlyHiddenEdgesGiveAnEmptyMesh) {
    BranchTree tree;
    const NodeId a = tree.addChild(tree.addRoot(Vec3::Zero()), Vec3(0, 1, 0));
    tree.node(a).hidden = true;
    EXPECT_TRUE(buildTubeMesh(tree).positions.empty());
}

TEST(TubeMesh, OutputHasOneBarkPrimitiveWithTheGivenMaterial) {
    TubeMeshParams params = thinTipSegments(5, true);
    params.material.name = "oak_bark";
    const Mesh mesh = buildTubeMesh(chainTree({Vec3::Zero(), Vec3(0, 1, 0)}), params);
    EXPECT_EQ(mesh.name, "tree");
    ASSERT_EQ(mesh.primitives.size(), 1u);
    EXPECT_EQ(mesh.primitives[0].name, "bark");
    EXPECT_EQ(mesh.primitives[0].firstIndex, 0u);
    EXPECT_EQ(mesh.primitives[0].indexCount, mesh.indices.size());
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].name, "oak_bark");
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_EQ(mesh.tangents.size(), mesh.positions.size());
    EXPECT_EQ(mesh.uvs.size(), mesh.positions.size());
}

TEST(TubeMesh, SegmentCountGrowsLinearlyWithRadius) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero(), 1.0);
    const NodeId a = tree.addChild(root, Vec3(0, 1, 0), 1.0);
    tree.addChild(a, Vec3(0, 2, 0), 1.0);
    tree.addChild(a, Vec3(1, 2, 0), 0.25);
    TubeMeshParams params;
    params.minSegments = 4;
    params.maxSegments = 16;
    params.capTips = false;
    const Mesh mesh = buildTubeMesh(tree, params);
    // Trunk chain: 3 rings of 16 (+1); side chain: 4 + round(12 · 0.25) = 7 segments, 2 rings.
    EXPECT_EQ(mesh.vertexCount(), 3u * 17u + 2u * 8u);
    EXPECT_EQ(mesh.triangleCount(), 2u * 32u + 14u);
}

TEST(TubeMesh, TrunkMultiplierWidensOnlyTheRootRing) {
    TubeMeshParams params = thinTipSegments(8);
    params.trunkMultiplier = 3.0;
    const Mesh mesh =
        buildTubeMesh(chainTree({Vec3::Zero(), Vec3(0, 1, 0), Vec3(0, 2, 0)}), params);
    EXPECT_NEAR(mesh.positions[0].cast<double>().norm(), 0.3, 1e-6);
    EXPECT_NEAR(std::hypot(mesh.positions[9].x(), mesh.positions[9].z()), 0.1, 1e-6);
}

TEST(TubeMesh, StartRotationTurnsTheFirstRingVertex) {
    const BranchTree tree = chainTree({Vec3::Zero(), Vec3(0, 1, 0)});
    // Heading +y: reference axis x (least aligned), e2 = y × x = -z.
    const Mesh plain = buildTubeMesh(tree, thinTipSegments(4));
    EXPECT_NEAR((plain.positions[0].cast<double>() - Vec3(0.1, 0, 0)).norm(), 0.0, 1e-6);
    TubeMeshParams turned = thinTipSegments(4);
    turned.startRotationDegrees = 90.0;
    const Mesh mesh = buildTubeMesh(tree, turned);
    EXPECT_NEAR((mesh.positions[0].cast<double>() - Vec3(0, 0, -0.1)).norm(), 0.0, 1e-6);
}

TEST(TubeRadii, MurrayRadiiNeverIncreaseFromRootToTips) {
    BranchTree tree;
    Rng rng(7);
    tree.addRoot(Vec3::Zero());
    for (int i = 1; i < 500; ++i) {
        const auto parent = static_cast<NodeId>(rng.uniformInt(static_cast<std::uint32_t>(i)));
        tree.addChild(parent, tree.node(parent).position + Vec3(rng.uniform(-1, 1), 1, 0));
    }
    TubeMeshParams params;
    params.radiusMode = RadiusMode::Murray;
    const std::vector<double> radii = computeEdgeRadii(tree, params);
    ASSERT_EQ(radii.size(), tree.size());
    for (std::size_t i = 1; i < tree.size(); ++i) {
        EXPECT_LE(radii[i], radii[static_cast<std::size_t>(tree.nodes()[i].parent)] + 1e-12);
        EXPECT_GT(radii[i], 0.0);
    }
}

TEST(TubeRadii, AutomaticLeafRadiusIsFourPercentOfTheMeanEdgeLength) {
    const BranchTree tree = chainTree({Vec3::Zero(), Vec3(0, 1, 0), Vec3(0, 4, 0)});
    const std::vector<double> radii = computeEdgeRadii(tree, TubeMeshParams{});
    EXPECT_NEAR(radii[2], 0.04 * 2.0, 1e-12);  // mean of 1 and 3
    EXPECT_NEAR(radii[0], 0.08, 1e-12);        // one child all the way down
}

TEST(TubeRadii, WidthsAreInheritedByNodesWithoutOne) {
    BranchTree tree;
    const NodeId root = tree.addRoot(Vec3::Zero());
    const NodeId a = tree.addChild(root, Vec3(0, 1, 0), 0.5);
    const NodeId b = tree.addChild(a, Vec3(0, 2, 0));
    const NodeId c = tree.addChild(b, Vec3(0, 3, 0), 0.2);
    TubeMeshParams params;
    params.radiusMode = RadiusMode::Widths;
    const std::vector<double> radii = computeEdgeRadii(tree, params);
    EXPECT_DOUBLE_EQ(radii[root], 0.5);  // unset root: its first edge's radius
    EXPECT_DOUBLE_EQ(radii[a], 0.5);
    EXPECT_DOUBLE_EQ(radii[b], 0.5);
    EXPECT_DOUBLE_EQ(radii[c], 0.2);
    params.radiusMode = RadiusMode::Auto;
    EXPECT_EQ(computeEdgeRadii(tree, params), radii);
}

TEST(TubeRadii, WidthsModeFallsBackToMurrayWithoutAnyWidth) {
    const BranchTree tree = chainTree({Vec3::Zero(), Vec3(0, 1, 0)});
    TubeMeshParams widths;
    widths.radiusMode = RadiusMode::Widths;
    widths.leafRadius = 0.3;
    TubeMeshParams murray = widths;
    murray.radiusMode = RadiusMode::Murray;
    EXPECT_EQ(computeEdgeRadii(tree, widths), computeEdgeRadii(tree, murray));
    EXPECT_DOUBLE_EQ(computeEdgeRadii(tree, widths)[1], 0.3);
}

TEST(TubeMesh, CurveReductionDropsRingsOfANearlyStraightChain) {
    std::vector<Vec3> points;
    for (int i = 0; i <= 10; ++i) points.emplace_back(0.005 * (i % 2), i, 0);  // ±0.3° zigzag
    TubeMeshParams params = thinTipSegments(4);
    params.curveReduction = 0.999;  // cos 2.6°
    EXPECT_EQ(buildTubeMesh(chainTree(points), params).vertexCount(), 2u * 5u);
    params.curveReduction = 0.0;
    EXPECT_EQ(buildTubeMesh(chainTree(points), params).vertexCount(), 11u * 5u);
}

TEST(TubeMesh, CurveReductionKeepsRingsOfABentChain) {
    std::vector<Vec3> points{Vec3::Zero()};
    for (int i = 1; i <= 10; ++i) {  // 30° turn at every node
        const double angle = degToRad(30.0 * i);
        points.push_back(points.back() + Vec3(std::sin(angle), std::cos(angle), 0));
    }
    TubeMeshParams params = thinTipSegments(4);
    params.curveReduction = 0.999;
    EXPECT_EQ(buildTubeMesh(chainTree(points), params).vertexCount(), 11u * 5u);
}

TEST(TubeMesh, CurveReductionMeasuresFromTheLastKeptRingSoSlowArcsKeepSomeRings) {
    std::vector<Vec3> points{Vec3::Zero()};
    for (int i = 1; i <= 90; ++i) {  // quarter circle in 1° steps
        const double angle = degToRad(1.0 * i);
        points.push_back(points.back() + Vec3(std::sin(angle), std::cos(angle), 0));
    }
    TubeMeshParams params = thinTipSegments(4);
    params.curveReduction = std::cos(degToRad(5.0));
    const std::size_t rings = buildTubeMesh(chainTree(points), params).vertexCount() / 5;
    EXPECT_GT(rings, 10u);  // at most ~5° of turn between kept rings
    EXPECT_LT(rings, 40u);
}

TEST(TubeMesh, CoincidentNodesAreMergedWithoutDegenerateTriangles) {
    const BranchTree tree =
        chainTree({Vec3::Zero(), Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(0, 2, 0), Vec3(0, 2, 0)});
    const Mesh mesh = buildTubeMesh(tree, thinTipSegments(4, true));
    EXPECT_EQ(mesh.vertexCount(), 3u * 5u + 2u * 5u);  // 3 rings + 2 caps of 4 + centre
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3f a = mesh.positions[mesh.indices[3 * t]];
        const Vec3f b = mesh.positions[mesh.indices[3 * t + 1]];
        const Vec3f c = mesh.positions[mesh.indices[3 * t + 2]];
        EXPECT_GT((b - a).cross(c - a).norm(), 1e-6f);
    }
}

// Every directed edge of the position-welded mesh occurs exactly once and so does its
// reverse: a closed, consistently oriented 2-manifold.
void expectClosedManifold(const Mesh& mesh) {
    std::map<std::tuple<float, float, float>, std::uint32_t> weld;
    std::vector<std::uint32_t> id(mesh.vertexCount());
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        const Vec3f& p = mesh.positions[i];
        id[i] = weld.emplace(std::make_tuple(p.x(), p.y(), p.z()), weld.size()).first->second;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) {
            ++edges[{id[mesh.indices[3 * t + k]], id[mesh.indices[3 * t + (k + 1) % 3]]}];
        }
    }
    for (const auto& [edge, count] : edges) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
        const auto reverse = edges.find({edge.second, edge.first});
        EXPECT_TRUE(reverse != edges.end() && reverse->second == 1)
            << "open edge " << edge.first << "-" << edge.second;
    }
}

TEST(TubeMesh, CapsCloseASingleEdge) {
    const Mesh mesh =
        buildTubeMesh(chainTree({Vec3(1, 0, 0), Vec3(1, 2, 1)}), thinTipSegments(7, true));
    EXPECT_EQ(mesh.triangleCount(), 14u + 2u * 7u);
    expectClosedManifold(mesh);
    writeForValidator(mesh, "single_edge_capped");
}

TEST(TubeMesh, CapsCloseABentChainAndTheirNormalsPointOutward) {
    std::vector<Vec3> points{Vec3::Zero()};
    for (int i = 1; i <= 6; ++i) points.push_back(points.back() + Vec3(0.3 * i, 1, 0.1 * i));
    const Mesh mesh = buildTubeMesh(chainTree(points), thinTipSegments(9, true));
    expectClosedManifold(mesh);
    // The last vertex is a tip-cap vertex: its normal points along the last edge.
    const Vec3 lastEdge = (points[6] - points[5]).normalized();
    EXPECT_GT(mesh.normals.back().cast<double>().dot(lastEdge), 0.99);
}

TEST(TubeMesh, WithoutCapsTipsStayOpen) {
    const Mesh mesh = buildTubeMesh(chainTree({Vec3::Zero(), Vec3(0, 1, 0)}), thinTipSegments(6));
    EXPECT_EQ(mesh.triangleCount(), 12u);
}

TEST(TubeMesh, IsDeterministic) {
    BranchTree tree;
    Rng rng(42);
    tree.addRoot(Vec3::Zero());
    for (int i = 1; i < 2000; ++i) {
        const auto parent = static_cast<NodeId>(
            rng.uniform01() < 0.8 ? i - 1 : rng.uniformInt(static_cast<std::uint32_t>(i)));
        tree.addChild(parent,
                      tree.node(parent).position + Vec3(rng.gauss(0, 0.3), 1, rng.gauss(0, 0.3)));
    }
    TubeMeshParams params;
    params.curveReduction = 0.99;
    const Mesh a = buildTubeMesh(tree, params);
    const Mesh b = buildTubeMesh(tree, params);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    ASSERT_EQ(a.indices, b.indices);
    EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * 12), 0);
    EXPECT_EQ(std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * 12), 0);
    EXPECT_EQ(std::memcmp(a.tangents.data(), b.tangents.data(), a.tangents.size() * 16), 0);
    EXPECT_EQ(std::memcmp(a.uvs.data(), b.uvs.data(), a.uvs.size() * 8), 0);
    writeForValidator(a, "random_2000_reduced");
}

// countTubeTriangles is what LOD planning asks instead of meshing: it must agree with the mesh
// exactly, whatever merges, reduces, caps or hides rings. Shipped L-systems (dense ones, zero-
// length edges, hidden edges of `f`) under several settings, and with every third edge hidden.
TEST(TubeMesh, CountedTrianglesAreTheMeshesTriangles) {
    std::vector<TubeMeshParams> settings(4);
    settings[1].minSegments = 3;
    settings[1].maxSegments = 24;
    settings[1].capTips = true;
    settings[2].curveReduction = 0.98;
    settings[2].capTips = true;
    settings[3].minSegments = settings[3].maxSegments = 5;
    settings[3].radiusMode = RadiusMode::Widths;
    settings[3].windAttributes = true;
    std::size_t compared = 0;
    for (const char* name : {"tree_3d", "abop_1_24c", "abop_2_6d", "koch_island", "monopodial"}) {
        BranchTree tree =
            test::growLSystem(RAMUS_SOURCE_DIR "/examples/lsystems/" + std::string(name) + ".lsys");
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1) {
                for (std::size_t i = 1; i < tree.size(); i += 3) {
                    tree.node(static_cast<NodeId>(i)).hidden = true;
                }
            }
            for (std::size_t k = 0; k < settings.size(); ++k) {
                SCOPED_TRACE(std::string(name) + " pass " + std::to_string(pass) + " settings " +
                             std::to_string(k));
                const std::size_t meshed = buildTubeMesh(tree, settings[k]).triangleCount();
                EXPECT_EQ(countTubeTriangles(tree, settings[k]), meshed);
                compared += meshed > 0;
            }
        }
    }
    EXPECT_EQ(compared, 5u * 2u * 4u);
    EXPECT_EQ(countTubeTriangles(BranchTree{}), 0u);
}

}  // namespace
}  // namespace ramus
