// Tests of the shipped example L-systems (examples/lsystems): every deterministic file derives
// to the module counts of its production matrix, draws the total length its rules imply, and
// interprets and meshes cleanly. Expected values are computed here from the rules as written
// in each file's header (ABOP / seed 002), not from the library.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "examples_support.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/turtle.hpp"

namespace ramus::test {
namespace {

// s(k) = 1 + ratio·s(k-1), s(0) = 0: relative length of an axis whose every module draws its
// length l and passes l·ratio on to its only growing successor (summed per branch below).
double geometricSum(double ratio, int k) {
    double s = 0.0;
    for (int i = 0; i < k; ++i) s = 1.0 + ratio * s;
    return s;
}

// ABOP fig 2.6 (Honda): A(l) draws l, spawns B(l·r2) and A(l·r1); B and C draw l and spawn two
// of each other with l·r2 and l·r1. Total drawn length of ω = A(1) after n steps.
double hondaLength(double r1, double r2, int n) {
    double a = 0.0;
    for (int k = 1; k <= n; ++k) a = 1.0 + r2 * geometricSum(r1 + r2, k - 1) + r1 * a;
    return a;
}

// Seed 002 eq 2.17 / ABOP fig 2.8: each A adds four F(50); an F made at step k is scaled by
// lr in each of the remaining n - k steps. There are 3^(k-1) A's before step k.
double ternaryLength(double lr, int n) {
    double sum = 0.0;
    for (int k = 1; k <= n; ++k) {
        sum += 4.0 * std::pow(3.0, k - 1) * 50.0 * std::pow(lr, n - k);
    }
    return sum;
}

// Seed 002 eq 5.1: ω = F(100)A(100); A(l) draws l, spawns B(l) and A(l·r1); B(l) draws l and
// spawns two B(l·r2).
double monopodialLength(double r1, double r2, int n) {
    double a = 0.0;
    for (int k = 1; k <= n; ++k) a = 1.0 + geometricSum(2.0 * r2, k - 1) + r1 * a;
    return 100.0 + 100.0 * a;
}

struct ExampleCase {
    std::string file;
    int derivations;
    CountRecurrence counts;
    bool planar;                     // only + - turns: the drawing stays in the z = 0 plane
    std::function<double()> length;  // total drawn length; empty = (number of F) · step 1
};

std::vector<ExampleCase> exampleCases() {
    const CountRecurrence honda{"A", {{'A', "!F[&B]/A"}, {'B', "!F[-$C]C"}, {'C', "!F[+$B]B"}}};
    const CountRecurrence aonoKunii{"A", {{'A', "!F[&B]/[&B]"}, {'B', "!F[+$B][-$B]"}}};
    const CountRecurrence ternary{"!F/A", {{'A', "!F[&FA]/[&FA]/[&FA]"}}};
    const CountRecurrence tree3d{"/A", {{'A', "F[&FA]/[&FA]/[&FA]"}}};
    const auto aonoKuniiLength = [](double r1, double r2) {
        return [=] { return geometricSum(r1 + r2, 10); };
    };
    const auto ternaryWithTrunk = [](double lr, int n) {
        return [=] { return 200.0 * std::pow(lr, n) + ternaryLength(lr, n); };
    };
    return {
        {"koch_island.lsys", 3, {"F-F-F-F", {{'F', "F+F-F-FF+F+F-F"}}}, true, {}},
        {"abop_1_24a.lsys", 5, {"F", {{'F', "F[+F]F[-F]F"}}}, true, {}},
        {"abop_1_24b.lsys", 5, {"F", {{'F', "F[+F]F[-F][F]"}}}, true, {}},
        {"abop_1_24c.lsys", 4, {"F", {{'F', "FF-[-F+F+F]+[+F-F-F]"}}}, true, {}},
        {"abop_1_24d.lsys", 7, {"X", {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}}, true, {}},
        {"abop_1_24e.lsys", 7, {"X", {{'X', "F[+X][-X]FX"}, {'F', "FF"}}}, true, {}},
        {"abop_1_24f.lsys", 5, {"X", {{'X', "F-[[X]+X]+F[+FX]-X"}, {'F', "FF"}}}, true, {}},
        {"abop_1_25.lsys",
         7,
         {"A",
          {{'A', "[&FL!A]/////'[&FL!A]///////'[&FL!A]"},
           {'F', "S/////F"},
           {'S', "FL"},
           {'L', "['''^^{-f+f+f-|-f+f+f}]"}}},
         false,
         {}},
        {"abop_2_6a.lsys", 10, honda, false, [] { return hondaLength(0.9, 0.6, 10); }},
        {"abop_2_6b.lsys", 10, honda, false, [] { return hondaLength(0.9, 0.9, 10); }},
        {"abop_2_6c.lsys", 10, honda, false, [] { return hondaLength(0.9, 0.8, 10); }},
        {"abop_2_6d.lsys", 10, honda, false, [] { return hondaLength(0.9, 0.7, 10); }},
        {"abop_2_7a.lsys", 10, aonoKunii, false, aonoKuniiLength(0.9, 0.7)},
        {"abop_2_7b.lsys", 10, aonoKunii, false, aonoKuniiLength(0.9, 0.7)},
        {"abop_2_7c.lsys", 10, aonoKunii, false, aonoKuniiLength(0.9, 0.8)},
        {"abop_2_7d.lsys", 10, aonoKunii, false, aonoKuniiLength(0.9, 0.8)},
        {"abop_2_8a.lsys", 6, ternary, false, ternaryWithTrunk(1.109, 6)},
        {"abop_2_8b.lsys", 8, ternary, false, ternaryWithTrunk(1.109, 8)},
        {"abop_2_8c.lsys", 8, ternary, false, ternaryWithTrunk(1.790, 8)},
        {"abop_2_8d.lsys", 6, ternary, false, ternaryWithTrunk(1.070, 6)},
        {"tree_3d.lsys", 8, tree3d, false, [] { return ternaryLength(1.3, 8); }},
        {"tree_3d_tropism.lsys", 8, tree3d, false, [] { return ternaryLength(1.3, 8); }},
        {"monopodial.lsys",
         10,
         {"FA", {{'A', "F[&B]/A"}, {'B', "F[-B]/B"}}},
         false,
         [] { return monopodialLength(0.9, 0.6, 10); }},
        {"sympodial.lsys",
         10,
         {"FA", {{'A', "F[&B]/[&B]"}, {'B', "F[+/B][-\\B]"}}},
         false,
         [] { return 100.0 + 150.0 * geometricSum(0.9 + 0.7, 10); }},
    };
}

class ExampleFile : public testing::TestWithParam<ExampleCase> {};

std::string caseName(const testing::TestParamInfo<ExampleCase>& info) {
    return info.param.file.substr(0, info.param.file.size() - 5);  // drop ".lsys"
}

TEST_P(ExampleFile, HasTheDerivationCountOfItsSource) {
    EXPECT_EQ(loadExample(GetParam().file).settings.derivations, GetParam().derivations);
}

TEST_P(ExampleFile, DerivesToTheModuleCountsOfItsProductionMatrix) {
    const ExampleCase& c = GetParam();
    const LSystem system = loadExample(c.file);
    const ModuleString word = deriveLSystem(system);
    const auto expected = c.counts.after(c.derivations);
    const auto actual = countModules(system.symbols, word);

    EXPECT_EQ(word.size(), c.counts.total(c.derivations));
    for (int b = 0; b < 256; ++b) {
        if (expected[b] == 0) continue;
        const std::string name(1, static_cast<char>(b));
        const auto it = actual.find(name);
        EXPECT_EQ(it == actual.end() ? 0 : it->second, expected[b]) << "module " << name;
    }
    for (const auto& [name, count] : actual) {
        EXPECT_TRUE(name.size() == 1 && expected[static_cast<unsigned char>(name[0])] == count)
            << "unexpected module " << name << " ×" << count;
    }
}

TEST_P(ExampleFile, DrawsTheTotalLengthItsRulesImply) {
    const ExampleCase& c = GetParam();
    const LSystem system = loadExample(c.file);
    const TurtleResult turtle =
        interpretTurtle(deriveLSystem(system), system.symbols, turtleParamsFrom(system.settings));
    const double expected =
        c.length ? c.length()
                 : static_cast<double>(c.counts.after(c.derivations)['F']) * system.settings.step;
    EXPECT_NEAR(drawnLength(turtle.tree), expected, 1e-9 * expected);
    // One node per F: drawing moves (f) only occur inside leaf polygons in these files.
    EXPECT_EQ(turtle.tree.size(), c.counts.after(c.derivations)['F'] + 1);
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleFile, testing::ValuesIn(exampleCases()), caseName);

TEST(Examples, TwoDimensionalSystemsStayInTheXyPlane) {
    // Only + and - turn these turtles: rotations about U = +Z keep every point at z = 0.
    std::vector<std::string> planar = {"abop_1_27.lsys", "abop_1_31a.lsys"};
    for (const ExampleCase& c : exampleCases()) {
        if (c.planar) planar.push_back(c.file);
    }
    ASSERT_EQ(planar.size(), 9u);
    for (const std::string& file : planar) {
        const LSystem system = loadExample(file);
        const TurtleResult turtle = interpretTurtle(deriveLSystem(system), system.symbols,
                                                    turtleParamsFrom(system.settings));
        for (const BranchNode& node : turtle.tree.nodes()) {
            ASSERT_EQ(node.position.z(), 0.0) << file;
        }
    }
}

TEST(Examples, EveryFileIsCoveredByACountTest) {
    // Stochastic (1.27) and context-sensitive (1.31a) systems have their own tests.
    std::vector<std::string> covered = {"abop_1_27.lsys", "abop_1_31a.lsys"};
    for (const ExampleCase& c : exampleCases()) covered.push_back(c.file);
    for (const std::string& file : listExampleFiles()) {
        EXPECT_NE(std::find(covered.begin(), covered.end(), file), covered.end()) << file;
    }
    EXPECT_EQ(listExampleFiles().size(), covered.size());
}

// Every file in examples/lsystems, including ones added later, goes all the way to a mesh.
class ExamplePipeline : public testing::TestWithParam<std::string> {};

TEST_P(ExamplePipeline, DerivesInterpretsAndMeshesWithFinitePositions) {
    const std::string& file = GetParam();
    const LSystem system = loadExample(file);
    const ModuleString word = deriveLSystem(system);
    ASSERT_GT(word.size(), 0u);
    const TurtleResult turtle =
        interpretTurtle(word, system.symbols, turtleParamsFrom(system.settings));
    ASSERT_GT(turtle.tree.size(), 1u);
    EXPECT_TRUE(allFinite(turtle.tree));

    Mesh mesh = buildTubeMesh(turtle.tree);
    EXPECT_GT(mesh.triangleCount(), 0u);
    EXPECT_TRUE(isWellFormed(mesh));
    if (turtle.polygonCount() > 0) {
        const Mesh leaves = buildPolygonMesh(turtle.polygonVertices, turtle.polygonOffsets);
        EXPECT_GT(leaves.triangleCount(), 0u);
        EXPECT_TRUE(isWellFormed(leaves));
        appendMesh(mesh, leaves);
    }
    writeGlbIfRequested(mesh, "example_" + file.substr(0, file.size() - 5));
}

INSTANTIATE_TEST_SUITE_P(Examples, ExamplePipeline, testing::ValuesIn(listExampleFiles()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             return info.param.substr(0, info.param.size() - 5);
                         });

}  // namespace
}  // namespace ramus::test
