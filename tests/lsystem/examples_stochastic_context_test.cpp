// The stochastic (ABOP fig 1.27) and context-sensitive (ABOP fig 1.31a) examples: module counts
// of a stochastic word depend on the seed, so these tests check what holds for every seed;
// the context-sensitive word is compared with an independent reference rewriter.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "examples_support.hpp"
#include "ramus/lsystem.hpp"

namespace ramus::test {
namespace {

ModuleString deriveWithSeed(const LSystem& system, std::uint64_t seed, int derivations = -1) {
    DeriveOptions options;
    options.derivations = derivations;
    options.overrideSeed = true;
    options.seed = seed;
    return deriveLSystem(system, options);
}

TEST(Examples, StochasticPlantIsTheSameForTheSameSeed) {
    const LSystem system = loadExample("abop_1_27.lsys");
    ASSERT_EQ(system.settings.seed, 1u);
    const std::string fromFile = formatModules(system.symbols, deriveLSystem(system));
    EXPECT_EQ(formatModules(system.symbols, deriveWithSeed(system, 1)), fromFile);
    EXPECT_EQ(formatModules(system.symbols, deriveLSystem(system)), fromFile);
}

TEST(Examples, StochasticPlantDiffersBetweenSeeds) {
    const LSystem system = loadExample("abop_1_27.lsys");
    const std::string one = formatModules(system.symbols, deriveWithSeed(system, 1));
    EXPECT_NE(formatModules(system.symbols, deriveWithSeed(system, 2)), one);
    EXPECT_NE(formatModules(system.symbols, deriveWithSeed(system, 3)), one);
}

TEST(Examples, StochasticPlantKeepsBracketsBalancedAndItsCountsConsistent) {
    // Every F becomes F[+F]F[-F]F (5 F, 2 branches), F[+F]F or F[-F]F (3 F, 1 branch), so
    // F - 1 = 2·branches, each branch adds the 3 modules [ ± ], and 3^n ≤ F ≤ 5^n.
    const LSystem system = loadExample("abop_1_27.lsys");
    const int n = system.settings.derivations;
    const int open = system.symbols.find("["), close = system.symbols.find("]");
    const int forward = system.symbols.find("F");
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const ModuleString word = deriveWithSeed(system, seed);
        std::int64_t depth = 0, branches = 0, draws = 0;
        for (const Module& m : word.modules) {
            const int id = static_cast<int>(m.symbol);
            if (id == open) ++depth, ++branches;
            if (id == close) --depth;
            if (id == forward) ++draws;
            ASSERT_GE(depth, 0) << "seed " << seed;
        }
        EXPECT_EQ(depth, 0) << "seed " << seed;
        EXPECT_EQ(draws - 1, 2 * branches) << "seed " << seed;
        EXPECT_EQ(static_cast<std::int64_t>(word.size()), draws + 3 * branches) << "seed " << seed;
        EXPECT_GE(draws, std::pow(3, n));
        EXPECT_LE(draws, std::pow(5, n));
    }
}

TEST(Examples, StochasticPlantChoosesEachProductionWithItsProbability) {
    // One step from ω = F picks exactly one successor; over 3000 seeds each weight's share is
    // within 0.04 of 0.33 / 0.33 / 0.34 (4.6 standard deviations of a binomial share).
    const LSystem system = loadExample("abop_1_27.lsys");
    constexpr int kSeeds = 3000;
    int full = 0, left = 0, right = 0;
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        const std::string word = formatModules(system.symbols, deriveWithSeed(system, seed, 1));
        if (word == "F[+F]F[-F]F") {
            ++full;
        } else if (word == "F[+F]F") {
            ++left;
        } else if (word == "F[-F]F") {
            ++right;
        } else {
            FAIL() << "seed " << seed << " derived " << word;
        }
    }
    EXPECT_NEAR(full / double(kSeeds), 0.33, 0.04);
    EXPECT_NEAR(left / double(kSeeds), 0.33, 0.04);
    EXPECT_NEAR(right / double(kSeeds), 0.34, 0.04);
}

std::vector<ContextRule> hogewegHesperRules() {
    return {{'0', '0', '0', "0"}, {'0', '0', '1', "1[+F1F1]"}, {'0', '1', '0', "1"},
            {'0', '1', '1', "1"}, {'1', '0', '0', "0"},        {'1', '0', '1', "1F1"},
            {'1', '1', '0', "0"}, {'1', '1', '1', "0"},        {0, '+', 0, "-"},
            {0, '-', 0, "+"}};
}

TEST(Examples, ContextSensitivePlantMatchesAReferenceRewriterAtEveryStep) {
    const LSystem system = loadExample("abop_1_31a.lsys");
    std::string reference = "F1F1F1";
    for (int n = 0; n <= system.settings.derivations; ++n) {
        DeriveOptions options;
        options.derivations = n;
        ASSERT_EQ(formatModules(system.symbols, deriveLSystem(system, options)), reference)
            << "after " << n << " steps";
        reference = rewriteWithContext(reference, hogewegHesperRules(), "+-F");
    }
}

TEST(Examples, ContextSensitivePlantHas6910ModulesAfterThirtySteps) {
    // Counts of the reference rewriter (the same rules applied with ABOP's context search by an
    // independent script): n = 10: 47, 20: 604, 30: 6910, 40: 75931 modules.
    std::string word = "F1F1F1";
    for (int n = 1; n <= 40; ++n) {
        word = rewriteWithContext(word, hogewegHesperRules(), "+-F");
        if (n == 10) EXPECT_EQ(word.size(), 47u);
        if (n == 20) EXPECT_EQ(word.size(), 604u);
        if (n == 30) EXPECT_EQ(word.size(), 6910u);
    }
    EXPECT_EQ(word.size(), 75931u);

    const LSystem system = loadExample("abop_1_31a.lsys");
    const ModuleString derived = deriveLSystem(system);
    EXPECT_EQ(derived.size(), 6910u);
    EXPECT_EQ(countModules(system.symbols, derived).at("F"), 2501u);
}

TEST(Examples, ReferenceRewriterSkipsBranchesAndStopsAtTheEndOfItsOwn) {
    // ABOP p. 32 semantics on a tiny word: in "a[b]c", c's left context is a (the branch [b]
    // is skipped) and b's left context is a (stepping out of its branch); b has no right
    // context because its branch ends, and a's right context is c.
    const std::vector<ContextRule> rules = {
        {'a', 'c', 0, "L"}, {'a', 'b', 0, "M"}, {0, 'b', 'c', "X"}, {0, 'a', 'c', "R"}};
    EXPECT_EQ(rewriteWithContext("a[b]c", rules, ""), "R[M]L");
    EXPECT_EQ(rewriteWithContext("a[b]c", {{0, 'b', 'c', "X"}}, ""), "a[b]c");
    EXPECT_EQ(rewriteWithContext("a+c", {{'a', 'c', 0, "L"}}, "+"), "a+L");
    EXPECT_EQ(rewriteWithContext("a+c", {{'a', 'c', 0, "L"}}, ""), "a+c");
}

}  // namespace
}  // namespace ramus::test
