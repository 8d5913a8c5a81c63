// User bone libraries (src/bones/bone_library_files.cpp, bone_mesh_file.cpp): the default
// library written out and loaded back reproduces every model and every skeleton byte for byte;
// models a manifest leaves out come from the default library; OBJ and GLB models; every
// validation error names the file, the place and the missing piece.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bones/bone_files.hpp"
#include "bones/mesh_checks.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/scene.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("ramus_bones_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// The unit cube [0, 1]³, quads counter-clockwise seen from outside (volume 1).
constexpr const char* kCubeVertices =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
constexpr const char* kCubeFaces =
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

std::string cubeObj() { return std::string(kCubeVertices) + kCubeFaces; }

constexpr const char* kOffsets = R"("parent_joint": [0, 0, 0], "child_joints": [[1, 0, 0]])";

/// A library directory with `cube.obj` (or `meshText` under that name) and `manifest`.
fs::path libraryWith(const std::string& name, const std::string& manifest,
                     const std::string& meshText = cubeObj()) {
    const fs::path dir = scratch(name);
    writeFileAtomic((dir / "cube.obj").string(), meshText);
    writeFileAtomic((dir / "bones.json").string(), manifest);
    return dir;
}

std::string oneModel(const std::string& kind, const std::string& body) {
    return "{\"version\": 1, \"models\": {\"" + kind + "\": {" + body + "}}}";
}

/// The message of the Error loading `dir` at low resolution throws ("" if none).
std::string loadError(const fs::path& dir) {
    try {
        (void)loadBoneLibrary(dir.string(), BoneResolution::Low);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

BoneLibrary defaultLibraryAtBothResolutions() {
    BoneLibrary both;
    for (BoneResolution res : {BoneResolution::Low, BoneResolution::High}) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            both.set(kind, res, BoneLibrary::builtin(res).model(kind, res));
        }
    }
    return both;
}

void expectSameModel(const BoneModel& a, const BoneModel& b, const std::string& what) {
    EXPECT_EQ(a.mesh.name, b.mesh.name) << what;
    EXPECT_TRUE(a.mesh.positions == b.mesh.positions) << what;
    EXPECT_TRUE(a.mesh.normals == b.mesh.normals) << what;
    EXPECT_TRUE(a.mesh.indices == b.mesh.indices) << what;
    EXPECT_TRUE(a.parentJoint == b.parentJoint) << what;
    EXPECT_TRUE(a.childJoints == b.childJoints) << what;
    EXPECT_EQ(a.widthFromHeight, b.widthFromHeight) << what;
}

TEST(BoneLibraryFiles, TheDefaultLibraryWrittenOutLoadsBackIdentically) {
    const fs::path dir = scratch("round_trip");
    writeBoneLibrary(defaultLibraryAtBothResolutions(), dir.string());
    for (BoneResolution res : {BoneResolution::Low, BoneResolution::High}) {
        const BoneLibrary loaded = loadBoneLibrary(dir.string(), res);
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            expectSameModel(
                loaded.model(kind, res), BoneLibrary::builtin(res).model(kind, res),
                std::string(boneModelKindName(kind)) + " " + std::string(boneResolutionName(res)));
        }
    }
    EXPECT_TRUE(fs::exists(dir / "low" / "skull_bird.obj"));
    EXPECT_TRUE(fs::exists(dir / "high" / "pelvis_double.obj"));
}

TEST(BoneLibraryFiles, SkeletonsFromTheLoadedLibraryAreByteIdenticalGlbs) {
    const fs::path dir = scratch("round_trip_glb");
    writeBoneLibrary(defaultLibraryAtBothResolutions(), dir.string());
    SkeletonInputs pigeon;
    pigeon.example = "Pigeon";
    for (BoneResolution res : {BoneResolution::Low, BoneResolution::High}) {
        const BoneLibrary loaded = loadBoneLibrary(dir.string(), res);
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            Rng rng = Rng::forStream(seed, 0);
            const Skeleton skeleton = buildSkeleton(designSkeleton(
                SkeletonStats::builtin(), seed == 3 ? pigeon : SkeletonInputs{}, rng));
            for (const char* head : {"carnivore", "bird"}) {
                EXPECT_EQ(encodeGlb(skeletonSceneAt(skeleton, res, head, &loaded)),
                          encodeGlb(skeletonSceneAt(skeleton, res, head)))
                    << seed << " " << head;
            }
        }
    }
}

TEST(BoneLibraryFiles, WritingIsDeterministicAndTheManifestIsVersioned) {
    const fs::path a = scratch("write_a"), b = scratch("write_b");
    BoneLibrary low;
    low.set(
        BoneModelKind::Rib, BoneResolution::Low,
        BoneLibrary::builtin(BoneResolution::Low).model(BoneModelKind::Rib, BoneResolution::Low));
    writeBoneLibrary(low, a.string());
    writeBoneLibrary(low, b.string());
    const std::string manifest = readFile((a / "bones.json").string());
    EXPECT_EQ(manifest, readFile((b / "bones.json").string()));
    EXPECT_EQ(readFile((a / "low" / "rib.obj").string()),
              readFile((b / "low" / "rib.obj").string()));
    EXPECT_EQ(manifest,
              "{\n  \"version\": 1,\n  \"models\": {\n    \"rib\": {\n      \"low\": "
              "\"low/rib.obj\",\n      \"parent_joint\": [0, 0, 0],\n      \"child_joints\": "
              "[[1, 0, 0]],\n      \"width_from_height\": 0\n    }\n  }\n}\n");
    EXPECT_FALSE(fs::exists(a / "high"));
}

TEST(BoneLibraryFiles, KindsTheManifestLeavesOutComeFromTheDefaultLibrary) {
    const fs::path dir = libraryWith(
        "fallback", oneModel("skull_bird", std::string(R"("mesh": "cube.obj", )") + kOffsets));
    const BoneLibrary library = loadBoneLibrary(dir.string(), BoneResolution::Low);
    const BoneModel& skull = library.model(BoneModelKind::SkullBird, BoneResolution::Low);
    EXPECT_EQ(skull.mesh.positions.size(), 8u);
    EXPECT_EQ(skull.mesh.triangleCount(), 12u);
    EXPECT_EQ(skull.mesh.name, "skull_bird");
    EXPECT_DOUBLE_EQ(signedVolume(skull.mesh), 1.0);
    expectSameModel(
        library.model(BoneModelKind::Rib, BoneResolution::Low),
        BoneLibrary::builtin(BoneResolution::Low).model(BoneModelKind::Rib, BoneResolution::Low),
        "rib");
    // "mesh" serves both resolutions.
    EXPECT_EQ(loadBoneLibrary(dir.string(), BoneResolution::High)
                  .model(BoneModelKind::SkullBird, BoneResolution::High)
                  .mesh.triangleCount(),
              12u);
}

TEST(BoneLibraryFiles, OffsetsAreReadAsGiven) {
    const fs::path dir = libraryWith(
        "offsets", oneModel("pelvis_double", R"("mesh": "cube.obj", "parent_joint": [0.1, 0, 0],
 "child_joints": [[0.9, 0, 0], [0.3, -0.5, 0.4]], "width_from_height": 0.75)"));
    const BoneLibrary library = loadBoneLibrary(dir.string(), BoneResolution::Low);
    const BoneModel& model = library.model(BoneModelKind::PelvisDouble, BoneResolution::Low);
    EXPECT_TRUE(model.parentJoint == Vec3(0.1, 0, 0));
    ASSERT_EQ(model.childJoints.size(), 2u);
    EXPECT_TRUE(model.childJoints[1] == Vec3(0.3, -0.5, 0.4));
    EXPECT_EQ(model.widthFromHeight, 0.75);
}

TEST(BoneLibraryFiles, ObjWithoutNormalsGetsOutwardUnitNormals) {
    const fs::path dir =
        libraryWith("normals", oneModel("rib", std::string(R"("mesh": "cube.obj", )") + kOffsets));
    const BoneLibrary library = loadBoneLibrary(dir.string(), BoneResolution::Low);
    const Mesh& mesh = library.model(BoneModelKind::Rib, BoneResolution::Low).mesh;
    ASSERT_EQ(mesh.normals.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        EXPECT_NEAR(mesh.normals[i].norm(), 1.0f, 1e-6f);
        // Each corner of the cube: the normal points away from the centre in every axis.
        const Vec3f out = mesh.positions[i] - Vec3f::Constant(0.5f);
        for (int k = 0; k < 3; ++k) EXPECT_GT(mesh.normals[i][k] * out[k], 0.0f) << i;
    }
}

TEST(BoneLibraryFiles, GlbModelsArePlacedByTheirNodes) {
    const fs::path dir =
        libraryWith("glb", oneModel("hoof", std::string(R"("mesh": "cube.glb", )") + kOffsets));
    Scene scene;
    scene.meshes.push_back(detail::readBoneMesh((dir / "cube.obj").string(), "cube"));
    SceneNode node;
    node.mesh = 0;
    node.translation = Vec3(0.5, 0, 0);
    scene.nodes.push_back(node);
    writeGlb(scene, (dir / "cube.glb").string());
    const BoneLibrary library = loadBoneLibrary(dir.string(), BoneResolution::High);
    const Mesh& mesh = library.model(BoneModelKind::Hoof, BoneResolution::High).mesh;
    EXPECT_EQ(mesh.triangleCount(), 12u);
    EXPECT_FLOAT_EQ(mesh.bounds().min.x(), 0.5f);
    EXPECT_FLOAT_EQ(mesh.bounds().max.x(), 1.5f);
    EXPECT_DOUBLE_EQ(signedVolume(mesh), 1.0);
}

// ---- validation errors: the file, the place, the missing piece -------------------------------

TEST(BoneLibraryFiles, AMissingManifestOrDirectoryNamesIt) {
    const fs::path dir = scratch("no_manifest");
    EXPECT_NE(loadError(dir).find((dir / "bones.json").string() + ": cannot read file"),
              std::string::npos)
        << loadError(dir);
    EXPECT_NE(loadError(dir / "nope").find("not a directory"), std::string::npos);
}

TEST(BoneLibraryFiles, SyntaxErrorsAreLocatedInTheManifest) {
    const fs::path dir = libraryWith("syntax", "{\"version\": 1,\n \"models\": {,}}");
    EXPECT_NE(loadError(dir).find("bones.json:2:13: invalid JSON"), std::string::npos)
        << loadError(dir);
}

TEST(BoneLibraryFiles, UnknownKindNamesTheKindWithLineAndColumn) {
    const fs::path dir = libraryWith(
        "unknown_kind", "{\n  \"version\": 1,\n  \"models\": {\n    \"tentacle\": {}\n  }\n}\n");
    const std::string e = loadError(dir);
    EXPECT_NE(e.find("bones.json:4:17: models.tentacle: unknown bone model kind \"tentacle\"; "
                     "expected one of vertebra, tail_tip, rib"),
              std::string::npos)
        << e;
}

TEST(BoneLibraryFiles, MissingOrUnsupportedVersionIsAnError) {
    EXPECT_NE(loadError(libraryWith("no_version", "{\"models\": {}}")).find("missing \"version\""),
              std::string::npos);
    const std::string e = loadError(libraryWith("version_2", "{\"version\": 2, \"models\": {}}"));
    EXPECT_NE(e.find("bones.json:1:13: version: unsupported version 2; expected 1"),
              std::string::npos)
        << e;
}

TEST(BoneLibraryFiles, MissingOffsetsAreNamed) {
    const std::string e = loadError(libraryWith(
        "no_parent", oneModel("rib", R"("mesh": "cube.obj", "child_joints": [[1, 0, 0]])")));
    EXPECT_NE(e.find("bones.json:1:34: models.rib: missing \"parent_joint\""), std::string::npos)
        << e;
    const std::string children = loadError(
        libraryWith("no_children",
                    "{\"version\": 1, \"models\": {\n    \"rib\": {\"mesh\": \"cube.obj\", "
                    "\"parent_joint\": [0, 0, 0], \"child_joints\": []}}}"));
    EXPECT_NE(children.find("bones.json:2:76: models.rib.child_joints: expected a non-empty list"),
              std::string::npos)
        << children;
    const std::string coordinate = loadError(libraryWith(
        "bad_point",
        oneModel(
            "rib",
            R"("mesh": "cube.obj", "parent_joint": [0, "y", 0], "child_joints": [[1, 0, 0]])")));
    EXPECT_NE(coordinate.find("models.rib.parent_joint[1]: expected a finite number; got \"y\""),
              std::string::npos)
        << coordinate;
    const std::string backwards = loadError(libraryWith(
        "backwards",
        oneModel("rib",
                 R"("mesh": "cube.obj", "parent_joint": [1, 0, 0], "child_joints": [[0, 0, 0]])")));
    EXPECT_NE(backwards.find("models.rib.child_joints[0]: the first child joint"),
              std::string::npos)
        << backwards;
}

TEST(BoneLibraryFiles, MissingMeshesAndFilesAreNamed) {
    const std::string none = loadError(libraryWith("no_mesh", oneModel("rib", kOffsets)));
    EXPECT_NE(none.find("models.rib: missing \"mesh\" or \"low\""), std::string::npos) << none;
    const std::string highOnly = loadError(libraryWith(
        "high_only", oneModel("rib", std::string(R"("high": "cube.obj", )") + kOffsets)));
    EXPECT_NE(highOnly.find("missing \"mesh\" or \"low\""), std::string::npos) << highOnly;
    const fs::path dir = libraryWith(
        "missing_file", oneModel("rib", std::string(R"("mesh": "gone.obj", )") + kOffsets));
    const std::string missing = loadError(dir);
    EXPECT_NE(missing.find("bones.json:1:43: models.rib.mesh: mesh file not found: " +
                           (dir / "gone.obj").string()),
              std::string::npos)
        << missing;
    const std::string both = loadError(libraryWith(
        "both",
        oneModel("rib", std::string(R"("mesh": "cube.obj", "low": "cube.obj", )") + kOffsets)));
    EXPECT_NE(both.find("both \"mesh\" and \"low\"/\"high\""), std::string::npos) << both;
    const std::string unknownKey = loadError(libraryWith(
        "unknown_key",
        oneModel("rib", std::string(R"("mesh": "cube.obj", "colour": 1, )") + kOffsets)));
    EXPECT_NE(unknownKey.find("models.rib.colour: unknown key"), std::string::npos) << unknownKey;
}

TEST(BoneLibraryFiles, OpenInwardAndDegenerateMeshesAreErrorsNamingTheMeshFile) {
    const std::string manifest = oneModel("rib", std::string(R"("mesh": "cube.obj", )") + kOffsets);
    const std::string faces(kCubeFaces);
    // The x = 1 face left out: the cube is open; the first face on an open edge is line 9's
    // "f 1 4 3 2" (its edge 3–2 belonged to the missing face too).
    const fs::path open =
        libraryWith("open", manifest, kCubeVertices + faces.substr(0, faces.rfind("f 2 3 7 6")));
    const std::string e = loadError(open);
    EXPECT_NE(e.find((open / "cube.obj").string() + ":9: face has an edge that is open"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("(bone model \"rib\", low, in " + (open / "bones.json").string() + ")"),
              std::string::npos)
        << e;
    // Every face reversed: closed, but the volume is negative.
    const std::string inward = loadError(
        libraryWith("inward", manifest,
                    std::string(kCubeVertices) +
                        "f 2 3 4 1\nf 8 7 6 5\nf 5 6 2 1\nf 3 7 8 4\nf 4 8 5 1\nf 6 7 3 2\n"));
    EXPECT_NE(inward.find("signed volume of -1"), std::string::npos) << inward;
    // A zero-area triangle (three collinear corners) on line 16.
    const std::string degenerate =
        loadError(libraryWith("degenerate", manifest, cubeObj() + "v 0.5 0 0\nf 1 9 2\n"));
    EXPECT_NE(degenerate.find("cube.obj:16: face is degenerate"), std::string::npos) << degenerate;
    const std::string empty = loadError(libraryWith("empty", manifest, "# nothing\n"));
    EXPECT_NE(empty.find("cube.obj: the mesh has no triangles"), std::string::npos) << empty;
    const std::string syntax = loadError(libraryWith("obj_syntax", manifest, "v 0 0\n"));
    EXPECT_NE(syntax.find("cube.obj:1:1: a vertex needs three coordinates"), std::string::npos)
        << syntax;
}

TEST(BoneLibraryFiles, MeshChecksAcceptEveryDefaultModel) {
    for (BoneResolution res : {BoneResolution::Low, BoneResolution::High}) {
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            EXPECT_NO_THROW(detail::checkBoneMesh(BoneLibrary::builtin(res).model(kind, res).mesh,
                                                  std::string(boneModelKindName(kind))));
        }
    }
}

TEST(BoneLibraryFiles, TheBoxResolutionHasNoLibraryToLoad) {
    EXPECT_THROW((void)loadBoneLibrary(scratch("box").string(), BoneResolution::Box), Error);
}

}  // namespace
}  // namespace ramus
