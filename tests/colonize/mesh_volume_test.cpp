// MeshVolume: the inside test against analytic shapes (box, rotated box, icosahedron, sphere),
// rays through vertices and edges, segment tests, closedness and the OBJ/GLB readers.
#include "ramus/mesh_volume.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh_volume_test_util.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/rng.hpp"
#include "ramus/scene.hpp"

namespace ramus::testing {
namespace {

std::string errorOf(auto&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// Signed distance-like value of the cube [-1, 1]³: |value| ≤ the distance to its surface.
double cubeValue(const Vec3& p) { return p.cwiseAbs().maxCoeff() - 1.0; }

TEST(MeshVolume, ABoxMeshContainsExactlyThePointsOfTheBox) {
    const MeshVolume cube = boxMesh(Vec3(-1, -1, -1), Vec3(1, 1, 1)).volume();
    Rng rng(3);
    int inside = 0, checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5));
        if (std::abs(cubeValue(p)) < 1e-6) continue;
        ASSERT_EQ(cube.contains(p), cubeValue(p) < 0.0) << p.transpose();
        inside += cubeValue(p) < 0.0;
        ++checked;
    }
    EXPECT_GT(inside, 5000);  // both answers occur
    EXPECT_GT(checked - inside, 5000);
}

TEST(MeshVolume, RaysThroughVerticesAndEdgesOfACubeCountOnce) {
    // Points whose ray along +z runs exactly through the cube's vertical edges, its face
    // diagonals (the split of the top and bottom faces runs through x = y) and its faces' edges.
    const MeshVolume cube = boxMesh(Vec3(-1, -1, -1), Vec3(1, 1, 1)).volume();
    const double coords[] = {-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5};
    const double heights[] = {-3.0, -1.5, -0.5, 0.0, 0.25, 0.999, 1.5, 3.0};
    int checked = 0;
    for (double x : coords) {
        for (double y : coords) {
            for (double z : heights) {
                const Vec3 p(x, y, z);
                if (std::abs(cubeValue(p)) < 1e-6) continue;  // on the surface
                EXPECT_EQ(cube.contains(p), cubeValue(p) < 0.0) << p.transpose();
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 300);
}

TEST(MeshVolume, ARotatedBoxMatchesTheAnalyticBox) {
    TriangleSoup box = boxMesh(Vec3(-2, -1, -0.5), Vec3(2, 1, 0.5));
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 shift(10, -4, 2);
    for (Vec3& v : box.vertices) v = rotation * v + shift;
    const MeshVolume volume = box.volume();
    Rng rng(11);
    int inside = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p = shift + Vec3(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3));
        const Vec3 local = rotation.transpose() * (p - shift);
        const double value = (local.cwiseAbs() - Vec3(2, 1, 0.5)).maxCoeff();
        if (std::abs(value) < 1e-6) continue;
        ASSERT_EQ(volume.contains(p), value < 0.0) << p.transpose();
        inside += value < 0.0;
    }
    EXPECT_GT(inside, 500);  // the box fills 8/216 of the cube sampled: ~740 points
}

TEST(MeshVolume, TheIcosahedronMatchesItsFacePlanesAlsoOnRaysThroughItsVertices) {
    const TriangleSoup ico = icosahedron();
    const MeshVolume volume = ico.volume();
    // Analytic: inside every face plane (outward normals, the mesh is convex).
    auto planeValue = [&](const Vec3& p, double& nearest) {
        double value = -1e300;
        nearest = 1e300;
        for (const auto& t : ico.triangles) {
            const Vec3 &a = ico.vertices[t[0]], &b = ico.vertices[t[1]], &c = ico.vertices[t[2]];
            Vec3 n = (b - a).cross(c - a).normalized();
            if (n.dot(a) < 0) n = -n;
            value = std::max(value, n.dot(p - a));
            nearest = std::min(nearest, std::abs(n.dot(p - a)));
        }
        return value;
    };
    // Rays along z through every vertex's (x, y), and random points.
    std::vector<Vec3> points;
    for (const Vec3& v : ico.vertices) {
        for (double z = -2.5; z <= 2.5; z += 0.125) points.emplace_back(v.x(), v.y(), z);
    }
    Rng rng(5);
    for (int i = 0; i < 20000; ++i) {
        points.emplace_back(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
    }
    int inside = 0, checked = 0;
    for (const Vec3& p : points) {
        double nearest = 0.0;
        const double value = planeValue(p, nearest);
        if (nearest < 1e-6 && value > -1e-6) continue;  // on (or next to) the surface
        ASSERT_EQ(volume.contains(p), value < 0.0) << p.transpose();
        inside += value < 0.0;
        ++checked;
    }
    EXPECT_GT(inside, 3000);
    EXPECT_GT(checked, 20000);
}

TEST(MeshVolume, AnIcosphereContainsTheInscribedBallAndNothingOutsideTheSphere) {
    const TriangleSoup sphere = icosphere(3);  // 1280 triangles
    const MeshVolume volume = sphere.volume();
    EXPECT_EQ(volume.triangleCount(), 1280u);
    double inradius = 1.0;  // nearest face plane to the centre
    for (const auto& t : sphere.triangles) {
        const Vec3& a = sphere.vertices[t[0]];
        const Vec3 n = (sphere.vertices[t[1]] - a).cross(sphere.vertices[t[2]] - a).normalized();
        inradius = std::min(inradius, std::abs(n.dot(a)));
    }
    EXPECT_GT(inradius, 0.98);
    Rng rng(8);
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2));
        const double r = p.norm();
        if (r < inradius - 1e-6) ASSERT_TRUE(volume.contains(p)) << p.transpose();
        if (r > 1.0 + 1e-6) ASSERT_FALSE(volume.contains(p)) << p.transpose();
    }
    // Rays exactly through the vertices (0, 0, ±1) of the first subdivision.
    EXPECT_TRUE(volume.contains(Vec3::Zero()));
    EXPECT_TRUE(volume.contains(Vec3(0, 0, -0.9)));
    EXPECT_FALSE(volume.contains(Vec3(0, 0, -1.1)));
}

TEST(MeshVolume, TheWindingOfTheTrianglesDoesNotMatter) {
    TriangleSoup cube = boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
    for (std::size_t i = 0; i < cube.triangles.size(); i += 2) {
        std::swap(cube.triangles[i][1], cube.triangles[i][2]);  // every other one flipped
    }
    const MeshVolume volume = cube.volume();
    EXPECT_TRUE(volume.contains(Vec3(0.5, 0.5, 0.5)));
    EXPECT_TRUE(volume.contains(Vec3(0.25, 0.75, 0.1)));
    EXPECT_FALSE(volume.contains(Vec3(0.5, 0.5, 1.5)));
    EXPECT_FALSE(volume.contains(Vec3(0.5, 0.5, -0.5)));
}

TEST(MeshVolume, AMeshWithAHoleIsNotClosedAndTheErrorCountsTheBoundaryEdges) {
    TriangleSoup cube = boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
    cube.triangles.pop_back();  // one missing triangle: its three edges are open
    EXPECT_NE(errorOf([&] { (void)cube.volume(); }).find("not closed: 3 boundary edges"),
              std::string::npos);
}

TEST(MeshVolume, NoTrianglesIsAnError) {
    EXPECT_NE(errorOf([] { MeshVolume({Vec3(0, 0, 0)}, {}); }).find("no triangles"),
              std::string::npos);
}

TEST(MeshVolume, AFlatClosedMeshEnclosesNoVolume) {
    // Two triangles back to back: every edge is used twice, but the mesh is flat along z.
    const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_NE(errorOf([&] {
                  MeshVolume(v, {{0, 1, 2}, {0, 2, 1}});
              }).find("flat along z"),
              std::string::npos);
}

TEST(MeshVolume, AnIndexOutOfRangeIsAnError) {
    const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_NE(errorOf([&] { MeshVolume(v, {{0, 1, 3}}); }).find("out of range"), std::string::npos);
}

TEST(MeshVolume, DuplicateVerticesAreMergedBeforeTheClosednessCheck) {
    // Every triangle with its own three vertices (as in a GLB with flat normals).
    const TriangleSoup cube = boxMesh(Vec3(0, 0, 0), Vec3(2, 2, 2));
    TriangleSoup split;
    for (const auto& t : cube.triangles) {
        const auto base = static_cast<std::uint32_t>(split.vertices.size());
        for (const std::uint32_t i : t) split.vertices.push_back(cube.vertices[i]);
        split.triangles.push_back({base, base + 1, base + 2});
    }
    const MeshVolume volume = split.volume();
    EXPECT_EQ(volume.vertexCount(), 8u);
    EXPECT_TRUE(volume.contains(Vec3(1, 1, 1)));
}

TEST(MeshVolume, SegmentsHitTheSurfaceOrTheInsideOnly) {
    const MeshVolume cube = boxMesh(Vec3(-1, -1, -1), Vec3(1, 1, 1)).volume();
    EXPECT_TRUE(cube.segmentHits(Vec3(-2, 0.3, 0.2), Vec3(2, 0.3, 0.2)));      // through
    EXPECT_FALSE(cube.segmentHits(Vec3(-2, 0.3, 0.2), Vec3(-1.1, 0.3, 0.2)));  // stops short
    EXPECT_TRUE(cube.segmentHits(Vec3(-0.5, 0, 0), Vec3(0.5, 0.1, 0)));        // inside
    EXPECT_TRUE(cube.segmentHits(Vec3(-2, 0, 0), Vec3(0, 0, 0)));              // enters
    EXPECT_FALSE(cube.segmentHits(Vec3(-2, 1.5, 0), Vec3(2, 1.5, 0)));         // passes by
    // Exactly through the middle of a face's diagonal edge, and exactly through a corner.
    EXPECT_TRUE(cube.segmentHits(Vec3(0.2, 0.2, 2), Vec3(0.2, 0.2, -2)));
    EXPECT_TRUE(cube.segmentHits(Vec3(2, 2, 2), Vec3(0, 0, 0)));
    EXPECT_TRUE(cube.segmentHits(Vec3(2, 2, 2), Vec3(1, 1, 1)));  // ends on the corner
    // Diagonally past a corner without touching it.
    EXPECT_FALSE(cube.segmentHits(Vec3(1.5, 0.9, 0), Vec3(0.9, 1.5, 0)));
}

TEST(MeshVolume, SegmentTestsAgreeWithTheInsideTestAlongTheSegment) {
    // A segment whose ends differ in the inside test crosses the surface; a segment that
    // misses the volume has every point outside; one with an end inside hits.
    const MeshVolume sphere = icosphere(2).volume();
    Rng rng(17);
    int hits = 0, misses = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 a(rng.uniform(-1.3, 1.3), rng.uniform(-1.3, 1.3), rng.uniform(-1.3, 1.3));
        const Vec3 b = a + 0.4 * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        const bool hit = sphere.segmentHits(a, b);
        if (sphere.contains(a) || sphere.contains(b)) ASSERT_TRUE(hit);
        if (!hit) {
            for (int k = 0; k <= 64; ++k) ASSERT_FALSE(sphere.contains(a + (k / 64.0) * (b - a)));
        }
        hits += hit, misses += !hit;
    }
    EXPECT_GT(hits, 500);
    EXPECT_GT(misses, 500);
}

TEST(MeshVolume, AnObjCubeWithQuadsNegativeIndicesAndTextureReferencesReads) {
    const std::string obj =
        "# a cube\no cube\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\n"
        "v 1 1 1\nvt 0 0\nvn 0 0 1\ns off\n"
        "f 1/1 3/1 4/1 2/1\nf 5//1 6//1 8//1 7//1\nf 1/1/1 2/1/1 6/1/1 5/1/1\n"
        "f -6 -2 -1 -5\nf -8 -4 -2 -6\nf 2 4 8 6\n";
    const MeshVolume volume = parseObjVolume(obj, "cube.obj");
    EXPECT_EQ(volume.triangleCount(), 12u);
    EXPECT_EQ(volume.vertexCount(), 8u);
    EXPECT_TRUE(volume.contains(Vec3(0.5, 0.5, 0.5)));
    EXPECT_FALSE(volume.contains(Vec3(0.5, 0.5, 1.5)));
}

TEST(MeshVolume, AnObjIndexBeyondTheVerticesNamesFileLineAndColumn) {
    EXPECT_EQ(errorOf([] { parseObjVolume("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "a.obj"); }),
              "a.obj:3:7: vertex index 3 refers to no vertex (2 defined above)");
}

TEST(MeshVolume, AnObjCoordinateThatIsNoNumberIsNamed) {
    EXPECT_EQ(errorOf([] { parseObjVolume("v 0 zero 0\n", "a.obj"); }),
              "a.obj:1:5: invalid coordinate 'zero'; expected a finite number");
}

TEST(MeshVolume, AnObjIndexZeroIsAnError) {
    EXPECT_NE(errorOf([] {
                  parseObjVolume("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "a.obj");
              }).find("a.obj:4:3: invalid vertex reference '0'"),
              std::string::npos);
}

TEST(MeshVolume, AnOpenObjNamesTheFileAndTheBoundaryEdges) {
    EXPECT_EQ(errorOf([] { parseObjVolume("v 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n", "a.obj"); }),
              "a.obj: the mesh is not closed: 3 boundary edges (used by an odd number of "
              "triangles); expected a closed surface that encloses a volume");
}

TEST(MeshVolume, AnObjWithoutFacesHasNoTriangles) {
    EXPECT_NE(errorOf([] { parseObjVolume("v 0 0 0\n", "a.obj"); }).find("a.obj: the mesh has no"),
              std::string::npos);
}

TEST(MeshVolume, AMissingFileAndAnUnknownExtensionAreNamed) {
    EXPECT_NE(errorOf([] {
                  readMeshVolume("/nonexistent/crown.obj");
              }).find("/nonexistent/crown.obj: cannot read file"),
              std::string::npos);
    EXPECT_NE(errorOf([] { readMeshVolume("crown.stl"); }).find("unknown mesh file extension"),
              std::string::npos);
}

TEST(MeshVolume, AGlbIsReadWithItsNodeTransform) {
    const TriangleSoup sphere = icosphere(2);
    Mesh mesh;
    for (const Vec3& v : sphere.vertices) mesh.positions.push_back(v.cast<float>());
    for (const auto& t : sphere.triangles)
        mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
    Scene scene = makeSingleMeshScene(mesh, "crown");
    scene.nodes[0].translation = Vec3(0, 5, 0);
    const auto dir = std::filesystem::temp_directory_path() / "ramus_mesh_volume_test";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "crown.glb").string();
    writeGlb(scene, path);
    const MeshVolume volume = readMeshVolume(path);
    EXPECT_EQ(volume.triangleCount(), sphere.triangles.size());
    EXPECT_TRUE(volume.contains(Vec3(0, 5, 0)));
    EXPECT_TRUE(volume.contains(Vec3(0.5, 5.5, 0)));
    EXPECT_FALSE(volume.contains(Vec3(0, 0, 0)));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ramus::testing

namespace ramus::testing {
namespace {

// Mesh files used as envelopes: non-finite coordinates are errors located at the value, and
// files above the size limit are refused before they are parsed.
TEST(MeshVolumeInput, ObjNanAndInfinityAreLocatedAtTheValue) {
    EXPECT_EQ(errorOf([] { parseObjVolume("v 0 0 0\nv 1 nan 0\n", "a.obj"); }),
              "a.obj:2:5: invalid coordinate 'nan'; expected a finite number");
    EXPECT_EQ(errorOf([] { parseObjVolume("v 0 0 -inf\n", "a.obj"); }),
              "a.obj:1:7: invalid coordinate '-inf'; expected a finite number");
    EXPECT_EQ(errorOf([] { parseObjVolume("v 1e999 0 0\n", "a.obj"); }),
              "a.obj:1:3: invalid coordinate '1e999'; expected a finite number");
}

TEST(MeshVolumeInput, AMeshFileLargerThanTheLimitIsRefused) {
    const auto path = std::filesystem::temp_directory_path() / "ramus_mesh_limit.obj";
    writeFileAtomic(path.string(), "v 0 0 0\n");  // 8 bytes
    EXPECT_NE(errorOf([&] {
                  readMeshVolume(path.string(), 7);
              }).find(path.string() + ": the file is larger than the input limit of 7 bytes"),
              std::string::npos);
}

}  // namespace
}  // namespace ramus::testing
