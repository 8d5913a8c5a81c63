// The small XML reader, the SVG path data parser and transform lists used by the species SVG
// import, checked against hand-computed coordinates.
#include "skeleton/svg_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "ramus/error.hpp"
#include "skeleton/svg_xml.hpp"

namespace ramus::detail {
namespace {

void expectPoint(const Vec2& p, double x, double y) {
    EXPECT_NEAR(p.x(), x, 1e-12);
    EXPECT_NEAR(p.y(), y, 1e-12);
}

std::string errorOf(std::string_view xml) {
    try {
        parseXml(xml, "t.svg");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(SvgPath, AbsoluteCubic) {
    const auto s = parsePathData("M 10,20 C 30,40 50,60 70,80");
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].kind, SegmentKind::Cubic);
    expectPoint(s[0].p0, 10, 20);
    expectPoint(s[0].p1, 30, 40);
    expectPoint(s[0].p2, 50, 60);
    expectPoint(s[0].p3, 70, 80);
}

TEST(SvgPath, RelativeCubicIsOffsetFromTheCurrentPoint) {
    const auto s = parsePathData("m 10 20 c 20 20 40 40 60 60");
    ASSERT_EQ(s.size(), 1u);
    expectPoint(s[0].p1, 30, 40);
    expectPoint(s[0].p3, 70, 80);
}

TEST(SvgPath, ImplicitLinetoAfterMoveto) {
    const auto s = parsePathData("m 1 1 2 0 0 3");
    ASSERT_EQ(s.size(), 2u);
    expectPoint(s[0].p3, 3, 1);
    expectPoint(s[1].p3, 3, 4);
}

TEST(SvgPath, NumbersRunTogether) {
    // "M1-2.5.5-1": moveto (1, -2.5), then an implicit lineto (.5, -1).
    const auto s = parsePathData("M1-2.5.5-1L.5e1-1e-1");
    ASSERT_EQ(s.size(), 2u);
    expectPoint(s[0].p0, 1, -2.5);
    expectPoint(s[0].p3, 0.5, -1);
    expectPoint(s[1].p3, 5, -0.1);
}

TEST(SvgPath, HorizontalAndVerticalLines) {
    const auto s = parsePathData("M 0 0 H 10 v 5 h -3 V 0");
    ASSERT_EQ(s.size(), 4u);
    expectPoint(s[0].p3, 10, 0);
    expectPoint(s[1].p3, 10, 5);
    expectPoint(s[2].p3, 7, 5);
    expectPoint(s[3].p3, 7, 0);
}

TEST(SvgPath, SmoothCubicReflectsThePreviousControlPoint) {
    const auto s = parsePathData("M 0 0 C 0 10 10 10 10 0 S 20 -10 20 0");
    ASSERT_EQ(s.size(), 2u);
    expectPoint(s[1].p1, 10, -10);  // reflection of (10, 10) about (10, 0)
    expectPoint(s[1].p3, 20, 0);
}

TEST(SvgPath, SmoothCubicWithoutAPreviousCubicStartsAtTheCurrentPoint) {
    const auto s = parsePathData("M 5 5 S 20 -10 20 0");
    expectPoint(s[0].p1, 5, 5);
}

TEST(SvgPath, QuadraticAndSmoothQuadratic) {
    const auto s = parsePathData("M 0 0 Q 5 10 10 0 T 20 0");
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].kind, SegmentKind::Quadratic);
    expectPoint(s[1].p1, 15, -10);
}

TEST(SvgPath, ArcFlagsMayBeWrittenTogether) {
    const auto s = parsePathData("M 0 0 a1 1 0 00 1 1");
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].kind, SegmentKind::Arc);
    expectPoint(s[0].p3, 1, 1);
}

TEST(SvgPath, CloseAddsTheClosingLine) {
    const auto s = parsePathData("M 0 0 L 3 0 L 3 4 Z");
    ASSERT_EQ(s.size(), 3u);
    expectPoint(s[2].p3, 0, 0);
}

TEST(SvgPath, SecondMovetoStartsANewSubpath) {
    const auto s = parsePathData("M 0 0 L 1 0 M 5 5 l 1 0");
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[1].subpath, 1);
    expectPoint(s[1].p3, 6, 5);
}

TEST(SvgPath, MustStartWithMoveto) { EXPECT_THROW(parsePathData("L 1 2"), std::invalid_argument); }

TEST(SvgPath, RejectsAMissingCoordinate) {
    try {
        parsePathData("M 1 2 C 3 4 5");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("expected a number"), std::string::npos) << e.what();
    }
}

TEST(SvgPath, RejectsAnUnknownCommand) {
    EXPECT_THROW(parsePathData("M 1 2 X 3 4"), std::invalid_argument);
}

TEST(SvgTransform, TranslateWithOneValue) {
    const Affine2 t = parseTransform("translate(10)");
    expectPoint(t.apply({1, 2}), 11, 2);
}

TEST(SvgTransform, ListAppliesRightmostFirst) {
    const Affine2 t = parseTransform("translate(10,0) scale(2)");
    expectPoint(t.apply({1, 1}), 12, 2);
}

TEST(SvgTransform, RotateAboutACentre) {
    const Affine2 t = parseTransform("rotate(90 10 10)");
    expectPoint(t.apply({20, 10}), 10, 20);
}

TEST(SvgTransform, MatrixAndSkew) {
    expectPoint(parseTransform("matrix(1 0 0 -1 0 1000)").apply({3, 4}), 3, 996);
    expectPoint(parseTransform("skewX(45)").apply({0, 2}), 2, 2);
    expectPoint(parseTransform("skewY(45)").apply({2, 0}), 2, 2);
}

TEST(SvgTransform, SimilarityScale) {
    EXPECT_EQ(parseTransform("translate(5 5) scale(2)").similarityScale(), 2.0);
    EXPECT_EQ(parseTransform("matrix(1 0 0 -1 0 1000)").similarityScale(), 1.0);
    EXPECT_NEAR(parseTransform("rotate(30) scale(3)").similarityScale(), 3.0, 1e-12);
    EXPECT_LT(parseTransform("scale(1 2)").similarityScale(), 0.0);
}

TEST(SvgTransform, RejectsWrongArgumentCounts) {
    EXPECT_THROW(parseTransform("matrix(1 2 3)"), std::invalid_argument);
    EXPECT_THROW(parseTransform("rotate(1 2)"), std::invalid_argument);
    EXPECT_THROW(parseTransform("shear(1)"), std::invalid_argument);
    EXPECT_THROW(parseTransform("translate(1"), std::invalid_argument);
}

TEST(SvgXml, ReadsElementsAttributesAndNesting) {
    const XmlDocument doc = parseXml(
        "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [ <!ENTITY a \"b\"> ]>\n<!-- c -->\n"
        "<svg a='1' b=\"x &amp; &lt;y&gt; &#65;&#x42; &unknown;\">\n  <g>\n    <path d=\"M 0 "
        "0\"/>\n"
        "  </g><![CDATA[ <not/> ]]>\n</svg>\n",
        "t.svg");
    ASSERT_EQ(doc.elements.size(), 3u);
    EXPECT_EQ(doc.elements[0].name, "svg");
    EXPECT_EQ(*doc.elements[0].attribute("a"), "1");
    EXPECT_EQ(*doc.elements[0].attribute("b"), "x & <y> AB &unknown;");
    EXPECT_EQ(doc.elements[2].parent, 1);
    EXPECT_EQ(doc.elements[2].line, 6);
    EXPECT_EQ(doc.elements[2].column, 5);
    EXPECT_EQ(doc.elements[2].localName(), "path");
}

TEST(SvgXml, MismatchedEndTagNamesBothTags) {
    const std::string message = errorOf("<svg>\n<g></svg>");
    EXPECT_NE(message.find("t.svg:2:4: mismatched end tag; expected </g>, got </svg>"),
              std::string::npos)
        << message;
}

TEST(SvgXml, UnclosedElementIsReported) {
    EXPECT_NE(errorOf("<svg><g>").find("unclosed <g>"), std::string::npos);
}

TEST(SvgXml, SecondRootIsReported) {
    EXPECT_NE(errorOf("<svg/><svg/>").find("second root"), std::string::npos);
}

TEST(SvgXml, EmptyDocumentIsReported) {
    EXPECT_NE(errorOf("  <!-- only a comment -->").find("no root element"), std::string::npos);
}

TEST(SvgXml, UnterminatedCommentIsReported) {
    EXPECT_NE(errorOf("<svg><!-- x").find("unterminated comment"), std::string::npos);
}

TEST(SvgXml, UnquotedAttributeIsReported) {
    EXPECT_NE(errorOf("<svg a=1/>").find("expected a quoted value"), std::string::npos);
}

TEST(SvgXml, DeepNestingIsLimited) {
    std::string deep;
    for (int i = 0; i < 300; ++i) deep += "<g>";
    EXPECT_NE(errorOf(deep).find("nested deeper than 256"), std::string::npos);
}

TEST(SvgXml, EscapeXml) { EXPECT_EQ(escapeXml("a<b>&\"c"), "a&lt;b&gt;&amp;&quot;c"); }

}  // namespace
}  // namespace ramus::detail
