// Annotated SVG side views (seed 000 §7.4.1): import with hand-computed expectations, every
// error case, and the lossless export → import round trip.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/species.hpp"

namespace ramus {
namespace {

constexpr const char* kHeader =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" "
    "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" ";

// An Inkscape-style file: a layer moved by translate(0,-52), relative and absolute commands,
// labels in inkscape:label or id, y pointing down.
std::string inkscapeFile(const std::string& extra = "") {
    return std::string(kHeader) +
           "width=\"1000\" height=\"1000\" viewBox=\"0 0 1000 1000\">\n"
           "  <g inkscape:groupmode=\"layer\" inkscape:label=\"Layer 1\" "
           "transform=\"translate(0,-52)\">\n"
           "    <path id=\"path10\" inkscape:label=\"neck\" d=\"m 100,500 c 10,-20 30,-30 "
           "50,-40\"/>\n"
           "    <path inkscape:label=\"back\" d=\"M 150,460 C 300,450 500,450 700,470\"/>\n"
           "    <path inkscape:label=\"tail\" d=\"M 700,470 C 800,480 850,500 900,560\"/>\n"
           "    <path inkscape:label=\"upper_arm\" d=\"M 160,470 v 100\"/>\n"
           "    <path inkscape:label=\"Lower-Arm\" d=\"m 160,570 l 30,40\"/>\n"
           "    <path id=\"thigh\" d=\"M 680 480 L 680 600\"/>\n"
           "    <path id=\"some-other-drawing\" d=\"M 0 0 L 5 5 L 9 9\"/>\n" +
           extra + "  </g>\n</svg>\n";
}

SvgImportOptions fields() {
    SvgImportOptions o;
    o.name = "Test animal";
    o.animalClass = AnimalClass::Reptile;
    o.wings = 0;
    o.legs = 2;
    o.weightKg = 7;
    return o;
}

// A file with just a back curve and the given root attributes / viewBox.
std::string backOnly(const std::string& root, const std::string& backD,
                     const std::string& extra = "") {
    return std::string(kHeader) + root + ">\n<path id=\"back\" d=\"" + backD + "\"/>\n" + extra +
           "</svg>\n";
}

std::string importError(const std::string& svg, const SvgImportOptions& options = fields()) {
    try {
        importSpeciesSvg(svg, "a.svg", options);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

void expectPoint(const Vec2& p, double x, double y) {
    EXPECT_NEAR(p.x(), x, 1e-9);
    EXPECT_NEAR(p.y(), y, 1e-9);
}

#define EXPECT_CONTAINS(text, part) \
    EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)

TEST(SpeciesSvg, ImportsAnInkscapeAnnotation) {
    const SpeciesRecord r = importSpeciesSvg(inkscapeFile(), "a.svg", fields());
    // y' = 1000 − (y − 52) = 1052 − y.
    const double expected[10][2] = {{100, 552}, {110, 572}, {130, 582}, {150, 592}, {300, 602},
                                    {500, 602}, {700, 582}, {800, 572}, {850, 552}, {900, 492}};
    for (int i = 0; i < 10; ++i) expectPoint(r.features.spine[i], expected[i][0], expected[i][1]);
    EXPECT_DOUBLE_EQ(r.features.limb(Limb::UpperArm), 100);
    EXPECT_DOUBLE_EQ(r.features.limb(Limb::Forearm), 50);  // "Lower-Arm" is an alias
    EXPECT_DOUBLE_EQ(r.features.limb(Limb::Hand), 0);
    EXPECT_DOUBLE_EQ(r.features.limb(Limb::Thigh), 120);
    EXPECT_EQ(r.name, "Test animal");
    EXPECT_EQ(r.animalClass, AnimalClass::Reptile);
    EXPECT_EQ(r.features.weightKg, 7);
}

TEST(SpeciesSvg, MissingNeckAndTailRepeatTheBacksEnds) {
    const SpeciesRecord r = importSpeciesSvg(
        backOnly("viewBox=\"0 0 1000 1000\"", "M 100 900 C 200 900 300 900 400 900"), "a.svg",
        fields());
    for (int i = 0; i < 3; ++i) expectPoint(r.features.spine[i], 100, 100);
    for (int i = 7; i < 10; ++i) expectPoint(r.features.spine[i], 400, 100);
}

TEST(SpeciesSvg, StraightAndQuadraticBacksBecomeExactCubics) {
    SpeciesRecord r = importSpeciesSvg(
        backOnly("viewBox=\"0 0 1000 1000\"", "M 100 1000 L 400 1000"), "a.svg", fields());
    expectPoint(r.features.spine[4], 200, 0);
    expectPoint(r.features.spine[5], 300, 0);
    r = importSpeciesSvg(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 1000 Q 300 700 600 1000"),
                         "a.svg", fields());
    expectPoint(r.features.spine[4], 200, 200);
    expectPoint(r.features.spine[5], 400, 200);
}

TEST(SpeciesSvg, CurvesDrawnBackwardsAreOriented) {
    const std::string svg = std::string(kHeader) +
                            "viewBox=\"0 0 1000 1000\">\n"
                            "<path id=\"neck\" d=\"M 300 500 C 250 450 200 420 100 400\"/>\n"
                            "<path id=\"back\" d=\"M 700 500 C 600 500 400 500 300 500\"/>\n"
                            "<path id=\"tail\" d=\"M 900 600 C 850 550 800 520 700 500\"/>\n</svg>";
    const SpeciesRecord r = importSpeciesSvg(svg, "a.svg", fields());
    expectPoint(r.features.spine[0], 100, 600);  // head
    expectPoint(r.features.spine[3], 300, 500);  // shoulder
    expectPoint(r.features.spine[6], 700, 500);  // hip
    expectPoint(r.features.spine[9], 900, 400);  // tail tip
}

TEST(SpeciesSvg, FrameFitScalesAWideDocumentAndMovesItToTheBottom) {
    // 2000×1000 → scale 0.5: the document becomes 1000×500 at the bottom of the frame.
    const SpeciesRecord r = importSpeciesSvg(
        backOnly("viewBox=\"0 0 2000 1000\"", "M 0 1000 C 500 0 1500 0 2000 0"), "a.svg", fields());
    expectPoint(r.features.spine[3], 0, 0);
    expectPoint(r.features.spine[4], 250, 500);
    expectPoint(r.features.spine[6], 1000, 500);
}

TEST(SpeciesSvg, FrameFitCentresATallDocument) {
    const SpeciesRecord r = importSpeciesSvg(
        backOnly("width=\"50mm\" height=\"100mm\"", "M 0 0 L 0 0"), "a.svg", fields());
    // 188.97×377.95 px → scale 1000/377.95; width 500 after scaling, centred: x = 250.
    expectPoint(r.features.spine[3], 250, 1000);
}

TEST(SpeciesSvg, ContentFitCropsToTheImage) {
    SvgImportOptions o = fields();
    o.fit = SvgFit::Content;
    const SpeciesRecord r =
        importSpeciesSvg(backOnly("viewBox=\"0 0 1000 1000\"", "M 300 300 L 500 400",
                                  "<image x=\"100\" y=\"200\" width=\"400\" height=\"200\"/>\n"),
                         "a.svg", o);
    // Box [100, 500] × [200, 400], scale 2.5: x' = 2.5x − 250, y' = (400 − y)·2.5.
    expectPoint(r.features.spine[3], 500, 250);
    expectPoint(r.features.spine[6], 1000, 0);
}

TEST(SpeciesSvg, ContentFitWithoutAnImageUsesTheAnnotations) {
    SvgImportOptions o = fields();
    o.fit = SvgFit::Content;
    const SpeciesRecord r =
        importSpeciesSvg(backOnly("viewBox=\"0 0 1000 1000\"", "M 10 20 L 110 70"), "a.svg", o);
    // Box 100×50 → scale 10, width 1000; bottom (y = 70) at 0.
    expectPoint(r.features.spine[3], 0, 500);
    expectPoint(r.features.spine[6], 1000, 0);
}

TEST(SpeciesSvg, NoFitOnlyFlipsY) {
    SvgImportOptions o = fields();
    o.fit = SvgFit::None;
    const SpeciesRecord r =
        importSpeciesSvg(backOnly("viewBox=\"0 0 2000 800\"", "M 10 20 L 1500 70"), "a.svg", o);
    expectPoint(r.features.spine[3], 10, 780);
    expectPoint(r.features.spine[6], 1500, 730);
}

TEST(SpeciesSvg, YUpCoordinatesAreNotFlipped) {
    SvgImportOptions o = fields();
    o.yUp = true;
    const SpeciesRecord r =
        importSpeciesSvg(backOnly("viewBox=\"0 0 1000 1000\"", "M 100 200 L 400 300"), "a.svg", o);
    expectPoint(r.features.spine[3], 100, 200);
    expectPoint(r.features.spine[6], 400, 300);
}

TEST(SpeciesSvg, LineAndPolylineElementsMeasureLimbs) {
    const SpeciesRecord r = importSpeciesSvg(
        backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0",
                 "<line id=\"hand\" x1=\"0\" y1=\"0\" x2=\"3\" y2=\"4\"/>\n"
                 "<polyline id=\"foot\" points=\"0,0 3,4 3,10\"/>\n"
                 "<g transform=\"scale(2)\"><path id=\"shank\" d=\"M 0 0 h 10\"/></g>\n"),
        "a.svg", fields());
    EXPECT_DOUBLE_EQ(r.features.limb(Limb::Hand), 5);
    EXPECT_DOUBLE_EQ(r.features.limb(Limb::Foot), 11);
    EXPECT_DOUBLE_EQ(r.features.limb(Limb::Shank), 20);
}

TEST(SpeciesSvg, PathsInDefsAreIgnored) {
    const SpeciesRecord r = importSpeciesSvg(
        backOnly(
            "viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0",
            "<defs><path id=\"hand\" d=\"M 0 0 L 0 50\"/><path id=\"back\" d=\"M 0 0\"/></defs>\n"),
        "a.svg", fields());
    EXPECT_EQ(r.features.limb(Limb::Hand), 0);
}

TEST(SpeciesSvg, FieldsComeFromRamusAttributesWhenNotGiven) {
    const SpeciesRecord r = importSpeciesSvg(
        backOnly(
            "xmlns:ramus=\"urn:ramus:species:1\" viewBox=\"0 0 1000 1000\" ramus:name=\"Gecko\" "
            "ramus:class=\"reptile\" ramus:wings=\"0\" ramus:legs=\"2\" ramus:weight-kg=\"0.05\"",
            "M 0 0 L 1 0"),
        "a.svg", SvgImportOptions{});
    EXPECT_EQ(r.name, "Gecko");
    EXPECT_EQ(r.features.weightKg, 0.05);
}

TEST(SpeciesSvg, OptionsOverrideAttributes) {
    SvgImportOptions o = fields();
    o.name = "Override";
    const SpeciesRecord r = importSpeciesSvg(
        backOnly("viewBox=\"0 0 1000 1000\" ramus:name=\"Gecko\"", "M 0 0 L 1 0"), "a.svg", o);
    EXPECT_EQ(r.name, "Override");
}

TEST(SpeciesSvg, MissingBackIsAnError) {
    const std::string svg =
        std::string(kHeader) + "viewBox=\"0 0 10 10\"><path id=\"neck\" d=\"M 0 0 L 1 1\"/></svg>";
    EXPECT_CONTAINS(importError(svg), "a.svg: no path named \"back\"");
}

TEST(SpeciesSvg, SpineCurveWithTwoSegmentsIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0 L 2 0")),
                    "\"back\" must be one cubic Bézier (or line), got 2 segments");
}

TEST(SpeciesSvg, ArcSpineIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 A 5 5 0 0 1 10 0")),
                    "is an arc");
}

TEST(SpeciesSvg, DuplicateNameIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0",
                                         "<path inkscape:label=\"back\" d=\"M 0 0 L 1 0\"/>\n")),
                    "a.svg:3:1: a second element named \"back\" (the first is at line 2)");
}

TEST(SpeciesSvg, NonPathAnnotationIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0",
                                         "<rect id=\"hand\" width=\"3\" height=\"4\"/>\n")),
                    "\"hand\" is a <rect>; expected a <path>, <line> or <polyline>");
}

TEST(SpeciesSvg, BadPathDataNamesTheElement) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 C 1 2 3")),
                    "a.svg:2:1: bad path data for \"back\": at character 14: expected a number");
}

TEST(SpeciesSvg, BadTransformNamesTheElement) {
    EXPECT_CONTAINS(
        importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0",
                             "<g transform=\"spin(3)\"><path id=\"hand\" d=\"M 0 0\"/></g>\n")),
        "bad transform \"spin(3)\"");
}

TEST(SpeciesSvg, MalformedXmlIsAnError) {
    EXPECT_CONTAINS(
        importError("<svg viewBox=\"0 0 10 10\">\n<path id=\"back\" d=\"M 0 0\">\n</svg>"),
        "a.svg:3:1: mismatched end tag");
}

TEST(SpeciesSvg, RootMustBeSvg) {
    EXPECT_CONTAINS(importError("<html/>"), "expected the root element <svg>, got <html>");
}

TEST(SpeciesSvg, DocumentWithoutSizeIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("", "M 0 0 L 1 0")), "neither a viewBox nor a width");
}

TEST(SpeciesSvg, BadViewBoxIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 -5 10\"", "M 0 0 L 1 0")),
                    "viewBox width and height must be > 0");
}

TEST(SpeciesSvg, NeckFarFromTheShoulderIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 300 500 L 600 500",
                                         "<path id=\"neck\" d=\"M 100 300 L 200 400\"/>\n")),
                    "\"neck\" does not meet the back at the shoulder (141 px apart");
}

TEST(SpeciesSvg, OverflowingTransformIsAnError) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0",
                                         "<g transform=\"scale(1e300)\"><path id=\"hand\" "
                                         "d=\"M 0 0 L 1e300 1e300\"/></g>\n")),
                    "coordinates overflow");
}

TEST(SpeciesSvg, MissingWeightIsAnError) {
    SvgImportOptions o = fields();
    o.weightKg.reset();
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0"), o),
                    "missing weight: the SVG has no ramus:weight-kg attribute");
}

TEST(SpeciesSvg, MissingNameIsAnError) {
    SvgImportOptions o = fields();
    o.name.reset();
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1 0"), o),
                    "missing name");
}

TEST(SpeciesSvg, BadClassAttributeIsAnError) {
    SvgImportOptions o = fields();
    o.animalClass.reset();
    EXPECT_CONTAINS(
        importError(backOnly("viewBox=\"0 0 1000 1000\" ramus:class=\"dragon\"", "M 0 0 L 1 0"), o),
        "bad ramus:class \"dragon\"");
}

TEST(SpeciesSvg, NegativeLegsAttributeIsAnError) {
    SvgImportOptions o = fields();
    o.legs.reset();
    EXPECT_CONTAINS(
        importError(backOnly("viewBox=\"0 0 1000 1000\" ramus:legs=\"-2\"", "M 0 0 L 1 0"), o),
        "bad ramus:legs \"-2\"; expected a number >= 0");
}

TEST(SpeciesSvg, RoundTripIsLosslessForEveryShippedSpecies) {
    const char* out = std::getenv("RAMUS_TEST_OUTPUT");
    for (const SpeciesRecord& record : builtinSpecies()) {
        const std::string svg = exportSpeciesSvg(record);
        EXPECT_EQ(importSpeciesSvg(svg, record.name + ".svg"), record) << record.name;
        if (out) {
            std::string file = record.name;
            for (char& c : file) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
            writeFileAtomic(std::string(out) + "/species_" + file + ".svg", svg);
        }
    }
}

TEST(SpeciesSvg, RoundTripIsLosslessForAwkwardRecords) {
    SpeciesRecord r;
    r.name = "A <strange> & \"quoted\" name";
    r.nameDe = "Ünïcödé";
    r.animalClass = AnimalClass::Fish;
    r.notes = "line\nbreak";
    r.features.wings = 0.3;
    r.features.legs = 1.0 / 3.0;
    r.features.weightKg = 1e-3;
    // Facing +x, no neck and no tail, negative and fractional coordinates.
    for (int i = 0; i < 10; ++i) {
        r.features.spine[i] = i < 3   ? Vec2(700.1, -3.3)
                              : i > 6 ? Vec2(0.1 + 0.2, 5e-7)
                                      : Vec2(0, 0);
    }
    r.features.spine[3] = Vec2(700.1, -3.3);
    r.features.spine[4] = Vec2(500.123456789, 12.5);
    r.features.spine[5] = Vec2(1.0 / 7.0, 1e6);
    r.features.spine[6] = Vec2(0.1 + 0.2, 5e-7);
    r.features.limbs = {0.1, 1.0 / 3.0, 0, 1e-9, 987.654321, 2.0 / 3.0};
    EXPECT_EQ(importSpeciesSvg(exportSpeciesSvg(r), "r.svg"), r);
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

// Non-finite numbers in SVG annotations are refused where they are read.
TEST(SpeciesSvgNonFinite, PathDataBeyondDoubleRangeNamesTheElement) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 1000 1000\"", "M 0 0 L 1e999 0")),
                    "a.svg:2:1: bad path data for \"back\": at character 9: expected a number");
}

TEST(SpeciesSvgNonFinite, ViewBoxWithInfinityIsRefused) {
    EXPECT_CONTAINS(importError(backOnly("viewBox=\"0 0 inf 1000\"", "M 0 0 L 1 0")),
                    "bad viewBox \"0 0 inf 1000\"; expected 4 numbers");
}

TEST(SpeciesSvgNonFinite, SizeAttributesMustBeFiniteNumbers) {
    EXPECT_CONTAINS(importError(backOnly("width=\"1e999\" height=\"10\"", "M 0 0 L 1 0")), "width");
}

TEST(SpeciesSvgNonFinite, RamusAttributesMustBeFiniteNumbers) {
    SvgImportOptions o = fields();
    o.weightKg.reset();
    for (const char* value : {"nan", "inf", "1e999"}) {
        EXPECT_CONTAINS(
            importError(backOnly(std::string("viewBox=\"0 0 1000 1000\" "
                                             "ramus:weight-kg=\"") +
                                     value + "\"",
                                 "M 0 0 L 1 0"),
                        o),
            std::string("bad ramus:weight-kg \"") + value + "\"; expected a number >= 0");
    }
}

}  // namespace
}  // namespace ramus
