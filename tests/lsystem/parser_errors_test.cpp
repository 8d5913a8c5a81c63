// One test per parse error: each message names file:line:col and what was expected.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"

namespace ramus {
namespace {

using ::testing::HasSubstr;

std::string parseError(const std::string& text, const ParseOptions& options = {}) {
    try {
        parseLSystem(text, "bad.lsys", options);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(LSystemParseErrors, UnknownIdentifierInSuccessor) {
    std::string m = parseError("axiom: A(1)\nA(x) -> A(y + 1)");
    EXPECT_THAT(m, HasSubstr("bad.lsys:2:11: unknown identifier 'y'"));
    EXPECT_THAT(m, HasSubstr("expected a formal parameter (x) or a #define constant"));
}

TEST(LSystemParseErrors, UnknownIdentifierInAxiom) {
    EXPECT_THAT(parseError("axiom: F(len)"),
                HasSubstr("bad.lsys:1:10: unknown identifier 'len' in the axiom; expected a "
                          "#define constant"));
}

TEST(LSystemParseErrors, UnknownFunction) {
    std::string m = parseError("axiom: F(sine(30))");
    EXPECT_THAT(m, HasSubstr("bad.lsys:1:10: unknown function 'sine'"));
    EXPECT_THAT(m, HasSubstr("expected one of sin, cos"));
}

TEST(LSystemParseErrors, FunctionCalledWithWrongArgumentCount) {
    EXPECT_THAT(parseError("axiom: F(min(1, 2, 3))"),
                HasSubstr("bad.lsys:1:10: function 'min' takes 2 arguments; got 3"));
}

TEST(LSystemParseErrors, DuplicateFormalParameterInPredecessor) {
    EXPECT_THAT(parseError("axiom: A(1,2)\nA(x, x) -> B"),
                HasSubstr("bad.lsys:2:6: formal parameter 'x' is already used in this "
                          "production (column 3); expected a distinct name"));
}

TEST(LSystemParseErrors, ContextParameterClashesWithPredecessorParameter) {
    EXPECT_THAT(parseError("axiom: B(1)A(2)\nB(x) < A(x) -> C"),
                HasSubstr("bad.lsys:2:3: formal parameter 'x' is already used"));
}

TEST(LSystemParseErrors, NumberWithoutExponentDigits) {
    EXPECT_THAT(parseError("axiom: F(1e)"),
                HasSubstr("bad.lsys:1:10: bad number '1e'; expected digits after the exponent"));
}

TEST(LSystemParseErrors, NumberFollowedByLetters) {
    EXPECT_THAT(parseError("axiom: F(2x)"),
                HasSubstr("bad.lsys:1:10: bad number '2x'; expected digits"));
}

TEST(LSystemParseErrors, NumberWithTwoDecimalPoints) {
    EXPECT_THAT(parseError("axiom: F(1.2.3)"), HasSubstr("bad.lsys:1:10: bad number '1.2.3'"));
}

TEST(LSystemParseErrors, NumberOutOfRange) {
    EXPECT_THAT(parseError("axiom: F(1e999)"),
                HasSubstr("bad.lsys:1:10: number '1e999' is out of range"));
}

TEST(LSystemParseErrors, UnclosedBracketInAxiom) {
    EXPECT_THAT(parseError("axiom: F[+F[-F]"),
                HasSubstr("bad.lsys:1:9: unclosed '[' in the axiom; expected a matching ']'"));
}

TEST(LSystemParseErrors, StrayClosingBracketInAxiom) {
    EXPECT_THAT(parseError("axiom: F]F"),
                HasSubstr("bad.lsys:1:9: unbalanced ']' in the axiom; expected a '[' before it"));
}

TEST(LSystemParseErrors, UnbalancedBracketsInSuccessor) {
    EXPECT_THAT(parseError("axiom: X\nX -> F[+X]]"),
                HasSubstr("bad.lsys:2:11: unbalanced ']' in the successor"));
}

TEST(LSystemParseErrors, MissingArrow) {
    EXPECT_THAT(parseError("axiom: X\nX F[+X]"),
                HasSubstr("bad.lsys:2:8: missing '->'; expected a production 'predecessor -> "
                          "successor' or a header 'key: value'"));
}

TEST(LSystemParseErrors, ConditionWithoutArrow) {
    EXPECT_THAT(parseError("axiom: B(1)\nB(x) : x > 2"),
                HasSubstr("bad.lsys:2:13: missing '->'; expected a production"));
}

TEST(LSystemParseErrors, UnknownHeaderKey) {
    std::string m = parseError("axiom: F\nangel: 30");
    EXPECT_THAT(m, HasSubstr("bad.lsys:2:1: unknown header 'angel'"));
    EXPECT_THAT(m, HasSubstr("expected one of axiom, derivations, angle"));
}

TEST(LSystemParseErrors, NegativeDerivations) {
    EXPECT_THAT(parseError("derivations: -2\naxiom: F"),
                HasSubstr("bad.lsys:1:14: derivations must be a whole number from 0 to"));
}

TEST(LSystemParseErrors, FractionalDerivations) {
    EXPECT_THAT(parseError("derivations: 2.5\naxiom: F"),
                HasSubstr("bad.lsys:1:14: derivations must be a whole number"));
}

TEST(LSystemParseErrors, MissingAxiom) {
    EXPECT_THAT(parseError("derivations: 2\nF -> FF\n"),
                HasSubstr("bad.lsys:3:1: no axiom; expected a line 'axiom: <modules>'"));
}

TEST(LSystemParseErrors, EmptyAxiom) {
    EXPECT_THAT(parseError("axiom:   "),
                HasSubstr("bad.lsys:1:10: missing value after 'axiom:'; expected a word"));
}

TEST(LSystemParseErrors, HeaderGivenTwice) {
    EXPECT_THAT(parseError("angle: 30\naxiom: F\nangle: 40"),
                HasSubstr("bad.lsys:3:1: 'angle:' is given twice (first on line 1)"));
}

TEST(LSystemParseErrors, TwoPredecessorModules) {
    EXPECT_THAT(parseError("axiom: AB\nA B -> C"),
                HasSubstr("bad.lsys:2:3: a production rewrites one module, but a second one "
                          "follows 'A'"));
}

TEST(LSystemParseErrors, MissingPredecessor) {
    EXPECT_THAT(parseError("axiom: A\n -> C"),
                HasSubstr("bad.lsys:2:2: missing predecessor; expected a module before '->'"));
}

TEST(LSystemParseErrors, BracketAsPredecessor) {
    EXPECT_THAT(parseError("axiom: A\n[ -> C"),
                HasSubstr("bad.lsys:2:1: '[' cannot be rewritten (it is a bracket)"));
}

TEST(LSystemParseErrors, CutSymbolAsPredecessor) {
    EXPECT_THAT(parseError("axiom: A\n% -> C"),
                HasSubstr("bad.lsys:2:1: '%' cannot be rewritten (it is the cut symbol)"));
}

TEST(LSystemParseErrors, EmptyLeftContext) {
    EXPECT_THAT(parseError("axiom: A\n < A -> C"),
                HasSubstr("bad.lsys:2:2: empty left context; expected modules before '<'"));
}

TEST(LSystemParseErrors, BracketsInLeftContext) {
    EXPECT_THAT(parseError("axiom: A\n[B] < A -> C"),
                HasSubstr("bad.lsys:2:1: brackets are not allowed in a left context"));
}

TEST(LSystemParseErrors, UnbalancedRightContext) {
    EXPECT_THAT(parseError("axiom: A\nA > [B -> C"),
                HasSubstr("bad.lsys:2:5: unclosed '[' in the right context"));
}

TEST(LSystemParseErrors, SecondLeftContextMarker) {
    EXPECT_THAT(parseError("axiom: A\nB < C < A -> C"),
                HasSubstr("bad.lsys:2:7: second '<' in the predecessor"));
}

TEST(LSystemParseErrors, SecondRightContextMarker) {
    EXPECT_THAT(parseError("axiom: A\nA > B > C -> D"),
                HasSubstr("bad.lsys:2:7: second '>' in the predecessor"));
}

TEST(LSystemParseErrors, RightContextMarkerBeforeLeft) {
    EXPECT_THAT(parseError("axiom: A\nA > B < C -> D"),
                HasSubstr("bad.lsys:2:3: '>' before '<'; expected 'left < predecessor > right'"));
}

TEST(LSystemParseErrors, EmptyRightContext) {
    EXPECT_THAT(parseError("axiom: A\nA > -> D"),
                HasSubstr("bad.lsys:2:3: empty right context; expected modules after '>'"));
}

TEST(LSystemParseErrors, MissingPredecessorBetweenContexts) {
    EXPECT_THAT(parseError("axiom: A\nB <  > C -> D"),
                HasSubstr("bad.lsys:2:6: missing predecessor; expected a module before '>'"));
}

TEST(LSystemParseErrors, IgnoredSymbolInContext) {
    EXPECT_THAT(parseError("ignore: + -\naxiom: A\n+ < A -> C"),
                HasSubstr("bad.lsys:3:1: '+' is skipped when matching contexts"));
}

TEST(LSystemParseErrors, BracketInIgnoreList) {
    EXPECT_THAT(parseError("ignore: + [\naxiom: A"),
                HasSubstr("bad.lsys:1:11: brackets cannot be ignored"));
}

TEST(LSystemParseErrors, IgnoreAndConsiderTogether) {
    EXPECT_THAT(parseError("ignore: +\nconsider: A\naxiom: A"),
                HasSubstr("bad.lsys:2:1: 'ignore:' and 'consider:' cannot both be used"));
}

TEST(LSystemParseErrors, ParametersInIgnoreList) {
    EXPECT_THAT(parseError("ignore: F(x)\naxiom: A"),
                HasSubstr("bad.lsys:1:10: unexpected '(' after 'F'; expected module names "
                          "without parameters"));
}

TEST(LSystemParseErrors, RandomFunctionInAxiom) {
    EXPECT_THAT(parseError("axiom: F(rand())"),
                HasSubstr("bad.lsys:1:10: random function 'rand()' is not allowed in the "
                          "axiom; expected a constant expression"));
}

TEST(LSystemParseErrors, RandomFunctionInDefine) {
    EXPECT_THAT(parseError("#define r uniform(0, 1)\naxiom: F"),
                HasSubstr("bad.lsys:1:11: random function 'uniform()' is not allowed"));
}

TEST(LSystemParseErrors, DivisionByZeroInConstantExpression) {
    EXPECT_THAT(parseError("#define z 0\naxiom: F(1 / z)"),
                HasSubstr("bad.lsys:2:12: division by zero; expected a non-zero divisor"));
}

TEST(LSystemParseErrors, DivisionByLiteralZeroInSuccessor) {
    EXPECT_THAT(parseError("axiom: A(1)\nA(x) -> A(x / 0)"),
                HasSubstr("bad.lsys:2:13: division by zero; expected a non-zero divisor"));
}

TEST(LSystemParseErrors, NonFiniteConstantExpression) {
    EXPECT_THAT(parseError("axiom: F(sqrt(-1))"),
                HasSubstr("bad.lsys:1:10: constant expression has no finite value"));
}

TEST(LSystemParseErrors, DefineRedefinition) {
    EXPECT_THAT(parseError("#define a 1\n#define a 2\naxiom: F"),
                HasSubstr("bad.lsys:2:9: constant 'a' is already defined on line 1"));
}

TEST(LSystemParseErrors, DefineWithoutValue) {
    EXPECT_THAT(parseError("#define a\naxiom: F"),
                HasSubstr("bad.lsys:1:10: #define a has no value; expected '#define a value'"));
}

TEST(LSystemParseErrors, DefineUsingLaterConstant) {
    EXPECT_THAT(parseError("#define a b\n#define b 1\naxiom: F"),
                HasSubstr("bad.lsys:1:11: unknown identifier 'b' in #define"));
}

TEST(LSystemParseErrors, DefineNamedLikeAFunction) {
    EXPECT_THAT(parseError("#define sin 1\naxiom: F"),
                HasSubstr("bad.lsys:1:9: 'sin' is a built-in function"));
}

TEST(LSystemParseErrors, UnsupportedPreprocessorDirective) {
    EXPECT_THAT(parseError("#include other.lsys\naxiom: F"),
                HasSubstr("bad.lsys:1:1: preprocessor directive '#include' is not supported"));
}

TEST(LSystemParseErrors, EmptyParameterList) {
    EXPECT_THAT(parseError("axiom: F()"),
                HasSubstr("bad.lsys:1:9: empty parameter list after 'F'"));
}

TEST(LSystemParseErrors, MissingClosingParenthesis) {
    EXPECT_THAT(parseError("axiom: F(1 + 2"),
                HasSubstr("bad.lsys:1:15: expected ',' or ')' in the parameters of 'F', got end "
                          "of line"));
}

TEST(LSystemParseErrors, ParameterListWithoutModule) {
    EXPECT_THAT(parseError("axiom: (1)F"),
                HasSubstr("bad.lsys:1:8: unexpected '('; expected a module name"));
}

TEST(LSystemParseErrors, ReservedCharacterInSuccessor) {
    EXPECT_THAT(parseError("axiom: A\nA -> B > C"),
                HasSubstr("bad.lsys:2:8: '>' separates the parts of a production"));
}

TEST(LSystemParseErrors, SecondArrowInProduction) {
    EXPECT_THAT(parseError("axiom: A\nA -> B \xE2\x86\x92 C"),
                HasSubstr("bad.lsys:2:8: '\xE2\x86\x92' is the production arrow; expected a "
                          "module"));
    EXPECT_THAT(parseError("axiom: A\nA -> B -> C"),
                HasSubstr("bad.lsys:2:9: '>' separates the parts of a production"));
}

TEST(LSystemParseErrors, BracketWithParameters) {
    EXPECT_THAT(parseError("axiom: F[(1)F]"),
                HasSubstr("bad.lsys:1:10: brackets take no parameters"));
}

TEST(LSystemParseErrors, SingleEqualsInCondition) {
    EXPECT_THAT(parseError("axiom: A(1)\nA(x) : x = 1 -> B"),
                HasSubstr("bad.lsys:2:10: unexpected '=' after the expression; expected an "
                          "operator or '->'"));
}

TEST(LSystemParseErrors, TextAfterWeight) {
    EXPECT_THAT(parseError("axiom: A\nA -> B : 0.5 : 2"),
                HasSubstr("bad.lsys:2:14: unexpected ':' after the expression"));
}

TEST(LSystemParseErrors, TropismWithThreeValues) {
    EXPECT_THAT(parseError("tropism: 0 1 0\naxiom: F"),
                HasSubstr("bad.lsys:1:15: tropism needs 4 values"));
}

TEST(LSystemParseErrors, UnknownTropismMode) {
    EXPECT_THAT(parseError("tropism_mode: bend\naxiom: F"),
                HasSubstr("bad.lsys:1:15: unknown tropism mode 'bend'; expected rotate or blend"));
}

TEST(LSystemParseErrors, NegativeWidth) {
    EXPECT_THAT(parseError("width: -1\naxiom: F"), HasSubstr("bad.lsys:1:8: width must be >= 0"));
}

TEST(LSystemParseErrors, ControlCharacterInWord) {
    EXPECT_THAT(parseError(std::string("axiom: F\x01") + "F"),
                HasSubstr("bad.lsys:1:9: unexpected control character 0x01; expected a module"));
}

TEST(LSystemParseErrors, BadCharacterInModuleDeclaration) {
    EXPECT_THAT(parseError("module Ap(ex\naxiom: F"),
                HasSubstr("bad.lsys:1:10: module name contains '('"));
}

TEST(LSystemParseErrors, UnknownSetOverride) {
    ParseOptions o;
    o.constantOverrides = {{"lenght", 2.0}};
    std::string m = parseError("#define length 1\n#define angle 30\naxiom: F(length)", o);
    EXPECT_THAT(m, HasSubstr("bad.lsys: --set lenght: the file does not use a constant "
                             "'lenght'; expected one of length, angle"));
}

TEST(LSystemParseErrors, InvalidSetOverrideName) {
    ParseOptions o;
    o.constantOverrides = {{"a b", 2.0}};
    EXPECT_THAT(parseError("axiom: F", o), HasSubstr("bad.lsys: --set 'a b': not a constant name"));
}

TEST(LSystemParseErrors, ColumnsCountCharactersNotBytes) {
    // The arrow is one character (three bytes); the unknown name is at column 7.
    EXPECT_THAT(parseError("axiom: A\nA \xE2\x86\x92 B(q)"),
                HasSubstr("bad.lsys:2:7: unknown identifier 'q'"));
}

TEST(LSystemParseErrors, ExpressionNestedTooDeeply) {
    std::string deep(200, '(');
    EXPECT_THAT(parseError("axiom: F(" + deep + "1" + std::string(200, ')') + ")"),
                HasSubstr("expression nested too deeply"));
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

// Non-finite numbers are refused where they enter: literals beyond double range, constants and
// header values that evaluate to NaN or infinity, and --set overrides.
TEST(LSystemNonFiniteInput, DefineBeyondDoubleRangeIsRefusedAtTheNumber) {
    EXPECT_THAT(parseError("#define a 1e999\naxiom: F(a)"),
                HasSubstr("bad.lsys:1:11: number '1e999' is out of range"));
}

TEST(LSystemNonFiniteInput, DefineEvaluatingToInfinityIsRefused) {
    EXPECT_THAT(parseError("#define a 1e300 * 1e300\naxiom: F(a)"),
                HasSubstr("bad.lsys:1:17: constant expression has no finite value"));
}

TEST(LSystemNonFiniteInput, NanIsNotANumberLiteral) {
    EXPECT_THAT(parseError("#define a nan\naxiom: F(a)"),
                HasSubstr("bad.lsys:1:11: unknown identifier 'nan'"));
    EXPECT_THAT(parseError("axiom: F(inf)"), HasSubstr("bad.lsys:1:10: unknown identifier 'inf'"));
}

TEST(LSystemNonFiniteInput, HeaderValuesBeyondDoubleRangeAreRefused) {
    EXPECT_THAT(parseError("angle: 1e999\naxiom: F"),
                HasSubstr("bad.lsys:1:8: number '1e999' is out of range"));
    EXPECT_THAT(parseError("step: 1e308 * 10\naxiom: F"),
                HasSubstr("bad.lsys:1:13: constant expression has no finite value"));
    EXPECT_THAT(parseError("tropism: 0 1 0 1e999\naxiom: F"),
                HasSubstr("bad.lsys:1:16: number '1e999' is out of range"));
}

TEST(LSystemNonFiniteInput, ModuleParameterBeyondDoubleRangeIsRefused) {
    EXPECT_THAT(parseError("axiom: A\nA -> F(-1e400)"),
                HasSubstr("bad.lsys:2:9: number '1e400' is out of range"));
}

TEST(LSystemNonFiniteInput, NonFiniteSetOverridesAreRefused) {
    for (double value : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        ParseOptions o;
        o.constantOverrides = {{"a", value}};
        EXPECT_THAT(parseError("#define a 1\naxiom: F(a)", o),
                    HasSubstr("bad.lsys: --set a: value is not finite; expected a number"));
    }
}

}  // namespace
}  // namespace ramus
