// Skeleton metadata files: exact round trips, the bone list, and one test per validation error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"

namespace ramus {
namespace {

using Json = nlohmann::json;

constexpr std::uint64_t kMaxSeed = std::numeric_limits<std::uint64_t>::max();

// A design with every field away from its default.
SkeletonDesign fullDesign() {
    SkeletonDesign d;
    for (int i = 0; i < kFeatureCount; ++i) d.featurePoint[i] = std::sqrt(i + 2.0) / 7.0 - 0.1;
    d.featurePoint[3] = 1e-300;
    d.featurePoint[4] = -2.5e10;
    d.featurePoint[5] = 0.1;
    d.featurePoint[6] = 1.0 / 3.0;
    d.featurePoint[kFeatureWeight] = scaleFeatureValue(kFeatureWeight, 93.0);
    d.neckVertebrae = 12;
    d.frontBackVertebrae = 9;
    d.rearBackVertebrae = 4;
    d.tailVertebrae = 17;
    d.ribs = 11;
    d.limbs = {LimbKind::Leg, LimbKind::Wing, LimbKind::Fin,
               LimbKind::Arm, LimbKind::Wing, LimbKind::Fin};
    d.wingAngles[static_cast<int>(Attachment::Shoulder)] = {131.25, 44.9, -0.5, 89.0 / 3.0};
    d.wingAngles[static_cast<int>(Attachment::Neck)] = {170.0, 0.0, -45.0, 0.1};
    d.heelDraw = 0.1234567890123456789;
    d.headKind = "horse \"long\" é";
    d.spacing = SpineSpacing::Parameter;
    d.grammarSeed = kMaxSeed;
    d.metresPerPixel = 0.0012345678901234567;
    return d;
}

// Root, a back vertebra, a left thigh with two degrees of freedom and its right twin.
Skeleton handSkeleton() {
    Skeleton s;
    s.bones.resize(4);
    s.bones[1].kind = BoneKind::Vertebra;
    s.bones[1].region = SpineRegion::Back;
    s.bones[1].index = 3;
    s.bones[1].parent = 0;
    s.bones[1].extents = Vec3(31.5, 10, 10);
    s.bones[1].joint.position = Vec3(-12.25, 0.5, 0);
    s.bones[1].joint.rest = Eigen::AngleAxisd(0.3, Vec3::UnitZ()).toRotationMatrix();
    for (int i : {2, 3}) {
        Bone& b = s.bones[i];
        b.kind = BoneKind::Thigh;
        b.side = i == 2 ? Side::Left : Side::Right;
        b.limb = LimbKind::Leg;
        b.attachment = Attachment::Hip;
        b.parent = 1;
        b.twin = i == 2 ? 3 : 2;
        b.extents = Vec3(120.0 / 7.0, 8, 6);
        b.joint.position = Vec3(31.5, 0, i == 2 ? 5.0 : -5.0);
        b.joint.dofCount = 2;
        b.joint.dofs[0] = {Vec3::UnitZ(), -30.5, -170, 170};
        b.joint.dofs[1] = {Vec3::UnitX(), 12.0, 0, 45};
    }
    s.word = "root ( vertebra ( thigh ) )";
    s.groundHeight = -412.75;
    s.heelProbability = 0.375;
    s.heelContact = true;
    s.metresPerPixel = 0.0012345678901234567;
    return s;
}

std::string fullJson() {
    return skeletonMetadataJson(fullDesign(), handSkeleton(), "Pegasus «1»", 18446744073709551557u);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSameDesign(const SkeletonDesign& a, const SkeletonDesign& b) {
    ASSERT_EQ(a.featurePoint.size(), b.featurePoint.size());
    for (int i = 0; i < a.featurePoint.size(); ++i) {
        EXPECT_TRUE(sameBits(a.featurePoint[i], b.featurePoint[i])) << i;
    }
    EXPECT_EQ(a.neckVertebrae, b.neckVertebrae);
    EXPECT_EQ(a.frontBackVertebrae, b.frontBackVertebrae);
    EXPECT_EQ(a.rearBackVertebrae, b.rearBackVertebrae);
    EXPECT_EQ(a.tailVertebrae, b.tailVertebrae);
    EXPECT_EQ(a.ribs, b.ribs);
    EXPECT_EQ(a.limbs, b.limbs);
    EXPECT_EQ(a.wingAngles, b.wingAngles);
    EXPECT_TRUE(sameBits(a.heelDraw, b.heelDraw));
    EXPECT_EQ(a.headKind, b.headKind);
    EXPECT_EQ(a.spacing, b.spacing);
    EXPECT_EQ(a.grammarSeed, b.grammarSeed);
    EXPECT_TRUE(sameBits(a.metresPerPixel, b.metresPerPixel));
}

TEST(SkeletonMetadata, WriteReadWriteGivesIdenticalBytes) {
    const std::string first = fullJson();
    const LoadedSkeleton loaded = parseSkeletonMetadata(first, "full.json");
    EXPECT_EQ(loaded.name, "Pegasus «1»");
    EXPECT_EQ(loaded.seed, 18446744073709551557u);
    expectSameDesign(loaded.design, fullDesign());
    EXPECT_EQ(skeletonMetadataJson(loaded.design, handSkeleton(), loaded.name, loaded.seed), first);
}

TEST(SkeletonMetadata, DefaultDesignAndEmptySkeletonRoundTrip) {
    const std::string first = skeletonMetadataJson(SkeletonDesign{}, Skeleton{}, "", 0);
    const LoadedSkeleton loaded = parseSkeletonMetadata(first, "default.json");
    expectSameDesign(loaded.design, SkeletonDesign{});
    EXPECT_EQ(skeletonMetadataJson(loaded.design, Skeleton{}, loaded.name, loaded.seed), first);
    EXPECT_TRUE(Json::parse(first)["skeleton"]["bones"].empty());
}

TEST(SkeletonMetadata, EveryDoubleRoundTripsExactly) {
    std::mt19937_64 bits(7);
    for (int round = 0; round < 200; ++round) {
        SkeletonDesign d;
        for (int i = 0; i < kFeatureCount; ++i) {
            double v = std::numeric_limits<double>::quiet_NaN();
            while (!std::isfinite(v)) {
                const std::uint64_t b = bits();
                std::memcpy(&v, &b, sizeof v);
            }
            d.featurePoint[i] = v;
        }
        d.featurePoint[0] = std::numeric_limits<double>::denorm_min();
        d.featurePoint[1] = std::numeric_limits<double>::max();
        d.featurePoint[2] = 9007199254740993.0;  // 2^53 + 1 rounds to 2^53; must stay that
        const SkeletonDesign back =
            parseSkeletonMetadata(skeletonMetadataJson(d, Skeleton{}, "x", 1), "r.json").design;
        for (int i = 0; i < kFeatureCount; ++i) {
            // −0 is written as 0, which compares equal; every other value keeps its bits.
            EXPECT_TRUE(sameBits(back.featurePoint[i], d.featurePoint[i]) ||
                        (d.featurePoint[i] == 0.0 && back.featurePoint[i] == 0.0))
                << d.featurePoint[i];
        }
    }
}

TEST(SkeletonMetadata, SeedsRoundTripExactly) {
    for (std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{1} << 53,
                               (std::uint64_t{1} << 53) + 1, kMaxSeed - 1, kMaxSeed}) {
        SkeletonDesign d;
        d.grammarSeed = seed ^ 0x5555;
        const LoadedSkeleton loaded =
            parseSkeletonMetadata(skeletonMetadataJson(d, Skeleton{}, "s", seed), "s.json");
        EXPECT_EQ(loaded.seed, seed);
        EXPECT_EQ(loaded.design.grammarSeed, seed ^ 0x5555);
    }
}

TEST(SkeletonMetadata, SeedMayBeAPlainInteger) {
    Json j = Json::parse(fullJson());
    j["seed"] = std::uint64_t{12345678901234567890u};
    j["design"]["grammar_seed"] = 42;
    const LoadedSkeleton loaded = parseSkeletonMetadata(j.dump(), "int.json");
    EXPECT_EQ(loaded.seed, 12345678901234567890u);
    EXPECT_EQ(loaded.design.grammarSeed, 42u);
}

TEST(SkeletonMetadata, DesignListsNamedFeaturesInUserUnits) {
    const Json design = Json::parse(fullJson())["design"];
    ASSERT_EQ(design["features"].size(), static_cast<std::size_t>(kFeatureCount));
    const SkeletonFeatures f = fullDesign().features();
    EXPECT_DOUBLE_EQ(design["features"]["p0_x"].get<double>(), f.spine[0].x());
    EXPECT_DOUBLE_EQ(design["features"]["weight"].get<double>(), f.weightKg);
    EXPECT_EQ(design["limbs"]["hip2"], "fin");
    EXPECT_EQ(design["wing_angles"].size(), 2u);  // shoulder and neck carry wings
    EXPECT_EQ(design["vertebrae"]["tail"], 17);
}

TEST(SkeletonMetadata, BonesCarryHierarchyTransformsAndJoints) {
    const Skeleton s = handSkeleton();
    const Json sk = Json::parse(fullJson())["skeleton"];
    EXPECT_EQ(sk["ground_height"].get<double>(), -412.75);
    EXPECT_EQ(sk["heel_contact"], true);
    EXPECT_EQ(sk["word"], s.word);
    ASSERT_EQ(sk["bones"].size(), 4u);
    const Json& thigh = sk["bones"][3];
    EXPECT_EQ(thigh["name"], "thigh_R");
    EXPECT_EQ(thigh["kind"], "thigh");
    EXPECT_EQ(thigh["side"], "right");
    EXPECT_EQ(thigh["region"], nullptr);
    EXPECT_EQ(thigh["attachment"], "hip");
    EXPECT_EQ(thigh["parent"], 1);
    EXPECT_EQ(thigh["twin"], 2);
    EXPECT_EQ(sk["bones"][0]["attachment"], nullptr);
    const Mat4 local = s.bones[3].joint.transform();
    const Mat4 world = s.worldTransforms()[3];
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            EXPECT_EQ(thigh["local"][r][c].get<double>(), local(r, c));
            EXPECT_EQ(thigh["world"][r][c].get<double>(), world(r, c));
        }
    }
    ASSERT_EQ(thigh["joint"]["dofs"].size(), 2u);
    EXPECT_EQ(thigh["joint"]["dofs"][0]["min"], -170);
    EXPECT_EQ(thigh["joint"]["dofs"][1]["axis"], Json::parse("[1, 0, 0]"));
    EXPECT_EQ(thigh["joint"]["position"][2], -5);
    EXPECT_EQ(sk["bones"][1]["name"], "vertebra_back_03");
}

TEST(SkeletonMetadata, FileIsWrittenAndReadBack) {
    const auto dir = std::filesystem::temp_directory_path() / "ramus_skeleton_metadata_test";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "pegasus.json").string();
    writeSkeletonMetadata(path, fullDesign(), handSkeleton(), "Pegasus «1»", 18446744073709551557u);
    EXPECT_EQ(readFile(path), fullJson());
    expectSameDesign(readSkeletonMetadata(path).design, fullDesign());
    std::filesystem::remove_all(dir);
}

// ---- validation: one test per error ----------------------------------------------------------

// The full file with one change; returns the error message parsing it gives ("" if none).
std::string errorAfter(const std::function<void(Json&)>& change) {
    Json j = Json::parse(fullJson());
    change(j);
    try {
        parseSkeletonMetadata(j.dump(2), "bad.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(SkeletonMetadata, MalformedJsonNamesLineAndColumn) {
    try {
        parseSkeletonMetadata("{\n  \"format\": \"ramus-skeleton\",\n  \"version\": x\n}",
                              "b.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().line, 3);
        EXPECT_EQ(e.loc().column, 14);
        EXPECT_EQ(std::string(e.what()).rfind("b.json:3:14: invalid JSON: ", 0), 0u) << e.what();
    }
}

TEST(SkeletonMetadata, ReadingAMissingFileNamesIt) {
    EXPECT_THROW(readSkeletonMetadata("/nonexistent/ramus/skeleton.json"), Error);
}

TEST(SkeletonMetadata, TopLevelMustBeAnObject) {
    try {
        parseSkeletonMetadata("[1, 2]", "a.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("expected an object"), std::string::npos);
    }
}

TEST(SkeletonMetadata, OtherFormatIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["format"] = "ramus-species"; }),
              "bad.json: field 'format': expected \"ramus-skeleton\"; got \"ramus-species\"");
}

TEST(SkeletonMetadata, UnsupportedVersionNamesTheSupportedOne) {
    EXPECT_EQ(errorAfter([](Json& j) { j["version"] = 2; }),
              "bad.json: field 'version': unsupported version 2; this ramus reads version 1");
}

TEST(SkeletonMetadata, MissingFieldIsNamed) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"].erase("ribs"); }),
              "bad.json: field 'design.ribs': missing");
}

TEST(SkeletonMetadata, UnknownFieldIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["rib"] = 3; }),
              "bad.json: field 'design.rib': unknown field");
}

TEST(SkeletonMetadata, NameMustBeAString) {
    EXPECT_EQ(errorAfter([](Json& j) { j["name"] = 5; }),
              "bad.json: field 'name': expected a string; got 5");
}

TEST(SkeletonMetadata, FeaturePointNeeds29Numbers) {
    const std::string message = errorAfter([](Json& j) { j["design"]["feature_point"].erase(0); });
    EXPECT_EQ(message.rfind("bad.json: field 'design.feature_point': expected an array of 29 "
                            "numbers; got ",
                            0),
              0u)
        << message;
}

TEST(SkeletonMetadata, FeatureMustBeANumber) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["feature_point"][4] = nullptr; }),
              "bad.json: field 'design.feature_point[4]': expected a number; got null");
}

TEST(SkeletonMetadata, NeckOfOneToSixVertebraeIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["vertebrae"]["neck"] = 6; }),
              "bad.json: field 'design.vertebrae.neck': expected 0 (no neck) or at least 7; got 6");
}

TEST(SkeletonMetadata, FrontBackBelowThreeIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["vertebrae"]["back_front"] = 2; }),
              "bad.json: field 'design.vertebrae.back_front': expected an integer in [3, 1000]; "
              "got 2");
}

TEST(SkeletonMetadata, RearBackBelowOneIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["vertebrae"]["back_rear"] = 0; }),
              "bad.json: field 'design.vertebrae.back_rear': expected an integer in [1, 1000]; "
              "got 0");
}

TEST(SkeletonMetadata, NegativeTailIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["vertebrae"]["tail"] = -1; }),
              "bad.json: field 'design.vertebrae.tail': expected an integer in [0, 1000]; got -1");
}

TEST(SkeletonMetadata, HugeCountIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["vertebrae"]["tail"] = kMaxSeed; }),
              "bad.json: field 'design.vertebrae.tail': expected an integer in [0, 1000]; got "
              "18446744073709551615");
}

TEST(SkeletonMetadata, FractionalCountIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["vertebrae"]["tail"] = 7.5; }),
              "bad.json: field 'design.vertebrae.tail': expected an integer; got 7.5");
}

TEST(SkeletonMetadata, MoreRibsThanBackVertebraeAreRejected) {
    // fullDesign: 9 front + 4 rear back vertebrae.
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["ribs"] = 14; }),
              "bad.json: field 'design.ribs': expected an integer in [0, 13]; got 14");
}

TEST(SkeletonMetadata, UnknownLimbKindIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["limbs"]["hip"] = "tail"; }),
              "bad.json: field 'design.limbs.hip': expected one of none, leg, wing, arm, fin; got "
              "\"tail\"");
}

TEST(SkeletonMetadata, LimbKindTheAttachmentRefusesIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["limbs"]["neck"] = "leg"; }),
              "bad.json: field 'design.limbs.neck': a leg cannot attach at the neck (seed 000 "
              "§5.5.3)");
}

TEST(SkeletonMetadata, SecondLimbPairWithoutTheFirstIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["limbs"]["hip"] = "none"; }),
              "bad.json: field 'design.limbs.hip2': needs a limb at hip; it has none");
}

TEST(SkeletonMetadata, NeckLimbWithoutNeckIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["vertebrae"]["neck"] = 0; }),
              "bad.json: field 'design.limbs.neck': a limb on the neck needs neck vertebrae; "
              "design.vertebrae.neck is 0");
}

TEST(SkeletonMetadata, UnknownAttachmentIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["limbs"]["tail"] = "fin"; }),
              "bad.json: field 'design.limbs.tail': unknown field");
}

TEST(SkeletonMetadata, WingAngleOutsideItsIntervalIsRejected) {
    EXPECT_EQ(
        errorAfter([](Json& j) { j["design"]["wing_angles"]["shoulder"]["elbow"] = 10; }),
        "bad.json: field 'design.wing_angles.shoulder.elbow': expected a number in [-45, 0]; got "
        "10");
}

TEST(SkeletonMetadata, WingWithoutAnglesIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["wing_angles"].erase("neck"); }),
              "bad.json: field 'design.wing_angles.neck': missing (the attachment has a wing)");
}

TEST(SkeletonMetadata, AnglesForALimbThatIsNoWingAreRejected) {
    EXPECT_EQ(errorAfter([](Json& j) {
                  j["design"]["wing_angles"]["shoulder2"] = j["design"]["wing_angles"]["neck"];
              }),
              "bad.json: field 'design.wing_angles.shoulder2': design.limbs.shoulder2 is not a "
              "wing");
}

TEST(SkeletonMetadata, HeelDrawOfOneIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["heel_draw"] = 1; }),
              "bad.json: field 'design.heel_draw': expected a number in [0, 1); got 1");
}

TEST(SkeletonMetadata, UnknownSpacingIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["spacing"] = "even"; }),
              "bad.json: field 'design.spacing': expected one of arc_length, parameter; got "
              "\"even\"");
}

TEST(SkeletonMetadata, SeedThatIsNotAnUnsignedIntegerIsRejected) {
    for (const Json& bad :
         {Json("-1"), Json("12a"), Json("18446744073709551616"), Json(-3), Json(1.5), Json("")}) {
        const std::string message = errorAfter([&](Json& j) { j["design"]["grammar_seed"] = bad; });
        EXPECT_EQ(message.rfind("bad.json: field 'design.grammar_seed': expected an integer in "
                                "[0, 18446744073709551615] or its decimal string; got ",
                                0),
                  0u)
            << message;
    }
}

TEST(SkeletonMetadata, NonPositiveScaleIsRejected) {
    EXPECT_EQ(errorAfter([](Json& j) { j["design"]["metres_per_pixel"] = 0; }),
              "bad.json: field 'design.metres_per_pixel': expected a number > 0; got 0");
}

TEST(SkeletonMetadata, OverflowingNumberIsRejected) {
    Json j = Json::parse(fullJson());
    std::string text = j.dump(2);
    const std::string key = "\"heel_draw\": ";
    const std::size_t at = text.find(key) + key.size();
    text.replace(at, text.find(',', at) - at, "1e999");
    try {
        parseSkeletonMetadata(text, "big.json");
        FAIL();
    } catch (const Error& e) {
        // Located at the number (core/json_text.hpp).
        EXPECT_EQ(e.loc().file, "big.json");
        EXPECT_GT(e.loc().line, 1);
        EXPECT_NE(std::string(e.what()).find("number '1e999' is out of range"), std::string::npos)
            << e.what();
    }
}

TEST(SkeletonMetadata, SkeletonPartIsNotReadOnLoad) {
    Json j = Json::parse(fullJson());
    j["skeleton"] = "anything";
    j["design"]["features"] = nullptr;
    expectSameDesign(parseSkeletonMetadata(j.dump(), "k.json").design, fullDesign());
}

}  // namespace
}  // namespace ramus
