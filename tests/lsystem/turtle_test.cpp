#include "ramus/turtle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace ramus {
namespace {

// Builds a word from single-character modules with optional arguments, e.g.
// word("F+F", {{}, {90}, {}}) — independent of the parser so the turtle is tested on its own.
struct WordBuilder {
    SymbolTable symbols;
    ModuleString word;

    WordBuilder& add(const std::string& name, std::initializer_list<double> args = {}) {
        int id = symbols.find(name);
        if (id < 0) {
            id = static_cast<int>(symbols.names.size());
            symbols.names.push_back(name);
        }
        Module m;
        m.symbol = static_cast<std::uint32_t>(id);
        m.paramOffset = static_cast<std::uint32_t>(word.params.size());
        m.paramCount = static_cast<std::uint16_t>(args.size());
        word.params.insert(word.params.end(), args.begin(), args.end());
        word.modules.push_back(m);
        return *this;
    }
    WordBuilder& chars(const std::string& text) {
        for (char c : text) add(std::string(1, c));
        return *this;
    }
    TurtleResult run(const TurtleParams& params = {}) const {
        return interpretTurtle(word, symbols, params);
    }
};

constexpr double kEps = 1e-9;

TEST(Turtle, StartsAtTheOriginHeadingUp) {
    WordBuilder b;
    b.add("F", {2.0});
    const TurtleResult r = b.run();
    ASSERT_EQ(r.tree.size(), 2u);
    EXPECT_TRUE(r.tree.node(0).position.isZero());
    EXPECT_NEAR((r.tree.node(1).position - Vec3(0, 2, 0)).norm(), 0.0, kEps);
}

TEST(Turtle, PlusTurnsLeftSeenFromTheFront) {
    // Front view looks along −Z, so the turtle's left (−X at start) is the viewer's left.
    WordBuilder b;
    b.add("+", {90}).add("F", {1});
    EXPECT_NEAR((b.run().tree.node(1).position - Vec3(-1, 0, 0)).norm(), 0.0, kEps);
}

TEST(Turtle, PitchDownTiltsTowardsMinusUp) {
    WordBuilder b;
    b.add("&", {90}).add("F", {1});
    EXPECT_NEAR((b.run().tree.node(1).position - Vec3(0, 0, -1)).norm(), 0.0, kEps);
}

TEST(Turtle, RollKeepsTheHeading) {
    WordBuilder b;
    b.add("/", {37}).add("\\", {11}).add("F", {1});
    EXPECT_NEAR((b.run().tree.node(1).position - Vec3(0, 1, 0)).norm(), 0.0, kEps);
}

TEST(Turtle, RollThenTurnMatchesTheSeedsMatrices) {
    // seed 002 eq 2.15 then 2.11: R' = R_H(90) · R_U(90) applied to the start frame.
    // After \(90) L = −U_start·(−1)… computed by hand: L becomes −Z, so + heads to −Z.
    WordBuilder b;
    b.add("\\", {90}).add("+", {90}).add("F", {1});
    EXPECT_NEAR((b.run().tree.node(1).position - Vec3(0, 0, -1)).norm(), 0.0, kEps);
}

TEST(Turtle, DefaultsApplyWithoutArguments) {
    TurtleParams params;
    params.defaultStep = 3;
    params.defaultAngleDegrees = 90;
    WordBuilder b;
    b.chars("F-F");
    const TurtleResult r = b.run(params);
    EXPECT_NEAR((r.tree.node(2).position - Vec3(3, 3, 0)).norm(), 0.0, kEps);
}

TEST(Turtle, SquareCloses) {
    WordBuilder b;
    b.chars("F+F+F+F");
    const TurtleResult r = b.run();
    EXPECT_NEAR(r.tree.node(4).position.norm(), 0.0, kEps);
}

TEST(Turtle, BracketsRestorePositionOrientationAndNode) {
    WordBuilder b;
    b.chars("F[+F]F");
    const TurtleResult r = b.run();
    ASSERT_EQ(r.tree.size(), 4u);
    EXPECT_EQ(r.tree.node(2).parent, 1);
    EXPECT_EQ(r.tree.node(3).parent, 1);
    EXPECT_NEAR((r.tree.node(3).position - Vec3(0, 2, 0)).norm(), 0.0, kEps);
    // seed 002 eq 3.7: the bracketed branch was the fork's first child, the axis its second.
    EXPECT_EQ(r.tree.node(2).branchDepth, 0u);
    EXPECT_EQ(r.tree.node(3).branchDepth, 1u);
}

TEST(Turtle, UnbalancedCloseBracketIsIgnored) {
    WordBuilder b;
    b.chars("F]]F");
    EXPECT_EQ(b.run().tree.size(), 3u);
}

TEST(Turtle, LowercaseFMovesWithAHiddenEdge) {
    WordBuilder b;
    b.chars("FfF");
    const TurtleResult r = b.run();
    ASSERT_EQ(r.tree.size(), 4u);
    EXPECT_FALSE(r.tree.node(1).hidden);
    EXPECT_TRUE(r.tree.node(2).hidden);
    EXPECT_FALSE(r.tree.node(3).hidden);
    EXPECT_NEAR(r.tree.node(3).position.y(), 3.0, kEps);
}

TEST(Turtle, PipeTurnsAround) {
    WordBuilder b;
    b.chars("F|F");
    EXPECT_NEAR(b.run().tree.node(2).position.norm(), 0.0, kEps);
}

TEST(Turtle, WidthSetsTheRadiusOfFollowingEdges) {
    WordBuilder b;
    b.add("!", {4}).add("F").add("[").add("!", {2}).add("F").add("]").add("F").add("!").add("F");
    const TurtleResult r = b.run();
    EXPECT_DOUBLE_EQ(r.tree.node(1).radius, 2.0);
    EXPECT_DOUBLE_EQ(r.tree.node(2).radius, 1.0);
    EXPECT_DOUBLE_EQ(r.tree.node(3).radius, 2.0);  // width restored by `]`
    EXPECT_DOUBLE_EQ(r.tree.node(4).radius, 2.0 * 0.7);
}

TEST(Turtle, DollarRollsLeftIntoTheHorizontalPlane) {
    WordBuilder b;
    // Pitch and roll into an arbitrary frame, level it, then a 90° turn must stay horizontal
    // relative to the heading: the turn moves only within the plane spanned by H and level L.
    b.add("&", {30}).add("/", {50}).add("$").add("+", {90}).add("F", {1});
    const Vec3 p = b.run().tree.node(1).position;
    EXPECT_NEAR(p.y(), 0.0, kEps);  // L is horizontal after `$`
    EXPECT_NEAR(p.norm(), 1.0, kEps);
}

TEST(Turtle, OtherSymbolsAreIgnored) {
    WordBuilder b;
    b.chars("AF'~BF;");
    EXPECT_EQ(b.run().tree.size(), 3u);
}

TEST(Turtle, PolygonRecordsTracedVertices) {
    WordBuilder b;
    // ABOP fig 1.25's leaf shape: moves inside { } trace vertices, no tree nodes are made.
    b.chars("F{-f+f+f-|-f+f+f}");
    TurtleParams params;
    params.defaultAngleDegrees = 22.5;
    const TurtleResult r = b.run(params);
    EXPECT_EQ(r.tree.size(), 2u);
    ASSERT_EQ(r.polygonCount(), 1u);
    EXPECT_EQ(r.polygonOffsets[1] - r.polygonOffsets[0], 6u);  // start + 6 moves − closing
}

TEST(Turtle, PolygonWithExplicitVerticesAndSilentMoves) {
    WordBuilder b;
    b.chars("{.G.+G.+G.}");
    TurtleParams params;
    params.defaultAngleDegrees = 120;
    const TurtleResult r = b.run(params);
    ASSERT_EQ(r.polygonCount(), 1u);
    EXPECT_EQ(r.polygonOffsets[1], 3u);  // the last G returns to the start: kept once
}

TEST(Turtle, DegeneratePolygonsAreDropped) {
    WordBuilder b;
    b.chars("{.}{.f.}F");
    const TurtleResult r = b.run();
    EXPECT_EQ(r.polygonCount(), 0u);
    EXPECT_EQ(r.tree.size(), 2u);
}

TEST(Turtle, BlendTropismBendsTheStepButNotTheHeading) {
    TurtleParams params;
    params.tropism = Vec3(1, 0, 0);
    params.susceptibility = 1.0;
    params.tropismMode = TropismMode::Blend;
    WordBuilder b;
    b.chars("FF");
    const TurtleResult r = b.run(params);
    const Vec3 expected = Vec3(1, 1, 0).normalized();  // eq 2.18 with H = +Y, e·T = +X
    EXPECT_NEAR((r.tree.node(1).position - expected).norm(), 0.0, kEps);
    EXPECT_NEAR((r.tree.node(2).position - 2 * expected).norm(), 0.0, kEps);
}

TEST(Turtle, RotateTropismAccumulatesTowardsT) {
    TurtleParams params;
    params.tropism = Vec3(1, 0, 0);
    params.susceptibility = 0.2;
    WordBuilder b;
    for (int i = 0; i < 200; ++i) b.add("F");
    const TurtleResult r = b.run(params);
    // First step is straight (bending happens after a drawn step), second turned by e·|H×T|.
    EXPECT_NEAR((r.tree.node(1).position - Vec3(0, 1, 0)).norm(), 0.0, kEps);
    const Vec3 d2 = r.tree.node(2).position - r.tree.node(1).position;
    EXPECT_NEAR(std::acos(d2.normalized().dot(Vec3::UnitY())), 0.2, 1e-9);
    // After many steps the heading converges to T.
    const Vec3 last = r.tree.node(200).position - r.tree.node(199).position;
    EXPECT_GT(last.normalized().dot(Vec3::UnitX()), 0.999);
}

TEST(Turtle, ManyRotationsStayOrthonormal) {
    WordBuilder b;
    for (int i = 0; i < 10000; ++i) b.add("&", {13.7}).add("/", {29.3}).add("+", {7.1});
    b.add("F", {1});
    EXPECT_NEAR(b.run().tree.node(1).position.norm(), 1.0, 1e-12);
}

TEST(Turtle, EmptyWordGivesARootOnly) {
    WordBuilder b;
    const TurtleResult r = b.run();
    EXPECT_EQ(r.tree.size(), 1u);
    EXPECT_EQ(r.polygonCount(), 0u);
}

}  // namespace
}  // namespace ramus
