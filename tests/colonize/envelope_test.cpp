// Envelopes and obstacles: sampling stays inside and is uniform, same seed gives same points,
// segment tests, validation; point files (xyz, csv, ply) and their errors.
#include "ramus/envelope.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/rng.hpp"

namespace ramus {
namespace {

Shape makeShape(ShapeKind kind) {
    Shape s;
    s.kind = kind;
    s.offset = Vec3(10, 20, -5);
    s.radius = 3;
    s.height = 5;
    s.radii = Vec3(4, 2, 1);
    s.size = Vec3(2, 6, 4);
    return s;
}

const ShapeKind kAllKinds[] = {ShapeKind::Sphere,   ShapeKind::Ellipsoid, ShapeKind::Box,
                               ShapeKind::Cylinder, ShapeKind::Cone,      ShapeKind::Hemisphere,
                               ShapeKind::Disc};

TEST(Envelope, EverySampleLiesInsideItsShape) {
    for (ShapeKind kind : kAllKinds) {
        Envelope e;
        e.shape = makeShape(kind);
        e.pointCount = 2000;
        for (const Vec3& p : sampleEnvelope(e, 1)) {
            ASSERT_TRUE(shapeContains(e.shape, p)) << shapeKindName(kind) << " " << p.transpose();
            const Aabb box = shapeBounds(e.shape);
            for (int a = 0; a < 3; ++a) {
                ASSERT_GE(p[a], box.min[a] - 1e-12);
                ASSERT_LE(p[a], box.max[a] + 1e-12);
            }
        }
    }
}

TEST(Envelope, SamplesAreUniformInVolume) {
    // Monte Carlo: the fraction of samples inside a sub-box equals the sub-box's share of the
    // shape's volume. Estimate that share by rejection sampling over the bounding box.
    for (ShapeKind kind : kAllKinds) {
        Envelope e;
        e.shape = makeShape(kind);
        e.pointCount = 40000;
        const Aabb box = shapeBounds(e.shape);
        Aabb probe;  // the lower-left quarter of the bounding box, in x and y
        probe.add(box.min);
        probe.add(Vec3(box.center().x(), box.center().y(), box.max.z()));
        auto inProbe = [&](const Vec3& p) {
            return p.x() <= probe.max.x() && p.y() <= probe.max.y();
        };
        double sampled = 0;
        for (const Vec3& p : sampleEnvelope(e, 2)) sampled += inProbe(p);
        sampled /= e.pointCount;
        Rng rng(99);
        double inside = 0, both = 0;
        for (int i = 0; i < 200000; ++i) {
            const Vec3 q(rng.uniform(box.min.x(), box.max.x()),
                         rng.uniform(box.min.y(), box.max.y()),
                         kind == ShapeKind::Disc ? e.shape.offset.z()
                                                 : rng.uniform(box.min.z(), box.max.z()));
            if (!shapeContains(e.shape, q)) continue;
            ++inside;
            both += inProbe(q);
        }
        EXPECT_NEAR(sampled, both / inside, 0.015) << shapeKindName(kind);
        EXPECT_GT(inside, 1000.0);
    }
}

TEST(Envelope, SameSeedSameNumbersDifferentSeedDifferentPoints) {
    Envelope e;
    e.shape = makeShape(ShapeKind::Cone);
    e.pointCount = 100;
    e.seed = 4;
    EXPECT_EQ(sampleEnvelope(e, 7), sampleEnvelope(e, 7));
    Envelope other = e;
    other.seed = 5;
    EXPECT_NE(sampleEnvelope(e, 7), sampleEnvelope(other, 7));
    EXPECT_NE(sampleEnvelope(e, 7), sampleEnvelope(e, 8));  // the base seed matters too
}

TEST(Envelope, EnvelopesOfAListDoNotDependOnEachOther) {
    Envelope a, b;
    a.shape = makeShape(ShapeKind::Box);
    b.shape = makeShape(ShapeKind::Sphere);
    a.pointCount = 30, b.pointCount = 40;
    a.seed = 1, b.seed = 2;
    const std::vector<Envelope> both = {a, b};
    const std::vector<Vec3> all = sampleAttractionPoints(both, {}, 3);
    ASSERT_EQ(all.size(), 70u);
    const std::vector<Vec3> onlyB = sampleEnvelope(b, 3);
    EXPECT_TRUE(std::equal(onlyB.begin(), onlyB.end(), all.begin() + 30));
}

TEST(Envelope, DiscPointsLieInItsPlane) {
    Envelope e;
    e.shape = makeShape(ShapeKind::Disc);
    e.shape.innerRadius = 2;
    e.pointCount = 500;
    for (const Vec3& p : sampleEnvelope(e)) {
        EXPECT_EQ(p.z(), e.shape.offset.z());
        const double r = std::hypot(p.x() - 10, p.y() - 20);
        EXPECT_GE(r, 2.0 - 1e-12);
        EXPECT_LE(r, 3.0 + 1e-12);
    }
}

TEST(Envelope, ObstaclesRemovePointsInsideThem) {
    Envelope e;
    e.shape = makeShape(ShapeKind::Box);
    e.pointCount = 1000;
    Shape hole = makeShape(ShapeKind::Sphere);
    hole.radius = 1.5;
    const std::vector<Shape> obstacles = {hole};
    const std::vector<Envelope> envelopes = {e};
    const std::vector<Vec3> points = sampleAttractionPoints(envelopes, obstacles);
    EXPECT_LT(points.size(), 1000u);
    EXPECT_GT(points.size(), 500u);
    for (const Vec3& p : points) EXPECT_FALSE(shapeContains(hole, p));
}

TEST(Shape, SegmentsThroughAShapeHitIt) {
    const Shape sphere = makeShape(ShapeKind::Sphere);  // centre (10,20,-5), r 3
    EXPECT_TRUE(segmentHitsShape(sphere, Vec3(0, 20, -5), Vec3(20, 20, -5)));       // through
    EXPECT_FALSE(segmentHitsShape(sphere, Vec3(0, 23.5, -5), Vec3(20, 23.5, -5)));  // above
    EXPECT_TRUE(segmentHitsShape(sphere, Vec3(10, 20, -5), Vec3(10, 20, -4)));      // inside
    EXPECT_FALSE(segmentHitsShape(sphere, Vec3(0, 20, -5), Vec3(6.9, 20, -5)));     // stops short
    const Shape box = makeShape(ShapeKind::Box);  // x 9..11, y 17..23, z -7..-3
    EXPECT_TRUE(segmentHitsShape(box, Vec3(5, 18, -5), Vec3(15, 22, -5)));
    EXPECT_FALSE(segmentHitsShape(box, Vec3(5, 18, -5), Vec3(8.9, 22, -5)));
    const Shape cone = makeShape(ShapeKind::Cone);  // base r 3 at y 20, apex at y 25
    EXPECT_TRUE(segmentHitsShape(cone, Vec3(5, 22, -5), Vec3(15, 22, -5)));  // r 1.8 there
    EXPECT_FALSE(segmentHitsShape(cone, Vec3(5, 24.9, -4.5), Vec3(15, 24.9, -4.5)));
    Shape ring = makeShape(ShapeKind::Disc);
    ring.innerRadius = 2;
    EXPECT_FALSE(segmentHitsShape(ring, Vec3(9.5, 20, -5), Vec3(10.5, 20.5, -5)));  // in hole
    EXPECT_TRUE(segmentHitsShape(ring, Vec3(9.5, 20, -5), Vec3(20, 20, -5)));       // leaves it
}

TEST(Shape, InvalidSizesAreNamed) {
    Shape s = makeShape(ShapeKind::Cylinder);
    EXPECT_EQ(validateShape(s), "");
    s.height = -1;
    EXPECT_NE(validateShape(s).find("height"), std::string::npos);
    s = makeShape(ShapeKind::Ellipsoid);
    s.radii.y() = 0;
    EXPECT_NE(validateShape(s).find("radii"), std::string::npos);
    s = makeShape(ShapeKind::Disc);
    s.innerRadius = 3;
    EXPECT_NE(validateShape(s).find("inner_radius"), std::string::npos);
}

TEST(PointFile, ReadsXyzWithCommentsAndExtraColumns) {
    const auto points = parsePoints("# scan\n1 2 3\n\n  4.5\t-5 6e1 255 0 0\n", "xyz", "scan.xyz");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[0], Vec3(1, 2, 3));
    EXPECT_EQ(points[1], Vec3(4.5, -5, 60));
}

TEST(PointFile, ReadsCsvWithAHeader) {
    const auto points = parsePoints("x,y,z\n1,2,3\n-1, 0.5 ,2\n", "csv", "p.csv");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[1], Vec3(-1, 0.5, 2));
}

TEST(PointFile, ReadsAsciiPlyInAnyPropertyOrder) {
    const std::string ply =
        "ply\nformat ascii 1.0\ncomment test\nelement vertex 2\nproperty float z\n"
        "property float x\nproperty uchar red\nproperty float y\nelement face 0\n"
        "property list uchar int vertex_indices\nend_header\n3 1 9 2\n6 4 9 5\n";
    const auto points = parsePoints(ply, "ply", "p.ply");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[0], Vec3(1, 2, 3));
    EXPECT_EQ(points[1], Vec3(4, 5, 6));
}

std::string errorOf(const std::string& text, const std::string& format) {
    try {
        parsePoints(text, format, "in." + format);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(PointFile, TooFewCoordinatesNameTheLine) {
    EXPECT_EQ(errorOf("1 2 3\n4 5\n", "xyz"),
              "in.xyz:2: expected 3 coordinates x y z; got 2 field(s)");
}

TEST(PointFile, ANonNumberNamesTheLineAndTheText) {
    EXPECT_EQ(errorOf("1,2,3\n1,two,3\n", "csv"),
              "in.csv:2: invalid coordinate 'two'; expected a number");
}

TEST(PointFile, NonFiniteCoordinatesAreRejected) {
    EXPECT_NE(errorOf("1 2 inf\n", "xyz").find("in.xyz:1: coordinate 'inf' is not finite"),
              std::string::npos);
}

TEST(PointFile, BinaryPlyIsRejected) {
    EXPECT_EQ(errorOf("ply\nformat binary_little_endian 1.0\nend_header\n", "ply"),
              "in.ply:2: unsupported PLY format; expected 'format ascii 1.0'");
}

TEST(PointFile, PlyWithoutCoordinatesIsRejected) {
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n",
                      "ply"),
              "in.ply:5: the vertex element lacks property x, y or z");
}

TEST(PointFile, TruncatedPlyIsRejected) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n1 2 3\n";
    EXPECT_EQ(errorOf(ply, "ply"), "in.ply:8: the file ends after 1 of 3 vertices");
}

TEST(PointFile, UnknownExtensionIsRejected) {
    try {
        readPointsFile("cloud.las");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cloud.las: unsupported point file extension '.las'; expected .xyz, .txt, "
                  ".csv or .ply");
    }
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

// Non-finite numbers in point files, one test per format, and the PLY header's vertex count.
TEST(PointFileNonFinite, XyzNumbersBeyondDoubleRangeNameTheLine) {
    EXPECT_EQ(errorOf("0 0 0\n1 1e999 2\n", "xyz"),
              "in.xyz:2: coordinate '1e999' is outside the range of a double; expected a finite "
              "number");
}

TEST(PointFileNonFinite, CsvNanIsRejected) {
    EXPECT_EQ(errorOf("x,y,z\nnan,0,0\n", "csv"), "in.csv:2: coordinate 'nan' is not finite");
}

TEST(PointFileNonFinite, PlyInfinityIsRejected) {
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n0 -inf 0\n",
                      "ply"),
              "in.ply:8: coordinate '-inf' is not finite");
}

TEST(PointFileNonFinite, PlyVertexCountBeyondTheLimitIsAnError) {
    for (const char* count : {"1e300", "4294967296", "nan", "-1"}) {
        EXPECT_EQ(errorOf(std::string("ply\nformat ascii 1.0\nelement vertex ") + count +
                              "\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n",
                          "ply"),
                  std::string("in.ply:3: invalid vertex count '") + count +
                      "'; expected an integer from 0 to 4294967295");
    }
}

TEST(PointFileNonFinite, AHugeClaimedVertexCountFailsAtTheEndOfTheData) {
    // The claimed count is not reserved up front (that would exhaust memory).
    EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 4000000000\n"
                      "property float x\nproperty float y\nproperty float z\n"
                      "end_header\n1 2 3\n",
                      "ply"),
              "in.ply:8: the file ends after 1 of 4000000000 vertices");
}

TEST(PointFileLimits, AFileLargerThanTheLimitIsRefused) {
    const auto path = std::filesystem::temp_directory_path() / "ramus_points_limit.xyz";
    writeFileAtomic(path.string(), "1 2 3\n4 5 6\n");  // 12 bytes
    EXPECT_EQ(readPointsFile(path.string(), 12).size(), 2u);
    try {
        readPointsFile(path.string(), 11);
        FAIL() << "expected the size limit";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string() +
                                             ": the file is larger than the input limit of 11 "
                                             "bytes"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace ramus
