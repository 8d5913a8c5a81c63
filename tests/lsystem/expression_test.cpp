// Tests of the expression language: precedence, numbers, functions, short-circuit logic.
#include "lsystem/expression.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"

namespace ramus {
namespace {

/// Value of a constant expression, evaluated as an axiom parameter.
double value(const std::string& expr) {
    LSystem s = parseLSystem("#define c 3\naxiom: F(" + expr + ")", "e.lsys");
    EXPECT_EQ(s.axiom.size(), 1u);
    return s.axiom.params.at(0);
}

/// Value of an expression of the formal parameter x, evaluated during derivation.
double valueAt(const std::string& expr, double x) {
    LSystem s = parseLSystem("axiom: A(" + std::to_string(x) + ")\nA(x) -> B(" + expr + ")");
    ModuleString w = deriveLSystem(s);
    return w.params.at(0);
}

TEST(LSystemExpression, ArithmeticPrecedence) {
    EXPECT_DOUBLE_EQ(value("2 + 3 * 4"), 14.0);
    EXPECT_DOUBLE_EQ(value("(2 + 3) * 4"), 20.0);
    EXPECT_DOUBLE_EQ(value("10 - 4 - 3"), 3.0);
    EXPECT_DOUBLE_EQ(value("100 / 10 / 5"), 2.0);
    EXPECT_DOUBLE_EQ(value("7 % 3"), 1.0);
    EXPECT_DOUBLE_EQ(value("-7 % 3"), -1.0);  // fmod: sign of the dividend
    EXPECT_DOUBLE_EQ(value("2 * 3 % 4"), 2.0);
    EXPECT_DOUBLE_EQ(value("1 + -2"), -1.0);
    EXPECT_DOUBLE_EQ(value("--2"), 2.0);
    EXPECT_DOUBLE_EQ(value("+2"), 2.0);
}

TEST(LSystemExpression, PowerIsRightAssociativeAndBindsTighterThanUnaryMinus) {
    EXPECT_DOUBLE_EQ(value("2 ^ 3 ^ 2"), 512.0);
    EXPECT_DOUBLE_EQ(value("-2 ^ 2"), -4.0);
    EXPECT_DOUBLE_EQ(value("(-2) ^ 2"), 4.0);
    EXPECT_DOUBLE_EQ(value("2 ^ -1"), 0.5);
    EXPECT_DOUBLE_EQ(value("2 * 3 ^ 2"), 18.0);
    EXPECT_DOUBLE_EQ(value("2 ** 3 ** 2"), 512.0);  // L-Py / Python spelling
    EXPECT_DOUBLE_EQ(value("2 * -3 ** 2"), -18.0);
}

TEST(LSystemExpression, ComparisonsAndLogicGiveZeroOrOne) {
    EXPECT_EQ(value("1 < 2"), 1.0);
    EXPECT_EQ(value("2 <= 2"), 1.0);
    EXPECT_EQ(value("1 > 2"), 0.0);
    EXPECT_EQ(value("2 >= 3"), 0.0);
    EXPECT_EQ(value("1 + 1 == 2"), 1.0);
    EXPECT_EQ(value("1 != 1"), 0.0);
    EXPECT_EQ(value("3 > 2 && 2 > 1"), 1.0);
    EXPECT_EQ(value("0 || 0"), 0.0);
    EXPECT_EQ(value("0 || 7"), 1.0);
    EXPECT_EQ(value("5 && 7"), 1.0);
    EXPECT_EQ(value("!0"), 1.0);
    EXPECT_EQ(value("!5"), 0.0);
    EXPECT_EQ(value("1 || 0 && 0"), 1.0);  // && binds tighter than ||
    EXPECT_EQ(value("1 < 2 == 1"), 1.0);   // comparison binds tighter than ==
}

TEST(LSystemExpression, NumberForms) {
    EXPECT_DOUBLE_EQ(value("1e-3"), 0.001);
    EXPECT_DOUBLE_EQ(value(".5"), 0.5);
    EXPECT_DOUBLE_EQ(value("5."), 5.0);
    EXPECT_DOUBLE_EQ(value("1E+2"), 100.0);
    EXPECT_DOUBLE_EQ(value("c * 2"), 6.0);
}

TEST(LSystemExpression, TrigonometryUsesDegrees) {
    EXPECT_NEAR(value("sin(30)"), 0.5, 1e-15);
    EXPECT_NEAR(value("cos(60)"), 0.5, 1e-15);
    EXPECT_NEAR(value("tan(45)"), 1.0, 1e-15);
    EXPECT_NEAR(value("asin(0.5)"), 30.0, 1e-12);
    EXPECT_NEAR(value("acos(0.5)"), 60.0, 1e-12);
    EXPECT_NEAR(value("atan(1)"), 45.0, 1e-12);
    EXPECT_NEAR(value("atan2(1, -1)"), 135.0, 1e-12);
}

TEST(LSystemExpression, OtherFunctions) {
    EXPECT_DOUBLE_EQ(value("sqrt(16)"), 4.0);
    EXPECT_DOUBLE_EQ(value("abs(-3)"), 3.0);
    EXPECT_DOUBLE_EQ(value("min(2, -1)"), -1.0);
    EXPECT_DOUBLE_EQ(value("max(2, -1)"), 2.0);
    EXPECT_DOUBLE_EQ(value("pow(2, 10)"), 1024.0);
    EXPECT_DOUBLE_EQ(value("exp(0)"), 1.0);
    EXPECT_DOUBLE_EQ(value("log(exp(2))"), 2.0);
    EXPECT_DOUBLE_EQ(value("floor(-1.5)"), -2.0);
    EXPECT_DOUBLE_EQ(value("ceil(1.2)"), 2.0);
    EXPECT_DOUBLE_EQ(value("round(2.5)"), 3.0);
    EXPECT_DOUBLE_EQ(value("max(min(5, c), 1) + sqrt(abs(-4))"), 5.0);
}

TEST(LSystemExpression, FormalParametersAtDerivationTime) {
    EXPECT_DOUBLE_EQ(valueAt("x * 2 + 1", 3), 7.0);
    EXPECT_DOUBLE_EQ(valueAt("1 - x", 3), -2.0);
    EXPECT_DOUBLE_EQ(valueAt("12 / x", 3), 4.0);
    EXPECT_DOUBLE_EQ(valueAt("x / 4", 3), 0.75);
    EXPECT_DOUBLE_EQ(valueAt("x - 4", 3), -1.0);
    EXPECT_DOUBLE_EQ(valueAt("2 + x", 3), 5.0);
    EXPECT_DOUBLE_EQ(valueAt("x ^ 2 - x", 3), 6.0);
    EXPECT_DOUBLE_EQ(valueAt("-x", 3), -3.0);
    EXPECT_DOUBLE_EQ(valueAt("x > 2 && x < 4", 3), 1.0);
    EXPECT_DOUBLE_EQ(valueAt("x > 5 || x < 1", 3), 0.0);
}

TEST(LSystemExpression, LogicShortCircuits) {
    // The right side would divide by zero; it is never evaluated.
    EXPECT_DOUBLE_EQ(valueAt("x != 0 && 1 / x > 0", 0), 0.0);
    EXPECT_DOUBLE_EQ(valueAt("x == 0 || 1 / x > 0", 0), 1.0);
    EXPECT_DOUBLE_EQ(value("0 && 1 / (c - 3)"), 0.0);
}

TEST(LSystemExpression, FormalParametersShadowConstants) {
    LSystem s = parseLSystem("#define x 100\naxiom: A(1)\nA(x) -> B(x)");
    EXPECT_DOUBLE_EQ(deriveLSystem(s).params.at(0), 1.0);
}

TEST(LSystemExpression, CompilesToFlatCodeAndFoldsConstants) {
    std::vector<std::string> formals{"x"};
    detail::ConstantTable constants;
    constants.items.push_back(detail::Constant{"k", 2.0, true, false, false, 1});
    detail::ExprScope scope{&formals, &constants, true, ""};
    std::string text = "x * (k + 1) + sin(0)";
    detail::TextLine line{text, 1, nullptr};
    std::vector<detail::Instr> code;
    std::size_t pos = 0;
    detail::CompiledExpr e = detail::compileExpression(line, pos, scope, code);
    EXPECT_EQ(pos, text.size());
    EXPECT_FALSE(e.constant);
    // (k + 1) and sin(0) fold; x * 3 fuses into one instruction; + 0 stays.
    EXPECT_EQ(e.end - e.begin, 3u);
    Rng rng;
    double slots[1] = {4.0};
    double result = 0.0;
    ASSERT_EQ(detail::evaluate(code.data() + e.begin, code.data() + e.end, slots, rng, result),
              detail::EvalStatus::Ok);
    EXPECT_DOUBLE_EQ(result, 12.0);
    EXPECT_TRUE(constants.items[0].used);
}

TEST(LSystemExpression, EvaluationReportsDivisionByZeroAndNonFiniteValues) {
    std::vector<std::string> formals{"x"};
    detail::ExprScope scope{&formals, nullptr, true, ""};
    std::vector<detail::Instr> code;
    Rng rng;
    double result = 0.0;
    auto run = [&](const std::string& text, double x) {
        detail::TextLine line{text, 1, nullptr};
        std::size_t pos = 0;
        detail::CompiledExpr e = detail::compileExpression(line, pos, scope, code);
        return detail::evaluate(code.data() + e.begin, code.data() + e.end, &x, rng, result);
    };
    EXPECT_EQ(run("1 / x", 0.0), detail::EvalStatus::DivisionByZero);
    EXPECT_EQ(run("2 % x", 0.0), detail::EvalStatus::DivisionByZero);
    EXPECT_EQ(run("log(x)", 0.0), detail::EvalStatus::NonFinite);
    EXPECT_EQ(run("x * x", 1e200), detail::EvalStatus::NonFinite);
    EXPECT_EQ(run("exp(x) > 0", 1e5), detail::EvalStatus::NonFinite);
    EXPECT_EQ(run("x ^ 0.5", -1.0), detail::EvalStatus::NonFinite);
    EXPECT_EQ(run("x ^ 0.5", 4.0), detail::EvalStatus::Ok);
    EXPECT_DOUBLE_EQ(result, 2.0);
}

TEST(LSystemExpression, RandomFunctionsDrawFromTheGivenGenerator) {
    std::vector<std::string> formals;
    detail::ExprScope scope{&formals, nullptr, true, ""};
    std::string text = "rand() + uniform(10, 20) + gauss(0, 1)";
    detail::TextLine line{text, 1, nullptr};
    std::vector<detail::Instr> code;
    std::size_t pos = 0;
    detail::CompiledExpr e = detail::compileExpression(line, pos, scope, code);
    Rng a(77), b(77);
    double x = 0, y = 0;
    ASSERT_EQ(detail::evaluate(code.data() + e.begin, code.data() + e.end, nullptr, a, x),
              detail::EvalStatus::Ok);
    ASSERT_EQ(detail::evaluate(code.data() + e.begin, code.data() + e.end, nullptr, b, y),
              detail::EvalStatus::Ok);
    EXPECT_EQ(x, y);
    Rng c(77);
    double expected = c.uniform01();
    expected += c.uniform(10, 20);
    expected += c.gauss(0, 1);
    EXPECT_EQ(x, expected);
}

}  // namespace
}  // namespace ramus
