// Geometric invariants of individual example L-systems: the Koch island closes and has 4-fold
// symmetry, ABOP 1.24f reaches 6.46 M modules at n = 10, tropism bends towards T without
// changing lengths, `!` widths follow their rules, and the bush's leaves are hexagons.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "examples_support.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/turtle.hpp"

namespace ramus::test {
namespace {

TurtleResult interpretExample(const std::string& file, int derivations = -1) {
    const LSystem system = loadExample(file);
    DeriveOptions options;
    options.derivations = derivations;
    return interpretTurtle(deriveLSystem(system, options), system.symbols,
                           turtleParamsFrom(system.settings));
}

double sizeOf(const BranchTree& tree) { return tree.bounds().extent().maxCoeff(); }

TEST(Examples, KochIslandHasFourTimesEightToTheNEdgesOfUnitLength) {
    for (int n = 0; n <= 4; ++n) {
        const TurtleResult turtle = interpretExample("koch_island.lsys", n);
        const auto edges = static_cast<std::size_t>(4 * std::pow(8, n));
        ASSERT_EQ(turtle.tree.edgeCount(), edges) << "n = " << n;
        for (std::size_t i = 1; i < turtle.tree.size(); ++i) {
            const BranchNode& node = turtle.tree.node(static_cast<NodeId>(i));
            ASSERT_EQ(node.parent, static_cast<NodeId>(i - 1));  // one unbranched polyline
            ASSERT_NEAR((node.position - turtle.tree.node(node.parent).position).norm(), 1.0,
                        1e-12);
        }
        EXPECT_NEAR(drawnLength(turtle.tree), static_cast<double>(edges), 1e-9 * edges);
    }
}

TEST(Examples, KochIslandClosesOnItself) {
    for (int n = 0; n <= 4; ++n) {
        const TurtleResult turtle = interpretExample("koch_island.lsys", n);
        const Vec3 first = turtle.tree.node(0).position;
        const Vec3 last = turtle.tree.nodes().back().position;
        EXPECT_LE((last - first).norm(), 1e-9 * sizeOf(turtle.tree)) << "n = " << n;
    }
}

TEST(Examples, KochIslandHasFourFoldRotationalSymmetry) {
    // The axiom F-F-F-F draws the same side four times, each turned 90° clockwise (`-` turns
    // right, seen from +Z): vertex k + N/4 is vertex k rotated by -90° about the centre.
    const TurtleResult turtle = interpretExample("koch_island.lsys", 3);
    const std::size_t count = turtle.tree.size() - 1;  // the last vertex repeats the first
    ASSERT_EQ(count % 4, 0u);
    Vec3 centre = Vec3::Zero();
    for (std::size_t i = 0; i < count; ++i) centre += turtle.tree.node(NodeId(i)).position;
    centre /= static_cast<double>(count);

    const double tolerance = 1e-9 * sizeOf(turtle.tree);
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 p = turtle.tree.node(NodeId(k)).position - centre;
        const Vec3 q = turtle.tree.node(NodeId((k + count / 4) % count)).position - centre;
        ASSERT_NEAR((q - Vec3(p.y(), -p.x(), p.z())).norm(), 0.0, tolerance) << "vertex " << k;
    }
}

TEST(Examples, Abop124fHas6464679ModulesAfterTenSteps) {
    // X -> F-[[X]+X]+F[+FX]-X (18 modules: 4 X, 3 F, 11 others), F -> FF:
    // X_n = 4^n, F_n = 2 F_(n-1) + 3 X_(n-1) = 3 (4^n - 2^n) / 2, others_n = 11 (4^n - 1) / 3.
    // n = 10: 1 048 576 + 1 571 328 + 3 844 775 = 6 464 679.
    const LSystem system = loadExample("abop_1_24f.lsys");
    DeriveOptions options;
    options.derivations = 10;
    const ModuleString word = deriveLSystem(system, options);
    ASSERT_EQ(word.size(), 6'464'679u);
    const auto counts = countModules(system.symbols, word);
    EXPECT_EQ(counts.at("X"), 1'048'576u);
    EXPECT_EQ(counts.at("F"), 1'571'328u);
    EXPECT_EQ(counts.at("[") + counts.at("]") + counts.at("+") + counts.at("-"), 3'844'775u);
    EXPECT_TRUE(word.params.empty());
}

TEST(Examples, SeedTreeWithTropismKeepsEveryLengthAndBendsEachStepTowardsT) {
    // tropism_mode: blend (seed 002 eq 2.18) moves along normalize(H + e·T) and leaves H alone,
    // so both trees share their headings and every edge keeps its length; each step's
    // component along T can only grow (|H + eT| ≥ 1 - e|T| bounds the shrink of the rest).
    const TurtleResult straight = interpretExample("tree_3d.lsys");
    const TurtleResult bent = interpretExample("tree_3d_tropism.lsys");
    ASSERT_EQ(straight.tree.size(), bent.tree.size());
    const Vec3 towards = Vec3(-1.0, -0.5, 0.0).normalized();
    double gained = 0.0;
    for (std::size_t i = 1; i < bent.tree.size(); ++i) {
        const BranchNode& s = straight.tree.node(NodeId(i));
        const BranchNode& b = bent.tree.node(NodeId(i));
        ASSERT_EQ(s.parent, b.parent);
        const Vec3 ds = s.position - straight.tree.node(s.parent).position;
        const Vec3 db = b.position - bent.tree.node(b.parent).position;
        ASSERT_NEAR(db.norm(), ds.norm(), 1e-9 * ds.norm());
        ASSERT_GE(db.dot(towards), ds.dot(towards) - 1e-9 * ds.norm()) << "edge " << i;
        gained += db.dot(towards) - ds.dot(towards);
    }
    EXPECT_GT(gained, 0.0);

    // The first F(50) (scaled by lr = 1.3 in each of the 7 later steps) starts heading up:
    // it goes along normalize((0,1,0) + 0.27·(-1,-0.5,0)).
    const Vec3 direction = (Vec3(0, 1, 0) + 0.27 * Vec3(-1, -0.5, 0)).normalized();
    const Vec3 expected = 50.0 * std::pow(1.3, 7) * direction;
    EXPECT_NEAR((bent.tree.node(1).position - expected).norm(), 0.0, 1e-9 * expected.norm());
}

TEST(Examples, TernaryTreeTrunkWidthGrowsByVrEachStep) {
    // ω: !(1)F(200)/(45)A and !(w) -> !(w*vr): after n steps the trunk is vr^n wide.
    const std::pair<const char*, int> trees[] = {
        {"abop_2_8a.lsys", 6}, {"abop_2_8b.lsys", 8}, {"abop_2_8c.lsys", 8}, {"abop_2_8d.lsys", 6}};
    for (const auto& [file, n] : trees) {
        const TurtleResult turtle = interpretExample(file);
        const double width = std::pow(1.732, n);
        EXPECT_NEAR(turtle.tree.node(1).radius, 0.5 * width, 1e-9 * width) << file;
    }
}

TEST(Examples, HondaTreeTrunkStartsWithTheAxiomWidthAndThins) {
    // ω: A(1,0.15); A(l,w) -> !(w)F(l)… A(l*r1,w*wr): the k-th trunk internode is
    // 0.15·0.707^(k-1) wide; the first one is node 1.
    const TurtleResult turtle = interpretExample("abop_2_6a.lsys");
    EXPECT_NEAR(turtle.tree.node(1).radius, 0.075, 1e-12);
    NodeId trunk = 1;
    for (int k = 2; k <= 10; ++k) {
        // The trunk continues with the last child created from the apex (after the branch).
        trunk = turtle.tree.node(trunk).lastChild;
        ASSERT_NE(trunk, kNoNode);
        EXPECT_NEAR(turtle.tree.node(trunk).radius, 0.075 * std::pow(0.707, k - 1), 1e-12);
        EXPECT_NEAR((turtle.tree.node(trunk).position -
                     turtle.tree.node(turtle.tree.node(trunk).parent).position)
                        .norm(),
                    std::pow(0.9, k - 1), 1e-12);
    }
}

TEST(Examples, BushLeavesAreClosedHexagonsOnePerLeafModule) {
    // L -> ['''^^{-f+f+f-|-f+f+f}]: the six f moves trace a hexagon that ends where it began.
    const LSystem system = loadExample("abop_1_25.lsys");
    const ModuleString word = deriveLSystem(system);
    const auto counts = countModules(system.symbols, word);
    const TurtleResult turtle =
        interpretTurtle(word, system.symbols, turtleParamsFrom(system.settings));
    ASSERT_EQ(turtle.polygonCount(), counts.at("{"));
    for (std::size_t i = 0; i < turtle.polygonCount(); ++i) {
        ASSERT_EQ(turtle.polygonOffsets[i + 1] - turtle.polygonOffsets[i], 6u) << "leaf " << i;
        for (std::uint32_t v = turtle.polygonOffsets[i]; v + 1 < turtle.polygonOffsets[i + 1];
             ++v) {
            ASSERT_NEAR((turtle.polygonVertices[v + 1] - turtle.polygonVertices[v]).norm(), 1.0,
                        1e-9);
        }
    }
}

}  // namespace
}  // namespace ramus::test
