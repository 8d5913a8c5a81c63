// Tests of parallel derivation: word lengths and values against hand-computed results,
// conditions, rule order, stochastic rules, the cut symbol, limits and errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lsystem/derive_text.hpp"
#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"

namespace ramus {
namespace {

using test::derive;

using ::testing::HasSubstr;

std::string deriveError(const std::string& text, const DeriveOptions& o = {}) {
    try {
        LSystem s = parseLSystem(text, "d.lsys");
        deriveLSystem(s, o);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

std::size_t count(const LSystem& s, const ModuleString& w, const std::string& name) {
    std::size_t n = 0;
    for (const Module& m : w.modules) n += s.symbols.names[m.symbol] == name;
    return n;
}

TEST(LSystemDerive, AlgaeLengthsAreFibonacciNumbers) {
    // ABOP §1.2: A -> AB, B -> A gives |w_n| = Fib(n + 2).
    LSystem s = parseLSystem("axiom: A\nA -> AB\nB -> A");
    std::size_t a = 1, b = 2;
    for (int n = 0; n <= 25; ++n) {
        DeriveOptions o;
        o.derivations = n;
        EXPECT_EQ(deriveLSystem(s, o).size(), a) << "n = " << n;
        std::size_t c = a + b;
        a = b;
        b = c;
    }
    EXPECT_EQ(derive("axiom: A\nA -> AB\nB -> A", 5), "ABAABABAABAAB");
}

TEST(LSystemDerive, KochIslandLengthFollowsItsRecurrence) {
    // F -> F+F-F-FF+F+F-F: every F becomes 8 F and 6 turns; turns are copied.
    LSystem s = parseLSystem("axiom: F-F-F-F\nF -> F+F-F-FF+F+F-F\nangle: 90");
    std::size_t f = 4, turns = 3;
    for (int n = 0; n <= 5; ++n) {
        DeriveOptions o;
        o.derivations = n;
        ModuleString w = deriveLSystem(s, o);
        EXPECT_EQ(w.size(), f + turns) << "n = " << n;
        EXPECT_EQ(count(s, w, "F"), f);
        turns += 6 * f;
        f *= 8;
    }
}

TEST(LSystemDerive, ZeroDerivationsGiveTheAxiom) {
    EXPECT_EQ(derive("axiom: F(1)[+X]\nX -> F\nF(l) -> F(l*2)", 0), "F(1)[+X]");
}

TEST(LSystemDerive, UsesTheFileDerivationsUnlessOverridden) {
    EXPECT_EQ(derive("derivations: 3\naxiom: A\nA -> AA"), "AAAAAAAA");
    EXPECT_EQ(derive("derivations: 3\naxiom: A\nA -> AA", 1), "AA");
}

TEST(LSystemDerive, ParametricGrowthCompounds) {
    LSystem s = parseLSystem("#define lr 1.3\naxiom: F(2.5)\nF(l) -> F(l*lr)\nderivations: 8");
    ModuleString w = deriveLSystem(s);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NEAR(w.params[0], 2.5 * std::pow(1.3, 8), 1e-12);
}

TEST(LSystemDerive, SuccessorParametersSeeThePredecessorValues) {
    EXPECT_EQ(derive("axiom: A(1,2)\nA(x,y) -> A(x+1,y*2)B(y)", 3), "A(4,16)B(8)B(4)B(2)");
}

TEST(LSystemDerive, ConditionsChooseTheRule) {
    const char* text =
        "axiom: A(0)\nA(t) : t < 2 -> A(t+1)\nA(t) : t >= 2 && t < 4 -> A(t+1)F\nA(t) : t >= 4 "
        "-> X";
    EXPECT_EQ(derive(text, 2), "A(2)");
    EXPECT_EQ(derive(text, 4), "A(4)FF");
    EXPECT_EQ(derive(text, 6), "XFF");
}

TEST(LSystemDerive, FirstMatchingRuleApplies) {
    EXPECT_EQ(derive("axiom: A(5)\nA(x) : x > 1 -> B\nA(x) : x > 2 -> C\nA(x) -> D", 1), "B");
    EXPECT_EQ(derive("axiom: A(0)\nA(x) : x > 1 -> B\nA(x) -> D\nA(x) -> E", 1), "D");
}

TEST(LSystemDerive, ModulesWithoutAMatchingRuleAreCopied) {
    // No rule for B, and the A rule needs one parameter: A without parameters stays.
    EXPECT_EQ(derive("axiom: A B(1,2) A(3)\nA(x) -> C(x)", 1), "AB(1,2)C(3)");
}

TEST(LSystemDerive, RulesMatchOnParameterCount) {
    EXPECT_EQ(derive("axiom: F F(2) F(3,4)\nF -> G\nF(a) -> H(a)\nF(a,b) -> K(a+b)", 1),
              "GH(2)K(7)");
}

TEST(LSystemDerive, ConstantSuccessorParametersAreCopied) {
    EXPECT_EQ(derive("#define a 36\naxiom: A\nA -> F(50)[&(a)F(50)A]/(137.5)A", 1),
              "F(50)[&(36)F(50)A]/(137.5)A");
}

TEST(LSystemDerive, SameSeedGivesTheSameWord) {
    const char* text =
        "seed: 42\naxiom: X\nX -> F[+X]F[-X]+X : 1\nX -> F[+X]F : 1\nX -> F[-X]F : 1\n"
        "F -> F(rand())";
    LSystem s = parseLSystem(text);
    DeriveOptions o;
    o.derivations = 5;
    ModuleString a = deriveLSystem(s, o);
    ModuleString b = deriveLSystem(s, o);
    EXPECT_EQ(formatModules(s.symbols, a), formatModules(s.symbols, b));
    EXPECT_EQ(a.params, b.params);
}

TEST(LSystemDerive, SeedOptionChangesStochasticChoices) {
    LSystem s = parseLSystem("seed: 1\naxiom: XXXXXXXXXXXXXXXXXXXX\nX -> A : 1\nX -> B : 1");
    DeriveOptions o;
    o.derivations = 1;
    std::string fromFile = formatModules(s.symbols, deriveLSystem(s, o));
    o.overrideSeed = true;
    o.seed = 1;
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s, o)), fromFile);
    o.seed = 2;
    EXPECT_NE(formatModules(s.symbols, deriveLSystem(s, o)), fromFile);
}

TEST(LSystemDerive, StochasticChoiceFollowsTheWeights) {
    LSystem s = parseLSystem("seed: 3\naxiom: " + std::string(20000, 'X') +
                             "\nX -> A : 1\nX -> B : 3\nX -> C : 0");
    DeriveOptions o;
    o.derivations = 1;
    ModuleString w = deriveLSystem(s, o);
    std::size_t b = count(s, w, "B");
    EXPECT_EQ(count(s, w, "A") + b, 20000u);
    EXPECT_EQ(count(s, w, "C"), 0u);
    // Binomial(20000, 0.75): standard deviation 61; allow five of them.
    EXPECT_NEAR(static_cast<double>(b), 15000.0, 300.0);
}

TEST(LSystemDerive, StochasticWeightsMayDependOnParameters) {
    LSystem s = parseLSystem(
        "seed: 9\naxiom: X(0) X(1) X(0) X(1)\nX(t) -> A : 1 - t\n"
        "X(t) -> B : t");
    DeriveOptions o;
    o.derivations = 1;
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s, o)), "ABAB");
}

TEST(LSystemDerive, ZeroTotalWeightLeavesTheModule) {
    EXPECT_EQ(derive("axiom: X(0)\nX(t) -> A : t\nX(t) -> B : t", 1), "X(0)");
}

TEST(LSystemDerive, PlainRuleBeforeStochasticRulesWins) {
    EXPECT_EQ(derive("axiom: X(1)X(0)\nX(t) : t > 0 -> P\nX(t) -> A : 1\nX(t) -> A : 1", 1), "PA");
}

TEST(LSystemDerive, RandomFunctionsStayInRange) {
    LSystem s = parseLSystem("seed: 5\naxiom: " + std::string(2000, 'X') +
                             "\nX -> R(rand(), uniform(-2, 3), gauss(10, 0.001))");
    DeriveOptions o;
    o.derivations = 1;
    ModuleString w = deriveLSystem(s, o);
    for (const Module& m : w.modules) {
        const double* p = w.paramsOf(m);
        EXPECT_GE(p[0], 0.0);
        EXPECT_LT(p[0], 1.0);
        EXPECT_GE(p[1], -2.0);
        EXPECT_LT(p[1], 3.0);
        EXPECT_NEAR(p[2], 10.0, 0.01);
    }
}

TEST(LSystemDerive, CutRemovesTheRestOfTheBranch) {
    EXPECT_EQ(derive("axiom: A[B%C[D]E]F%G", 1), "A[B]F");
}

TEST(LSystemDerive, ProducedCutActsInTheNextStep) {
    // As in cpfg: the % produced in step 1 is in the word; step 2 removes it and the rest of
    // its branch.
    const char* text = "axiom: [AD]E\nA -> B%C";
    EXPECT_EQ(derive(text, 1), "[B%CD]E");
    EXPECT_EQ(derive(text, 2), "[B]E");
}

TEST(LSystemDerive, StopsAtTheModuleLimit) {
    LSystem s = parseLSystem("axiom: A\nA -> AB\nB -> A", "algae.lsys");
    DeriveOptions o;
    o.maxModules = 89;
    o.derivations = 9;  // exactly 89 modules: allowed
    EXPECT_EQ(deriveLSystem(s, o).size(), 89u);
    o.derivations = 10;  // 144 modules
    try {
        deriveLSystem(s, o);
        FAIL() << "expected the module limit";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("algae.lsys: derivation step 10 of 10 would exceed the "
                                        "module limit of 89 modules"));
        EXPECT_THAT(e.what(), HasSubstr("--max-modules"));
    }
}

TEST(LSystemDerive, AxiomLargerThanTheLimitIsAnError) {
    DeriveOptions o;
    o.maxModules = 3;
    EXPECT_THAT(deriveError("axiom: FFFF", o), HasSubstr("derivation step 0 of 1"));
}

TEST(LSystemDerive, NegativeDerivationOptionIsAnError) {
    DeriveOptions o;
    o.derivations = -3;
    EXPECT_THAT(deriveError("axiom: F", o), HasSubstr("derivations must be >= 0"));
}

TEST(LSystemDerive, DivisionByZeroNamesTheExpression) {
    EXPECT_THAT(deriveError("axiom: A(2)\nderivations: 3\nA(x) -> A(x - 1) B(10 / (x - 1))"),
                HasSubstr("d.lsys:3:20: division by zero in '10 / (x - 1)' (derivation step 2 "
                          "of 3); expected a non-zero divisor"));
}

TEST(LSystemDerive, ModuloByZeroIsAnError) {
    EXPECT_THAT(deriveError("axiom: A(0)\nA(x) -> B(5 % x)"),
                HasSubstr("d.lsys:2:11: division by zero in '5 % x'"));
}

TEST(LSystemDerive, NonFiniteValueNamesTheExpression) {
    EXPECT_THAT(deriveError("axiom: A(-4)\nA(x) -> A(sqrt(x))"),
                HasSubstr("d.lsys:2:11: no finite value (NaN or infinity) in 'sqrt(x)' "
                          "(derivation step 1 of 1)"));
}

TEST(LSystemDerive, OverflowIsAnError) {
    EXPECT_THAT(deriveError("axiom: A(1e290)\nderivations: 2\nA(x) -> A(x * 1e10)"),
                HasSubstr("d.lsys:3:11: no finite value (NaN or infinity) in 'x * 1e10' "
                          "(derivation step 2 of 2)"));
}

TEST(LSystemDerive, NonFiniteConditionIsAnError) {
    EXPECT_THAT(deriveError("axiom: A(0)\nA(x) : log(x) > 1 -> B"),
                HasSubstr("d.lsys:2:8: no finite value (NaN or infinity) in 'log(x) > 1'"));
}

TEST(LSystemDerive, NegativeWeightIsAnError) {
    EXPECT_THAT(deriveError("axiom: X(1)\nX(t) -> A : -t\nX(t) -> B : 1"),
                HasSubstr("d.lsys:2:13: negative weight -1.000000 from '-t' (derivation step 1)"
                          "; expected a weight >= 0"));
}

TEST(LSystemDerive, DefaultConstructedSystemGivesAnEmptyWord) {
    LSystem empty;
    EXPECT_EQ(deriveLSystem(empty).size(), 0u);
}

TEST(LSystemFormat, WritesParametersAndBrackets) {
    LSystem s = parseLSystem("axiom: F(50)[&(36)F(0.1234567890123)A]/(-1e-20)");
    EXPECT_EQ(formatModules(s.symbols, s.axiom), "F(50)[&(36)F(0.123456789)A]/(-1e-20)");
}

TEST(LSystemFormat, SeparatesMultiLetterNamesOnlyWhereNeeded) {
    LSystem s = parseLSystem("module Apex Ap\naxiom: Apex[+Ap e]A p Ap(1)x");
    EXPECT_EQ(formatModules(s.symbols, s.axiom), "Apex[+Ap e]A p Ap(1)x");
}

TEST(LSystemFormat, EmptyWordGivesEmptyText) {
    LSystem s = parseLSystem("axiom: A\nA ->\nderivations: 1");
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s)), "");
}

/// Parses `text`, derives, formats, parses the result as an axiom with the same module
/// declarations, and expects the same word (parameters to 10 significant digits).
void expectRoundTrip(const std::string& header, const std::string& rules, int derivations) {
    LSystem s = parseLSystem(header + rules);
    DeriveOptions o;
    o.derivations = derivations;
    ModuleString w = deriveLSystem(s, o);
    std::string text = formatModules(s.symbols, w);
    LSystem back = parseLSystem(header + "axiom: " + text);
    ASSERT_EQ(back.axiom.size(), w.size()) << text;
    for (std::size_t i = 0; i < w.size(); ++i) {
        const Module& a = w.modules[i];
        const Module& b = back.axiom.modules[i];
        ASSERT_EQ(s.symbols.names[a.symbol], back.symbols.names[b.symbol]) << i;
        ASSERT_EQ(a.paramCount, b.paramCount) << i;
        for (std::uint16_t k = 0; k < a.paramCount; ++k) {
            double x = w.paramsOf(a)[k];
            EXPECT_NEAR(back.axiom.paramsOf(b)[k], x, 1e-9 * std::max(1.0, std::fabs(x)));
        }
    }
}

TEST(LSystemFormat, RoundTripsParametricWords) {
    expectRoundTrip("#define r1 0.9\n#define r2 0.6\n#define d 137.5\n",
                    "axiom: A(1,10)\nA(l,w) -> !(w)F(l)[&(45)B(l*r2,w*0.707)]/(d)A(l*r1,w*0.707)"
                    "\nB(l,w) -> !(w)F(l)[-(45)$C(l*r2,w*0.707)]C(l*r1,w*0.707)\n"
                    "C(l,w) -> !(w)F(l)[+(45)$B(l*r2,w*0.707)]B(l*r1,w*0.707)\n",
                    6);
}

TEST(LSystemFormat, RoundTripsMultiLetterModulesThatArePrefixes) {
    expectRoundTrip("module Ap Apex pe\n", "axiom: A\nA -> A p e x Ap Apex pe A(-3.25)\n", 2);
}

TEST(LSystemFormat, RoundTripsEveryModuleCharacter) {
    expectRoundTrip("", "axiom: F'; ~ $|!.{}&^\\/@*=\"?0X\nX -> X%Y\n", 1);
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

// A(a, b, c) doubles every step: after k steps 2^k modules with 3 parameter values each, so a
// word takes 2^k · (12 + 3 · 8) = 36 · 2^k bytes, and step k holds 36 · (2^(k-1) + 2^k).
constexpr const char* kDoublingWithParameters =
    "axiom: A(1, 2, 3)\nA(a, b, c) -> A(a, b, c) A(a + 1, b, c)";

TEST(LSystemDeriveMemory, AStepThatFitsTheBudgetExactlyIsAllowed) {
    ASSERT_EQ(kModuleBytes, 12u);
    ASSERT_EQ(kParamBytes, 8u);
    LSystem s = parseLSystem(kDoublingWithParameters, "params.lsys");
    DeriveOptions o;
    o.derivations = 10;
    o.maxMemoryBytes = 36 * (512 + 1024);  // exactly step 10's two words
    const ModuleString word = deriveLSystem(s, o);
    EXPECT_EQ(word.size(), 1024u);
    EXPECT_EQ(word.params.size(), 3072u);
}

TEST(LSystemDeriveMemory, ParametersHitTheMemoryLimitWellUnderTheModuleLimit) {
    LSystem s = parseLSystem(kDoublingWithParameters, "params.lsys");
    DeriveOptions o;
    o.derivations = 10;
    o.maxMemoryBytes = 36 * (512 + 1024) - 1;  // one byte short of step 10
    o.maxModules = 1'000'000;
    try {
        deriveLSystem(s, o);
        FAIL() << "expected the memory limit";
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().file, "params.lsys");
        EXPECT_THAT(e.what(), HasSubstr("params.lsys: derivation step 10 of 10 would exceed the "
                                        "memory limit of 1 MiB (55295 bytes) for its words: 512 "
                                        "modules with 1536 parameter values rewritten into"));
        EXPECT_THAT(e.what(), HasSubstr("--max-memory"));
    }
    o.derivations = 9;  // 36 · (256 + 512) bytes: well within
    EXPECT_EQ(deriveLSystem(s, o).size(), 512u);
}

TEST(LSystemDeriveMemory, AnAxiomLargerThanTheBudgetIsAnError) {
    DeriveOptions o;
    o.maxMemoryBytes = 3 * kModuleBytes;  // the axiom has four modules
    EXPECT_THAT(deriveError("axiom: FFFF", o),
                HasSubstr("derivation step 0 of 1 would exceed the memory limit"));
}

TEST(LSystemDeriveMemory, TheBudgetDoesNotChangeTheWord) {
    LSystem s = parseLSystem(kDoublingWithParameters, "params.lsys");
    DeriveOptions tight;
    tight.derivations = 10;
    tight.maxMemoryBytes = 36 * (512 + 1024);
    DeriveOptions roomy = tight;
    roomy.maxMemoryBytes = DeriveOptions{}.maxMemoryBytes;
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s, tight)),
              formatModules(s.symbols, deriveLSystem(s, roomy)));
}

}  // namespace
}  // namespace ramus
