// Tests of the .lsys parser: headers, constants, modules, productions (docs/lsystem.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"

namespace ramus {
namespace {

using ::testing::HasSubstr;

/// The axiom as a list of symbol names, e.g. {"F", "[", "+", "F", "]"}.
std::vector<std::string> axiomNames(const LSystem& s) {
    std::vector<std::string> names;
    for (const Module& m : s.axiom.modules) names.push_back(s.symbols.names[m.symbol]);
    return names;
}

std::vector<double> paramsOf(const ModuleString& w, std::size_t i) {
    const Module& m = w.modules[i];
    return std::vector<double>(w.paramsOf(m), w.paramsOf(m) + m.paramCount);
}

TEST(LSystemParser, ReadsEveryHeaderSetting) {
    LSystem s = parseLSystem(
        "derivations: 8\nangle: 22.5\nstep: 2\nseed: 7\ntropism: 0 1 -0.5 0.27\n"
        "tropism_mode: blend\nwidth: 0.5\naxiom: F\n",
        "h.lsys");
    EXPECT_EQ(s.fileName, "h.lsys");
    EXPECT_EQ(s.settings.derivations, 8);
    EXPECT_DOUBLE_EQ(s.settings.angleDegrees, 22.5);
    EXPECT_DOUBLE_EQ(s.settings.step, 2.0);
    EXPECT_EQ(s.settings.seed, 7u);
    EXPECT_DOUBLE_EQ(s.settings.tropism.x(), 0.0);
    EXPECT_DOUBLE_EQ(s.settings.tropism.y(), 1.0);
    EXPECT_DOUBLE_EQ(s.settings.tropism.z(), -0.5);
    EXPECT_DOUBLE_EQ(s.settings.susceptibility, 0.27);
    EXPECT_EQ(s.settings.tropismMode, TropismMode::Blend);
    EXPECT_DOUBLE_EQ(s.settings.width, 0.5);
}

TEST(LSystemParser, UsesDefaultsWhenHeadersAreMissing) {
    LSystem s = parseLSystem("axiom: F");
    LSystemSettings d;
    EXPECT_EQ(s.settings.derivations, d.derivations);
    EXPECT_DOUBLE_EQ(s.settings.angleDegrees, d.angleDegrees);
    EXPECT_DOUBLE_EQ(s.settings.step, d.step);
    EXPECT_EQ(s.settings.seed, d.seed);
    EXPECT_EQ(s.settings.tropismMode, TropismMode::Rotate);
}

TEST(LSystemParser, AcceptsCpfgAndShortNamesForDerivations) {
    EXPECT_EQ(parseLSystem("n: 3\naxiom: F").settings.derivations, 3);
    EXPECT_EQ(parseLSystem("iterations: 4\naxiom: F").settings.derivations, 4);
    EXPECT_EQ(parseLSystem("derivation length: 5\naxiom: F").settings.derivations, 5);
}

TEST(LSystemParser, AcceptsCpfgFramingAndCapitalizedKeys) {
    LSystem s = parseLSystem("Lsystem: 1\nDerivation length: 2\nAxiom: F\nF --> FF\nendlsystem\n");
    EXPECT_EQ(s.settings.derivations, 2);
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s)), "FFFF");
}

TEST(LSystemParser, ReadsTropismWithCommasAndExpressions) {
    LSystem s = parseLSystem("#define e 0.2\ntropism: 0, -1, (1 + 1)/4, e\naxiom: F");
    EXPECT_DOUBLE_EQ(s.settings.tropism.y(), -1.0);
    EXPECT_DOUBLE_EQ(s.settings.tropism.z(), 0.5);
    EXPECT_DOUBLE_EQ(s.settings.susceptibility, 0.2);
}

TEST(LSystemParser, ReadsLargeSeedsExactly) {
    LSystem s = parseLSystem("seed: 18446744073709551615\naxiom: F");
    EXPECT_EQ(s.settings.seed, 18446744073709551615ull);
}

TEST(LSystemParser, DefinesAreUsableInHeadersAxiomAndProductions) {
    LSystem s = parseLSystem(
        "#define n 2 + 1\n#define a 36\n#define twice a * 2\nderivations: n\nangle: twice\n"
        "axiom: +(a)A(twice)\nA(x) : x > a -> B(x / a) : a\n");
    EXPECT_EQ(s.settings.derivations, 3);
    EXPECT_DOUBLE_EQ(s.settings.angleDegrees, 72.0);
    EXPECT_EQ(paramsOf(s.axiom, 0), std::vector<double>{36.0});
    EXPECT_EQ(paramsOf(s.axiom, 1), std::vector<double>{72.0});
}

TEST(LSystemParser, HeadersMayUseConstantsDefinedLater) {
    LSystem s = parseLSystem("derivations: n\naxiom: F\n#define n 4\n");
    EXPECT_EQ(s.settings.derivations, 4);
}

TEST(LSystemParser, SkipsCommentLinesAndTrailingComments) {
    LSystem s = parseLSystem(
        "# a comment line\n   # indented comment\n#define a 2   # trailing after define\n"
        "axiom: F(a) # the axiom\nF(x) -> F(x+1)  # grow\n\n");
    EXPECT_EQ(axiomNames(s), std::vector<std::string>{"F"});
    EXPECT_EQ(paramsOf(s.axiom, 0), std::vector<double>{2.0});
    EXPECT_EQ(s.symbols.find("#"), -1);
}

TEST(LSystemParser, HashIsNeverAModule) {
    LSystem s = parseLSystem("axiom: AB#C");
    EXPECT_EQ(axiomNames(s), (std::vector<std::string>{"A", "B"}));
}

TEST(LSystemParser, EveryPrintableNonSyntaxCharacterIsAModule) {
    LSystem s = parseLSystem("axiom: F'; ~ $|!.{}&^\\/%@*=\"?0");
    EXPECT_EQ(axiomNames(s),
              (std::vector<std::string>{"F", "'",  ";", "~", "$", "|", "!", ".",  "{", "}", "&",
                                        "^", "\\", "/", "%", "@", "*", "=", "\"", "?", "0"}));
}

TEST(LSystemParser, UndeclaredLettersAreSeparateModules) {
    LSystem s = parseLSystem("axiom: Apex");
    EXPECT_EQ(axiomNames(s), (std::vector<std::string>{"A", "p", "e", "x"}));
}

TEST(LSystemParser, DeclaredModulesUseLongestMatch) {
    LSystem s = parseLSystem("module Apex Ap Internode\naxiom: ApexApInternode[A]Ape");
    EXPECT_EQ(axiomNames(s),
              (std::vector<std::string>{"Apex", "Ap", "Internode", "[", "A", "]", "Ap", "e"}));
}

TEST(LSystemParser, ModuleDeclarationsMaySeparateNamesWithCommas) {
    LSystem s = parseLSystem("module Apex, Internode,Leaf\naxiom: InternodeLeafApex");
    EXPECT_EQ(axiomNames(s), (std::vector<std::string>{"Internode", "Leaf", "Apex"}));
}

TEST(LSystemParser, ModuleDeclarationsMayFollowTheirUse) {
    LSystem s = parseLSystem("axiom: Bud\nBud -> Leaf Bud\nmodule Bud Leaf");
    EXPECT_EQ(axiomNames(s), std::vector<std::string>{"Bud"});
}

TEST(LSystemParser, ParametricAxiomValuesAreEvaluated) {
    LSystem s = parseLSystem("axiom: A(1, -2.5, 1e-3, .5, 3.)B");
    EXPECT_EQ(paramsOf(s.axiom, 0), (std::vector<double>{1.0, -2.5, 1e-3, 0.5, 3.0}));
    EXPECT_EQ(s.axiom.modules[1].paramCount, 0);
}

TEST(LSystemParser, SymbolTableFindsMentionedNamesOnly) {
    LSystem s = parseLSystem("axiom: F[+X]\nX -> F");
    EXPECT_GE(s.symbols.find("X"), 0);
    EXPECT_EQ(s.symbols.names[static_cast<std::size_t>(s.symbols.find("X"))], "X");
    EXPECT_EQ(s.symbols.find("Y"), -1);
    EXPECT_EQ(s.symbols.find("-"), -1);
}

TEST(LSystemParser, AcceptsAllArrowSpellings) {
    for (const char* arrow : {"->", "-->", "\xE2\x86\x92"}) {
        LSystem s = parseLSystem(std::string("axiom: A\nA ") + arrow + " B\nderivations: 1");
        ModuleString w = deriveLSystem(s);
        ASSERT_EQ(w.size(), 1u) << arrow;
        EXPECT_EQ(s.symbols.names[w.modules[0].symbol], "B") << arrow;
    }
}

TEST(LSystemParser, ParsesProductionsForMinusAndPlus) {
    LSystem s = parseLSystem("axiom: +-\n- -> +\n+ -> F\nderivations: 1");
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s)), "F+");
}

TEST(LSystemParser, AcceptsAnEmptySuccessor) {
    LSystem s = parseLSystem("axiom: ABA\nA ->\nderivations: 1");
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s)), "B");
}

TEST(LSystemParser, ToleratesWindowsLineEndings) {
    LSystem s = parseLSystem("axiom: A\r\nA -> AB\r\nB -> A\r\nderivations: 2\r\n");
    EXPECT_EQ(formatModules(s.symbols, deriveLSystem(s)), "ABA");
}

TEST(LSystemParser, SetOverrideReplacesADefine) {
    ParseOptions o;
    o.constantOverrides = {{"a", 10.0}};
    LSystem s = parseLSystem("#define a 2\n#define b a * 3\naxiom: F(a, b)", "o.lsys", o);
    EXPECT_EQ(paramsOf(s.axiom, 0), (std::vector<double>{10.0, 30.0}));
}

TEST(LSystemParser, SetOverrideDefinesAConstantTheFileUses) {
    ParseOptions o;
    o.constantOverrides = {{"len", 4.0}};
    LSystem s = parseLSystem("axiom: F(len)", "o.lsys", o);
    EXPECT_EQ(paramsOf(s.axiom, 0), std::vector<double>{4.0});
}

TEST(LSystemParser, LoadsFilesAndNamesThemInErrors) {
    std::string path = std::string(RAMUS_BINARY_DIR) + "/parser_test_load.lsys";
    {
        FILE* f = std::fopen(path.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs("axiom: F\nF -> FF\nderivations: 2\nbogus: 1\n", f);
        std::fclose(f);
    }
    try {
        loadLSystem(path);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr(path + ":4:1: unknown header 'bogus'"));
    }
    std::remove(path.c_str());
    EXPECT_THROW(loadLSystem(path), Error);
}

}  // namespace
}  // namespace ramus
