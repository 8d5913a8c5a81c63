// Internal: arithmetic expressions of the .lsys language compiled once into flat postfix code
// and evaluated with a small fixed stack (no allocation per evaluation).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/text_line.hpp"
#include "ramus/rng.hpp"

namespace ramus::detail {

/// Instructions of the stack machine. Binary operators pop two values and push one.
enum class Op : std::uint8_t {
    Const,  ///< push value
    Slot,   ///< push slots[arg] (a formal parameter)
    Neg,
    Not,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Pow,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    AndJump,  ///< top == 0: replace by 0 and jump by arg; else pop (short-circuit &&)
    OrJump,   ///< top != 0: replace by 1 and jump by arg; else pop (short-circuit ||)
    ToBool,   ///< top = (top != 0)
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sqrt,
    Abs,
    Min,
    Max,
    Exp,
    Log,
    Floor,
    Ceil,
    Round,
    Rand,
    Uniform,
    Gauss,
    // Fused forms of the most common successor expressions (`l*r`, `x+1`, …): push
    // slots[arg] op value (or value op slots[arg] for the R forms) in one step.
    AddSC,
    SubSC,
    MulSC,
    DivSC,
    RSubSC,
    RDivSC,
};

/// One instruction: 16 bytes.
struct Instr {
    double value = 0.0;     ///< Const: the value
    std::uint32_t arg = 0;  ///< Slot: slot index; AndJump/OrJump: forward distance
    Op op = Op::Const;
};

/// Evaluation stack size; the compiler rejects expressions that would need more.
inline constexpr int kEvalStackSize = 128;

/// Result of evaluate().
enum class EvalStatus : std::uint8_t { Ok, DivisionByZero, NonFinite };

/// A `#define` constant (or a `--set` override).
struct Constant {
    std::string name;
    double value = 0.0;
    bool defined = false;       ///< has a #define line
    bool fromOverride = false;  ///< value comes from ParseOptions::constantOverrides
    bool used = false;          ///< referenced by some expression
    int line = 0;               ///< line of the #define, 0 if none
};

/// Constants by name, in definition order.
struct ConstantTable {
    std::vector<Constant> items;
    /// The constant `name` that expressions may use (defined or overridden), else nullptr.
    Constant* find(std::string_view name);
};

/// How identifiers resolve and what is allowed while compiling one expression.
struct ExprScope {
    const std::vector<std::string>* formals = nullptr;  ///< formal parameters; index = slot
    ConstantTable* constants = nullptr;
    bool allowRandom = false;  ///< rand/uniform/gauss allowed (not in constant expressions)
    const char* where = "";    ///< for messages, e.g. "in the axiom"
};

/// A compiled expression: code[begin, end) of the pool it was compiled into.
struct CompiledExpr {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    bool constant = false;      ///< folded to one Const (no parameters, no random functions)
    double value = 0.0;         ///< the value when constant
    std::size_t textBegin = 0;  ///< byte range of the source text in its line
    std::size_t textEnd = 0;
};

/// Compiles the expression that starts at byte `pos` of `line`, appending code to `code`.
/// Stops at the first character that cannot continue it (`,` `)` `:` end of line, …) and sets
/// `pos` there. Constant subexpressions are folded. Throws Error with the location on unknown
/// identifiers or functions, wrong argument counts, bad numbers, or a malformed expression.
CompiledExpr compileExpression(const TextLine& line, std::size_t& pos, const ExprScope& scope,
                               std::vector<Instr>& code);

/// Evaluates code[begin, end) with formal parameter values `slots`, drawing random numbers from
/// `rng`. Every intermediate value is checked: stops with DivisionByZero (x/0, x%0) or
/// NonFinite (NaN or ±inf from a function or overflow). `result` is set only on Ok.
EvalStatus evaluate(const Instr* begin, const Instr* end, const double* slots, Rng& rng,
                    double& result);

/// True when `name` is a built-in function (sin, rand, …).
bool isBuiltinFunction(std::string_view name);

/// evaluate() with the one-instruction programs (a parameter, or a parameter combined with a
/// constant) handled inline, which covers most successor parameters.
inline EvalStatus evaluateExpr(const Instr* begin, const Instr* end, const double* slots, Rng& rng,
                               double& result) {
    if (end - begin != 1) return evaluate(begin, end, slots, rng, result);
    const double s = slots[begin->arg];
    const double c = begin->value;
    double v;
    switch (begin->op) {
        case Op::Slot:
            result = s;
            return EvalStatus::Ok;
        case Op::Const:
            result = c;
            return EvalStatus::Ok;
        case Op::AddSC:
            v = s + c;
            break;
        case Op::SubSC:
            v = s - c;
            break;
        case Op::MulSC:
            v = s * c;
            break;
        case Op::DivSC:
            v = s / c;
            break;
        case Op::RSubSC:
            v = c - s;
            break;
        default:
            return evaluate(begin, end, slots, rng, result);
    }
    if (!std::isfinite(v)) return EvalStatus::NonFinite;
    result = v;
    return EvalStatus::Ok;
}

/// Names of the built-in functions, comma separated, for messages and docs.
std::string builtinFunctionList();

}  // namespace ramus::detail
