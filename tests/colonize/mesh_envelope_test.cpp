// Mesh envelopes and obstacles: rejection sampling is uniform, inside and deterministic; mesh
// obstacles block growth; "mesh" shapes in config files and their errors.
#include <gtest/gtest.h>

#include <filesystem>

#include "colonize_test_util.hpp"
#include "mesh_volume_test_util.hpp"
#include "ramus/colonize.hpp"
#include "ramus/envelope.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/mesh_volume.hpp"

namespace ramus::testing {
namespace {

Shape meshShape(const TriangleSoup& soup, const Vec3& offset = Vec3::Zero(), double scale = 1) {
    Shape s;
    s.kind = ShapeKind::Mesh;
    s.offset = offset;
    s.scale = scale;
    s.mesh = std::make_shared<const MeshVolume>(soup.volume());
    return s;
}

// Two separate boxes in one mesh: [0, 1]³ (volume 1) and [2, 5] × [0, 1]² (volume 3).
TriangleSoup twoBoxes() {
    TriangleSoup a = boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
    const TriangleSoup b = boxMesh(Vec3(2, 0, 0), Vec3(5, 1, 1));
    const auto base = static_cast<std::uint32_t>(a.vertices.size());
    a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (const auto& t : b.triangles)
        a.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    return a;
}

TEST(MeshEnvelope, SamplesLieInsideTheScaledAndOffsetMesh) {
    Envelope e;
    e.shape = meshShape(boxMesh(Vec3(0, 0, 0), Vec3(2, 1, 1)), Vec3(10, 0, 0), 3.0);
    e.pointCount = 5000;
    const std::vector<Vec3> points = sampleEnvelope(e, 4);
    ASSERT_EQ(points.size(), 5000u);
    for (const Vec3& p : points) {
        ASSERT_TRUE(p.x() >= 10 && p.x() <= 16 && p.y() >= 0 && p.y() <= 3 && p.z() >= 0 &&
                    p.z() <= 3)
            << p.transpose();
        ASSERT_TRUE(shapeContains(e.shape, p));
    }
    const Aabb box = shapeBounds(e.shape);
    EXPECT_EQ(box.min, Vec3(10, 0, 0));
    EXPECT_EQ(box.max, Vec3(16, 3, 3));
}

TEST(MeshEnvelope, SamplesAreUniformInTheVolume) {
    // Half of a box mesh holds half of the points; of two boxes with volumes 1 and 3, the
    // small one holds a quarter. 20 000 points: standard deviations 0.0035 and 0.0031.
    Envelope e;
    e.shape = meshShape(boxMesh(Vec3(0, 0, 0), Vec3(2, 1, 1)));
    e.pointCount = 20000;
    std::size_t lowerHalf = 0;
    for (const Vec3& p : sampleEnvelope(e, 1)) lowerHalf += p.x() < 1.0;
    EXPECT_NEAR(lowerHalf / 20000.0, 0.5, 0.015);
    e.shape = meshShape(twoBoxes());
    std::size_t small = 0;
    for (const Vec3& p : sampleEnvelope(e, 2)) {
        ASSERT_FALSE(p.x() > 1.0 && p.x() < 2.0) << "between the boxes: " << p.transpose();
        small += p.x() <= 1.0;
    }
    EXPECT_NEAR(small / 20000.0, 0.25, 0.013);
}

TEST(MeshEnvelope, SameSeedGivesTheSamePointsOtherSeedsDiffer) {
    Envelope e;
    e.shape = meshShape(icosphere(2), Vec3(0, 50, 0), 20.0);
    e.pointCount = 1000;
    e.seed = 7;
    const std::vector<Vec3> first = sampleEnvelope(e, 3);
    Envelope copy = e;
    copy.shape.mesh = std::make_shared<const MeshVolume>(icosphere(2).volume());  // rebuilt
    EXPECT_EQ(first, sampleEnvelope(copy, 3));
    EXPECT_NE(first, sampleEnvelope(e, 4));
    copy.seed = 8;
    EXPECT_NE(first, sampleEnvelope(copy, 3));
}

TEST(MeshEnvelope, AMeshObstacleRemovesThePointsInsideIt) {
    Envelope e;
    e.shape.kind = ShapeKind::Box;
    e.shape.size = Vec3(2, 2, 2);  // [-1, 1]³; the obstacle [0, 1]³ is an eighth of it
    e.pointCount = 4000;
    const std::vector<Shape> obstacles = {meshShape(boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1)))};
    const std::vector<Vec3> kept = sampleAttractionPoints({&e, 1}, obstacles, 0);
    EXPECT_NEAR(static_cast<double>(kept.size()), 3500.0, 100.0);  // σ ≈ 21
    for (const Vec3& p : kept) EXPECT_FALSE(p.minCoeff() > 0.0 && p.maxCoeff() < 1.0);
}

TEST(MeshEnvelope, AMeshObstacleBlocksGrowth) {
    // A ball of radius 20 above the root; points all around and above it.
    const TriangleSoup ball = icosphere(2);
    double inradius = 1.0;
    for (const auto& t : ball.triangles) {
        const Vec3& a = ball.vertices[t[0]];
        const Vec3 n = (ball.vertices[t[1]] - a).cross(ball.vertices[t[2]] - a).normalized();
        inradius = std::min(inradius, std::abs(n.dot(a)));
    }
    const Vec3 centre(0, 35, 0);
    const std::vector<Shape> obstacles = {meshShape(ball, centre, 20.0)};
    ColonizeParams p;
    p.influenceRadius = 30, p.killRadius = 8, p.step = 4, p.maxIterations = 500;
    std::vector<Vec3> points = randomPoints(3000, -60, 60, 21);
    for (Vec3& q : points) q.y() += 60;  // y in [0, 120]
    const ColonizeResult r = colonize(p, points, obstacles);
    EXPECT_LT(r.attractors, points.size());
    bool grewAbove = false;
    for (const BranchNode& n : r.trees[0].nodes()) {
        grewAbove |= n.position.y() > 60 && std::abs(n.position.x()) < 10;
        ASSERT_FALSE(shapeContains(obstacles[0], n.position));
        if (n.parent < 0) continue;
        // No edge comes closer to the centre than the ball inscribed in the mesh.
        const Vec3 a = r.trees[0].node(n.parent).position, b = n.position;
        const double t = std::clamp((centre - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        EXPECT_GE((a + t * (b - a) - centre).norm(), 20.0 * inradius) << a.transpose();
    }
    EXPECT_TRUE(grewAbove);  // around the ball to the points above it
    EXPECT_GT(r.trees[0].size(), 300u);
}

TEST(MeshEnvelope, ABoxMeshObstacleGrowsTheSameTreeAsTheBoxShape) {
    Shape box;
    box.kind = ShapeKind::Box;
    box.offset = Vec3(10, 30, 0);
    box.size = Vec3(40, 6, 50);
    const std::vector<Shape> analytic = {box};
    const std::vector<Shape> mesh = {
        meshShape(boxMesh(Vec3(-20, -3, -25), Vec3(20, 3, 25)), box.offset)};
    ColonizeParams p;
    p.influenceRadius = 30, p.killRadius = 8, p.step = 4, p.maxIterations = 500;
    std::vector<Vec3> points = randomPoints(2000, -60, 60, 5);
    for (Vec3& q : points) q.y() += 60;
    expectSameResult(colonize(p, points, analytic), colonize(p, points, mesh));
}

TEST(MeshEnvelope, AMeshShapeNeedsAMeshAndAPositiveScale) {
    Shape s;
    s.kind = ShapeKind::Mesh;
    EXPECT_NE(validateShape(s).find("mesh is missing"), std::string::npos);
    s = meshShape(boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1)));
    EXPECT_EQ(validateShape(s), "");
    s.scale = -2;
    EXPECT_NE(validateShape(s).find("scale must be a finite number > 0"), std::string::npos);
}

// A folder with a config and mesh files, removed afterwards.
class MeshConfigTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() / "ramus_mesh_config_test";
        std::filesystem::create_directories(dir_);
        write("cube.obj", toObj(boxMesh(Vec3(-1, -1, -1), Vec3(1, 1, 1))));
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    void write(const std::string& name, const std::string& text) {
        writeFileAtomic((dir_ / name).string(), text);
    }
    std::string config(const std::string& shapes) {
        write("c.json", R"({"influence_radius": 30, "kill_radius": 5, "step": 3, )" + shapes + "}");
        return (dir_ / "c.json").string();
    }
    std::string errorOf(const std::string& shapes) {
        const std::string path = config(shapes);
        try {
            loadColonizeConfig(path);
        } catch (const Error& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;  // names the config file
            return what.substr(path.size() + 2);
        }
        return "(no error)";
    }

    std::filesystem::path dir_;
};

TEST_F(MeshConfigTest, AMeshEnvelopeIsReadNextToTheConfigAndFilled) {
    const ColonizeConfig c = loadColonizeConfig(config(
        R"("envelopes": [{"shape": "mesh", "file": "cube.obj", "offset": [0, 100, 0],
            "scale": 40, "points": 500, "seed": 3}])"));
    ASSERT_EQ(c.envelopes.size(), 1u);
    EXPECT_EQ(c.envelopes[0].shape.kind, ShapeKind::Mesh);
    EXPECT_EQ(c.envelopes[0].shape.scale, 40.0);
    const std::vector<Vec3> points = configAttractionPoints(c);
    ASSERT_EQ(points.size(), 500u);
    for (const Vec3& p : points) {
        ASSERT_LE((p - Vec3(0, 100, 0)).cwiseAbs().maxCoeff(), 40.0) << p.transpose();
    }
    const ColonizeResult r = growFromConfig(c, points);
    EXPECT_LT(r.attractorsLeft, 25u);  // d_k < 2·D leaves a few
    EXPECT_GT(r.trees[0].size(), 100u);
}

TEST_F(MeshConfigTest, TheSameFileIsReadOnceForEnvelopesAndObstacles) {
    const ColonizeConfig c = loadColonizeConfig(
        config(R"("envelopes": [{"shape": "mesh", "file": "cube.obj", "scale": 50, "points": 10},
                                {"shape": "mesh", "file": "./cube.obj", "points": 10}],
                  "obstacles": [{"shape": "mesh", "file": "cube.obj", "offset": [0, 200, 0]}])"));
    ASSERT_EQ(c.obstacles.size(), 1u);
    EXPECT_EQ(c.envelopes[0].shape.mesh, c.envelopes[1].shape.mesh);
    EXPECT_EQ(c.envelopes[0].shape.mesh, c.obstacles[0].mesh);
    EXPECT_TRUE(shapeContains(c.obstacles[0], Vec3(0.5, 200.5, 0)));
}

TEST_F(MeshConfigTest, AMissingMeshFileNamesTheField) {
    EXPECT_NE(
        errorOf(R"("envelopes": [{"shape": "mesh", "file": "crown.obj", "points": 10}])")
            .find("envelopes[0].file: " + (dir_ / "crown.obj").string() + ": cannot read file"),
        std::string::npos);
}

TEST_F(MeshConfigTest, AnOpenMeshNamesTheFieldAndTheBoundaryEdges) {
    // A tetrahedron without two of its faces: the shared edge 1–2 is closed, four are open.
    write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n");
    const std::string e = errorOf(R"("obstacles": [{"shape": "box", "size": [1, 1, 1]},
                                 {"shape": "mesh", "file": "open.obj"}])");
    EXPECT_EQ(e.rfind("obstacles[1].file: ", 0), 0u) << e;
    EXPECT_NE(e.find("not closed: 4 boundary edges"), std::string::npos) << e;
}

TEST_F(MeshConfigTest, AnEmptyMeshFileIsAnError) {
    write("empty.obj", "# nothing\n");
    EXPECT_NE(errorOf(R"("envelopes": [{"shape": "mesh", "file": "empty.obj", "points": 10}])")
                  .find("envelopes[0].file: " + (dir_ / "empty.obj").string() +
                        ": the mesh has no triangles"),
              std::string::npos);
}

TEST_F(MeshConfigTest, AScaleOfZeroIsOutOfRange) {
    EXPECT_EQ(errorOf(R"("envelopes": [{"shape": "mesh", "file": "cube.obj", "scale": 0,
                                        "points": 10}])"),
              "envelopes[0].scale: out of range; expected > 0 (factor on the mesh file's "
              "coordinates), got 0");
}

TEST_F(MeshConfigTest, AMeshNeedsAFile) {
    EXPECT_EQ(errorOf(R"("envelopes": [{"shape": "mesh", "points": 10}])"),
              "envelopes[0]: missing key \"file\" for a mesh");
    EXPECT_EQ(errorOf(R"("envelopes": [{"shape": "mesh", "file": 3, "points": 10}])"),
              "envelopes[0].file: expected a mesh file name (.obj, .glb, .gltf), got 3");
}

TEST_F(MeshConfigTest, AMeshTakesNoRadius) {
    EXPECT_NE(errorOf(R"("envelopes": [{"shape": "mesh", "file": "cube.obj", "radius": 2,
                                        "points": 10}])")
                  .find("envelopes[0].radius: unknown key for a mesh"),
              std::string::npos);
}

}  // namespace
}  // namespace ramus::testing
