// Context-sensitive derivation in bracketed words (ABOP §1.8), hand-checked.
#include <gtest/gtest.h>

#include <string>

#include "lsystem/derive_text.hpp"
#include "ramus/lsystem.hpp"

namespace ramus {
namespace {

using test::derive;

TEST(LSystemContext, SignalPropagatesOneModulePerStep) {
    // ABOP eq. 1.8 (p. 31): ω: baaaaaaaa, b < a -> b, b -> a.
    const char* text = "axiom: baaaaaaaa\nb < a -> b\nb -> a";
    EXPECT_EQ(derive(text, 1), "abaaaaaaa");
    EXPECT_EQ(derive(text, 2), "aabaaaaaa");
    EXPECT_EQ(derive(text, 8), "aaaaaaaab");
    EXPECT_EQ(derive(text, 9), "aaaaaaaaa");
}

TEST(LSystemContext, RightContextPropagatesBackwards) {
    EXPECT_EQ(derive("axiom: aaab\na > b -> b\nb -> a", 2), "abaa");
}

/// The bracketed word of ABOP p. 32, rewritten by `S -> X` with the given context.
std::string rewriteS(const std::string& context) {
    return derive("axiom: ABC[DE][SG[HI[JK]L]MNO]\n" + context + " -> X", 1);
}

TEST(LSystemContext, LeftContextSkipsCompletedBranches) {
    const std::string unchanged = "ABC[DE][SG[HI[JK]L]MNO]";
    const std::string rewritten = "ABC[DE][XG[HI[JK]L]MNO]";
    EXPECT_EQ(rewriteS("BC < S"), rewritten);
    EXPECT_EQ(rewriteS("C < S"), rewritten);
    EXPECT_EQ(rewriteS("ABC < S"), rewritten);
    EXPECT_EQ(rewriteS("E < S"), unchanged);
    EXPECT_EQ(rewriteS("DE < S"), unchanged);
}

TEST(LSystemContext, RightContextMayEnterBranches) {
    const std::string unchanged = "ABC[DE][SG[HI[JK]L]MNO]";
    const std::string rewritten = "ABC[DE][XG[HI[JK]L]MNO]";
    EXPECT_EQ(rewriteS("S > G[H]M"), rewritten);    // ABOP's example
    EXPECT_EQ(rewriteS("S > GM"), rewritten);       // lateral branch skipped
    EXPECT_EQ(rewriteS("S > G[HI]MN"), rewritten);  // rest of the branch skipped at ']'
    EXPECT_EQ(rewriteS("S > G[HI[J]L]M"), rewritten);
    EXPECT_EQ(rewriteS("S > GH"), unchanged);  // H is in a branch, not on the axis
    EXPECT_EQ(rewriteS("S > G[I]"), unchanged);
    EXPECT_EQ(rewriteS("S > GMNOP"), unchanged);  // the branch ends after O
}

TEST(LSystemContext, StarMeansAnyContextAndAnyCondition) {
    // cpfg / ABOP notation: `* < + > * -> -` and `: *` (ABOP fig. 1.31, fig. 2.6).
    EXPECT_EQ(derive("axiom: +A(1)-\n* < + > * -> -\n* < - > * -> +\nA(x) : * -> B(x)", 1),
              "-B(1)+");
    EXPECT_EQ(derive("axiom: *A*\n* < A -> X", 1), "*X*");  // a lone `*` module elsewhere
}

TEST(LSystemContext, BothContextsMustMatch) {
    EXPECT_EQ(derive("axiom: ABC ABD\nA < B > C -> X", 1), "AXCABD");
}

TEST(LSystemContext, LeftContextLeavesTheBranchThroughItsBracket) {
    EXPECT_EQ(derive("axiom: A[B]C[[D]B]\nA < B -> X", 1), "A[X]C[[D]B]");
    EXPECT_EQ(derive("axiom: A[B]C[[D]B]\nC < B -> X", 1), "A[B]C[[D]X]");
}

TEST(LSystemContext, IgnoredModulesAreSkipped) {
    const char* rules = "A < B > C -> X";
    EXPECT_EQ(derive(std::string("axiom: A+B-C\n") + rules, 1), "A+B-C");
    EXPECT_EQ(derive(std::string("ignore: + -\naxiom: A+B-C\n") + rules, 1), "A+X-C");
    EXPECT_EQ(derive(std::string("ignore: + -\naxiom: A+[-B-C]\n") + rules, 1), "A+[-X-C]");
}

TEST(LSystemContext, ConsiderListIgnoresEverythingElse) {
    EXPECT_EQ(derive("consider: A B C\naxiom: A+F(1)B/C\nA < B > C -> X", 1), "A+F(1)X/C");
}

TEST(LSystemContext, ContextParametersAreBound) {
    EXPECT_EQ(derive("axiom: A(1)B(2)C(3)\nA(x) < B(y) > C(z) : x < z -> B(x+10*y+100*z)", 1),
              "A(1)B(321)C(3)");
    EXPECT_EQ(derive("axiom: A(5)B(2)C(3)\nA(x) < B(y) > C(z) : x < z -> B(0)", 1), "A(5)B(2)C(3)");
}

TEST(LSystemContext, MultiModuleContextsBindInOrder) {
    EXPECT_EQ(derive("axiom: A(1)B(2)C(3)[D(4)]E(5)\nA(a) B(b) < C(c) > [D(d)] E(e) -> "
                     "C(a+b+c+d+e)",
                     1),
              "A(1)B(2)C(15)[D(4)]E(5)");
}

TEST(LSystemContext, ContextRequiresTheSameParameterCount) {
    EXPECT_EQ(derive("axiom: A(1)B\nA < B -> X", 1), "A(1)B");
    EXPECT_EQ(derive("axiom: A(1)B\nA(x) < B -> X(x)", 1), "A(1)X(1)");
}

TEST(LSystemContext, ContextUsesTheOldWord) {
    // Parallel rewriting: every module sees its neighbours before this step.
    EXPECT_EQ(derive("axiom: abb\na < b -> a\na -> c", 1), "cab");
}

TEST(LSystemContext, Abop131aFirstStepsByHand) {
    // ABOP fig. 1.31a (p. 35), ignore + - F.
    const char* text =
        "ignore: + - F\naxiom: F1F1F1\n0 < 0 > 0 -> 0\n0 < 0 > 1 -> 1[+F1F1]\n0 < 1 > 0 -> 1\n"
        "0 < 1 > 1 -> 1\n1 < 0 > 0 -> 0\n1 < 0 > 1 -> 1F1\n1 < 1 > 0 -> 0\n1 < 1 > 1 -> 0\n"
        "+ -> -\n- -> +\n";
    EXPECT_EQ(derive(text, 1), "F1F0F1");
    EXPECT_EQ(derive(text, 2), "F1F1F1F1");
    EXPECT_EQ(derive(text, 3), "F1F0F0F1");
    EXPECT_EQ(derive(text, 4), "F1F0F1[+F1F1]F1");
    EXPECT_EQ(derive(text, 5), "F1F1F1F1[-F0F1]F1");
}

TEST(LSystemContext, Abop131aLengthGrowsLinearlyInWork) {
    // Not a timing test: the 30-step word of fig. 1.31a is derived, and its size is stable.
    const char* text =
        "ignore: + - F\naxiom: F1F1F1\n0 < 0 > 0 -> 0\n0 < 0 > 1 -> 1[+F1F1]\n0 < 1 > 0 -> 1\n"
        "0 < 1 > 1 -> 1\n1 < 0 > 0 -> 0\n1 < 0 > 1 -> 1F1\n1 < 1 > 0 -> 0\n1 < 1 > 1 -> 0\n"
        "+ -> -\n- -> +\nderivations: 30\n";
    LSystem s = parseLSystem(text);
    ModuleString a = deriveLSystem(s);
    ModuleString b = deriveLSystem(s);
    EXPECT_GT(a.size(), 1000u);
    EXPECT_EQ(formatModules(s.symbols, a), formatModules(s.symbols, b));
}

}  // namespace
}  // namespace ramus
