// Based on: precedence-climbing recursive descent (Wirth, "Compiler Construction", ch. 5)
// emitting postfix code for a stack machine; operator set after cpfg's expression language
// (Prusinkiewicz, Hanan, Mech: "An L-system-based plant modeling language", AGTIVE 1999).
#include <charconv>
#include <cmath>

#include "lsystem/expression.hpp"

namespace ramus::detail {
namespace {

struct FunctionInfo {
    std::string_view name;
    int arity;
    Op op;
    bool random;
};

constexpr FunctionInfo kFunctions[] = {
    {"sin", 1, Op::Sin, false},        {"cos", 1, Op::Cos, false},
    {"tan", 1, Op::Tan, false},        {"asin", 1, Op::Asin, false},
    {"acos", 1, Op::Acos, false},      {"atan", 1, Op::Atan, false},
    {"atan2", 2, Op::Atan2, false},    {"sqrt", 1, Op::Sqrt, false},
    {"abs", 1, Op::Abs, false},        {"min", 2, Op::Min, false},
    {"max", 2, Op::Max, false},        {"pow", 2, Op::Pow, false},
    {"exp", 1, Op::Exp, false},        {"log", 1, Op::Log, false},
    {"floor", 1, Op::Floor, false},    {"ceil", 1, Op::Ceil, false},
    {"round", 1, Op::Round, false},    {"rand", 0, Op::Rand, true},
    {"uniform", 2, Op::Uniform, true}, {"gauss", 2, Op::Gauss, true},
};

const FunctionInfo* findFunction(std::string_view name) {
    for (const auto& f : kFunctions) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

constexpr int kMaxNesting = 48;

/// Recursive-descent compiler for one expression. Precedence, lowest first:
/// || , && , == != , < <= > >= , + - , * / % , unary - + ! , ^ (right-assoc), primary.
class Compiler {
public:
    Compiler(const TextLine& line, const ExprScope& scope, std::vector<Instr>& code)
        : line_(line), text_(line.text), scope_(scope), code_(code) {}

    CompiledExpr run(std::size_t& pos) {
        pos_ = skipSpaces(text_, pos);
        CompiledExpr result;
        result.textBegin = pos_;
        result.begin = static_cast<std::uint32_t>(code_.size());
        parseOr();
        result.end = static_cast<std::uint32_t>(code_.size());
        result.textEnd = pos_;
        while (result.textEnd > result.textBegin && isSpaceChar(text_[result.textEnd - 1])) {
            --result.textEnd;
        }
        if (result.end == result.begin + 1 && code_[result.begin].op == Op::Const) {
            result.constant = true;
            result.value = code_[result.begin].value;
        }
        pos = pos_;
        return result;
    }

private:
    // --- helpers -------------------------------------------------------------------------
    char peek(std::size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }
    void skip() { pos_ = skipSpaces(text_, pos_); }
    bool accept(std::string_view token) {
        if (text_.substr(pos_, token.size()) != token) return false;
        pos_ += token.size();
        skip();
        return true;
    }
    [[noreturn]] void fail(std::size_t at, const std::string& message) const {
        line_.fail(at, message);
    }
    void push(int n) {
        stack_ += n;
        if (stack_ > kEvalStackSize) {
            fail(pos_, "expression too large; expected at most " + std::to_string(kEvalStackSize) +
                           " pending operands");
        }
    }
    void enter(std::size_t at) {
        if (++nesting_ > kMaxNesting) {
            fail(at, "expression nested too deeply; expected at most " +
                         std::to_string(kMaxNesting) + " levels");
        }
    }
    void leave() { --nesting_; }
    /// " in the axiom" etc., or "" when the scope names no place.
    std::string where() const {
        return scope_.where && *scope_.where ? std::string(" ") + scope_.where : std::string();
    }
    bool isConst(std::size_t at) const { return code_[at].op == Op::Const; }

    // --- emission with constant folding ------------------------------------------------
    void emitConst(double v) {
        Instr in;
        in.op = Op::Const;
        in.value = v;
        code_.push_back(in);
    }
    /// Emits `op` over the `operands` values whose code starts at `begin`; folds when every
    /// operand is a single constant and the op is not random.
    void emitOp(Op op, std::size_t begin, int operands, bool random, std::size_t at) {
        if ((op == Op::Div || op == Op::Mod) && dead_ == 0 && isConst(code_.size() - 1) &&
            code_.back().value == 0.0) {
            fail(at, "division by zero; expected a non-zero divisor");
        }
        Instr in;
        in.op = op;
        code_.push_back(in);
        push(1 - operands);
        if (fuseSlotConst(begin)) return;
        bool foldable = !random && code_.size() == begin + static_cast<std::size_t>(operands) + 1;
        for (int k = 0; foldable && k < operands; ++k) foldable = isConst(begin + k);
        if (!foldable) return;
        Rng unused;
        double value = 0.0;
        EvalStatus st =
            evaluate(code_.data() + begin, code_.data() + code_.size(), nullptr, unused, value);
        if (st != EvalStatus::Ok && dead_ > 0) {
            value = 0.0;  // never evaluated (short-circuit): the code is dropped anyway
        } else if (st == EvalStatus::DivisionByZero) {
            fail(at, "division by zero in a constant expression; expected a non-zero divisor");
        } else if (st == EvalStatus::NonFinite) {
            fail(at,
                 "constant expression has no finite value (NaN or infinity); expected "
                 "arguments inside the function's domain");
        }
        code_.resize(begin);
        emitConst(value);
    }

    /// Peephole: `slot op const` / `const op slot` for + - * / becomes one fused instruction.
    bool fuseSlotConst(std::size_t begin) {
        if (code_.size() != begin + 3) return false;
        const Instr a = code_[begin];
        const Instr b = code_[begin + 1];
        const Op op = code_[begin + 2].op;
        if (op != Op::Add && op != Op::Sub && op != Op::Mul && op != Op::Div) return false;
        Instr fused;
        if (a.op == Op::Slot && b.op == Op::Const) {
            fused.arg = a.arg;
            fused.value = b.value;
            fused.op = op == Op::Add   ? Op::AddSC
                       : op == Op::Sub ? Op::SubSC
                       : op == Op::Mul ? Op::MulSC
                                       : Op::DivSC;
        } else if (a.op == Op::Const && b.op == Op::Slot) {
            fused.arg = b.arg;
            fused.value = a.value;
            fused.op = op == Op::Add   ? Op::AddSC
                       : op == Op::Sub ? Op::RSubSC
                       : op == Op::Mul ? Op::MulSC
                                       : Op::RDivSC;
        } else {
            return false;
        }
        code_.resize(begin);
        code_.push_back(fused);
        return true;
    }

    // --- grammar -----------------------------------------------------------------------
    void parseOr() { parseLogic(true); }
    void parseLogic(bool isOr) {
        std::size_t begin = code_.size();
        if (isOr) {
            parseLogic(false);
        } else {
            parseEquality();
        }
        const char* token = isOr ? "||" : "&&";
        while (peek() == token[0] && peek(1) == token[1]) {
            std::size_t at = pos_;
            accept(token);
            emitShortCircuit(isOr, begin, at);
        }
    }
    void emitShortCircuit(bool isOr, std::size_t begin, std::size_t at) {
        bool lhsConst = code_.size() == begin + 1 && isConst(begin);
        if (lhsConst) {
            double lhs = code_[begin].value;
            bool decided = isOr ? lhs != 0.0 : lhs == 0.0;
            code_.resize(begin);
            push(-1);
            std::size_t rhsBegin = code_.size();
            dead_ += decided ? 1 : 0;
            isOr ? parseLogic(false) : parseEquality();
            dead_ -= decided ? 1 : 0;
            if (decided) {
                code_.resize(rhsBegin);  // right side never evaluated: drop it
                push(-1);
                emitConst(isOr ? 1.0 : 0.0);
                push(1);
            } else {
                emitOp(Op::ToBool, rhsBegin, 1, false, at);
            }
            return;
        }
        std::size_t jump = code_.size();
        Instr in;
        in.op = isOr ? Op::OrJump : Op::AndJump;
        code_.push_back(in);
        push(-1);
        std::size_t rhsBegin = code_.size();
        isOr ? parseLogic(false) : parseEquality();
        emitOp(Op::ToBool, rhsBegin, 1, false, at);
        code_[jump].arg = static_cast<std::uint32_t>(code_.size() - jump);
    }
    void parseEquality() {
        std::size_t begin = code_.size();
        parseComparison();
        for (;;) {
            std::size_t at = pos_;
            Op op;
            if (peek() == '=' && peek(1) == '=') {
                op = Op::Eq;
            } else if (peek() == '!' && peek(1) == '=') {
                op = Op::Ne;
            } else {
                break;
            }
            pos_ += 2;
            skip();
            parseComparison();
            emitOp(op, begin, 2, false, at);
        }
    }
    void parseComparison() {
        std::size_t begin = code_.size();
        parseAdditive();
        for (;;) {
            std::size_t at = pos_;
            char c = peek();
            if (c != '<' && c != '>') break;
            bool orEqual = peek(1) == '=';
            Op op = c == '<' ? (orEqual ? Op::Le : Op::Lt) : (orEqual ? Op::Ge : Op::Gt);
            pos_ += orEqual ? 2 : 1;
            skip();
            parseAdditive();
            emitOp(op, begin, 2, false, at);
        }
    }
    void parseAdditive() {
        std::size_t begin = code_.size();
        parseTerm();
        while (peek() == '+' || peek() == '-') {
            std::size_t at = pos_;
            Op op = peek() == '+' ? Op::Add : Op::Sub;
            ++pos_;
            skip();
            parseTerm();
            emitOp(op, begin, 2, false, at);
        }
    }
    void parseTerm() {
        std::size_t begin = code_.size();
        parseUnary();
        while ((peek() == '*' && peek(1) != '*') || peek() == '/' || peek() == '%') {
            std::size_t at = pos_;
            Op op = peek() == '*' ? Op::Mul : peek() == '/' ? Op::Div : Op::Mod;
            ++pos_;
            skip();
            parseUnary();
            emitOp(op, begin, 2, false, at);
        }
    }
    void parseUnary() {
        char c = peek();
        if ((c == '-' || c == '+' || c == '!') && peek(1) != '=') {
            std::size_t at = pos_;
            enter(at);
            ++pos_;
            skip();
            std::size_t begin = code_.size();
            parseUnary();
            if (c != '+') emitOp(c == '-' ? Op::Neg : Op::Not, begin, 1, false, at);
            leave();
            return;
        }
        parsePower();
    }
    void parsePower() {
        std::size_t begin = code_.size();
        parsePrimary();
        bool caret = peek() == '^';
        if (caret || (peek() == '*' && peek(1) == '*')) {
            std::size_t at = pos_;
            enter(at);
            pos_ += caret ? 1 : 2;
            skip();
            parseUnary();  // right-associative; the exponent may carry a sign: 2^-1
            emitOp(Op::Pow, begin, 2, false, at);
            leave();
        }
    }
    void parsePrimary() {
        char c = peek();
        if (isDigitChar(c) || (c == '.' && isDigitChar(peek(1)))) return parseNumber();
        if (isIdentStart(c)) return parseIdentifier();
        if (c == '(') {
            std::size_t open = pos_;
            enter(open);
            ++pos_;
            skip();
            parseOr();
            if (peek() != ')') {
                fail(pos_, "missing ')' for the '(' at column " +
                               std::to_string(line_.locAt(open).column) + "; expected ')', got " +
                               describeChar(text_, pos_));
            }
            ++pos_;
            skip();
            leave();
            return;
        }
        if (c == '=') {
            fail(pos_, "'=' is not an operator; expected '==' for comparison");
        }
        fail(pos_, "malformed expression" + where() + "; expected a number, a name or '(', got " +
                       describeChar(text_, pos_));
    }
    void parseNumber();
    void parseIdentifier();
    void parseCall(const FunctionInfo& f, std::size_t at);
    void emitVariable(std::string_view name, std::size_t at);

    const TextLine& line_;
    std::string_view text_;
    const ExprScope& scope_;
    std::vector<Instr>& code_;
    std::size_t pos_ = 0;
    int stack_ = 0;
    int nesting_ = 0;
    int dead_ = 0;  ///< > 0 while compiling code that short-circuiting never evaluates
};

void Compiler::parseNumber() {
    std::size_t start = pos_;
    std::size_t p = pos_;
    while (p < text_.size() && isDigitChar(text_[p])) ++p;
    if (p < text_.size() && text_[p] == '.') {
        ++p;
        while (p < text_.size() && isDigitChar(text_[p])) ++p;
    }
    if (p < text_.size() && (text_[p] == 'e' || text_[p] == 'E')) {
        std::size_t q = p + 1;
        if (q < text_.size() && (text_[q] == '+' || text_[q] == '-')) ++q;
        if (q >= text_.size() || !isDigitChar(text_[q])) {
            fail(start, "bad number '" + std::string(text_.substr(start, q - start)) +
                            "'; expected digits after the exponent 'e'");
        }
        p = q;
        while (p < text_.size() && isDigitChar(text_[p])) ++p;
    }
    if (p < text_.size() && (isIdentChar(text_[p]) || text_[p] == '.')) {
        std::size_t q = p;
        while (q < text_.size() && (isIdentChar(text_[q]) || text_[q] == '.')) ++q;
        fail(start, "bad number '" + std::string(text_.substr(start, q - start)) +
                        "'; expected digits, '.', or an exponent like 1e-3");
    }
    double value = 0.0;
    auto res = std::from_chars(text_.data() + start, text_.data() + p, value);
    if (res.ec != std::errc() || !std::isfinite(value)) {
        fail(start, "number '" + std::string(text_.substr(start, p - start)) +
                        "' is out of range; expected a magnitude below 1e308");
    }
    pos_ = p;
    skip();
    emitConst(value);
    push(1);
}

void Compiler::parseIdentifier() {
    std::size_t start = pos_;
    while (pos_ < text_.size() && isIdentChar(text_[pos_])) ++pos_;
    std::string_view name = text_.substr(start, pos_ - start);
    skip();
    if (peek() == '(') {
        const FunctionInfo* f = findFunction(name);
        if (!f) {
            fail(start, "unknown function '" + std::string(name) + "'; expected one of " +
                            builtinFunctionList());
        }
        return parseCall(*f, start);
    }
    emitVariable(name, start);
}

void Compiler::parseCall(const FunctionInfo& f, std::size_t at) {
    if (f.random && !scope_.allowRandom) {
        fail(at, "random function '" + std::string(f.name) + "()' is not allowed" + where() +
                     "; expected a constant expression (random numbers are drawn only while "
                     "deriving)");
    }
    enter(at);
    ++pos_;  // '('
    skip();
    std::size_t begin = code_.size();
    int count = 0;
    if (peek() != ')') {
        for (;;) {
            parseOr();
            ++count;
            if (peek() == ',') {
                ++pos_;
                skip();
                continue;
            }
            break;
        }
    }
    if (peek() != ')') {
        fail(pos_, "missing ')' after the arguments of '" + std::string(f.name) +
                       "'; expected ',' or ')', got " + describeChar(text_, pos_));
    }
    ++pos_;
    skip();
    if (count != f.arity) {
        fail(at, "function '" + std::string(f.name) + "' takes " + std::to_string(f.arity) +
                     (f.arity == 1 ? " argument" : " arguments") + "; got " +
                     std::to_string(count));
    }
    emitOp(f.op, begin, f.arity, f.random, at);
    leave();
}

void Compiler::emitVariable(std::string_view name, std::size_t at) {
    if (scope_.formals) {
        const auto& formals = *scope_.formals;
        for (std::size_t i = 0; i < formals.size(); ++i) {
            if (formals[i] == name) {
                Instr in;
                in.op = Op::Slot;
                in.arg = static_cast<std::uint32_t>(i);
                code_.push_back(in);
                push(1);
                return;
            }
        }
    }
    if (scope_.constants) {
        if (Constant* c = scope_.constants->find(name)) {
            c->used = true;
            emitConst(c->value);
            push(1);
            return;
        }
    }
    std::string expected = "a #define constant";
    if (scope_.formals && !scope_.formals->empty()) {
        expected = "a formal parameter (";
        for (std::size_t i = 0; i < scope_.formals->size(); ++i) {
            expected += (i ? ", " : "") + (*scope_.formals)[i];
        }
        expected += ") or a #define constant";
    }
    if (findFunction(name)) expected = quoted(std::string(name) + "(…)") + " to call the function";
    fail(at, "unknown identifier '" + std::string(name) + "'" + where() + "; expected " + expected);
}

}  // namespace

Constant* ConstantTable::find(std::string_view name) {
    for (auto& c : items) {
        if (c.name == name && (c.defined || c.fromOverride)) return &c;
    }
    return nullptr;
}

CompiledExpr compileExpression(const TextLine& line, std::size_t& pos, const ExprScope& scope,
                               std::vector<Instr>& code) {
    Compiler compiler(line, scope, code);
    return compiler.run(pos);
}

bool isBuiltinFunction(std::string_view name) { return findFunction(name) != nullptr; }

std::string builtinFunctionList() {
    std::string list;
    for (const auto& f : kFunctions) {
        if (!list.empty()) list += ", ";
        list += std::string(f.name) + (f.arity == 0 ? "()" : "");
    }
    return list;
}

}  // namespace ramus::detail
