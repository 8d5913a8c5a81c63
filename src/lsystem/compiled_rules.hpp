// Internal: the productions of a parsed L-system in the flat form the derivation reads
// (src/lsystem/derive.cpp). Built once by the parser, shared read-only between copies.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "lsystem/expression.hpp"
#include "ramus/lsystem.hpp"

namespace ramus::detail {

inline constexpr std::uint32_t kNoSymbol = std::numeric_limits<std::uint32_t>::max();
inline constexpr std::int32_t kNoExpr = -1;

/// One module of a context pattern. Its formal parameters bind to slots
/// [firstSlot, firstSlot + arity). In a right context `[` and `]` appear as themselves.
struct PatternModule {
    std::uint32_t symbol = 0;
    std::uint16_t arity = 0;
    std::uint16_t firstSlot = 0;
};

/// A successor parameter computed at derivation time: params[paramIndex] of the successor
/// template (relative to the rule's first parameter) = value of exprs[expr].
struct DynamicParam {
    std::uint32_t paramIndex = 0;
    std::uint32_t expr = 0;
};

/// Where an expression's code lives and where it came from (for derivation-time errors).
struct ExprInfo {
    std::uint32_t codeBegin = 0;
    std::uint32_t codeEnd = 0;
    int line = 0;
    int column = 0;
    std::string text;
};

/// One production `left < pred > right : condition -> successor : weight`.
struct Rule {
    std::uint32_t symbol = 0;     ///< strict predecessor
    std::uint16_t arity = 0;      ///< its parameter count; the rule applies only to that count
    std::uint16_t slotCount = 0;  ///< predecessor + context formal parameters
    std::uint32_t leftBegin = 0, leftEnd = 0;        ///< CompiledRules::patterns, in text order
    std::uint32_t rightBegin = 0, rightEnd = 0;      ///< CompiledRules::patterns, in text order
    std::int32_t condition = kNoExpr;                ///< exprs index or kNoExpr
    std::int32_t weight = kNoExpr;                   ///< exprs index; set = stochastic rule
    std::uint32_t moduleBegin = 0, moduleEnd = 0;    ///< successorModules (relative paramOffset)
    std::uint32_t paramBegin = 0, paramEnd = 0;      ///< successorParams (constants filled in)
    std::uint32_t dynamicBegin = 0, dynamicEnd = 0;  ///< dynamicParams
    bool successorHasParams = false;                 ///< some successor module has parameters
    int line = 0;                                    ///< of the predecessor, for messages
    int column = 0;

    bool hasContext() const { return leftBegin != leftEnd || rightBegin != rightEnd; }
    /// Applies whenever symbol and arity match: no context, no condition, not stochastic.
    bool isUnconditional() const {
        return !hasContext() && condition == kNoExpr && weight == kNoExpr;
    }
};

/// How the derivation treats a module of a given symbol.
enum class SymbolKind : std::uint8_t {
    Identity,  ///< no production: copied unchanged
    Always,    ///< first rule is unconditional and all rules share its arity
    General,   ///< try the rules in file order
    Cut,       ///< `%`: removes itself and the rest of its branch
};

struct SymbolRules {
    std::uint32_t ruleBegin = 0;  ///< rules[ruleBegin, ruleEnd) have this predecessor symbol
    std::uint32_t ruleEnd = 0;
    SymbolKind kind = SymbolKind::Identity;
};

/// All productions, grouped by predecessor symbol (file order kept within a symbol).
struct CompiledRules {
    std::vector<Rule> rules;
    std::vector<SymbolRules> bySymbol;  ///< indexed by symbol id; size = symbol count
    std::vector<PatternModule> patterns;
    std::vector<Module> successorModules;
    std::vector<double> successorParams;
    std::vector<DynamicParam> dynamicParams;
    std::vector<ExprInfo> exprs;
    std::vector<Instr> code;
    std::vector<std::uint8_t> ignored;  ///< by symbol id: skipped when matching contexts

    std::uint32_t openSymbol = kNoSymbol;   ///< `[`
    std::uint32_t closeSymbol = kNoSymbol;  ///< `]`
    bool hasLeftContext = false;
    bool hasRightContext = false;
    bool hasRightBrackets = false;  ///< some right context contains `[` `]`
    std::uint16_t maxSlots = 0;
    std::uint32_t maxSuccessorModules = 0;
    std::uint32_t maxSuccessorParams = 0;
    std::uint16_t maxRightDepth = 0;  ///< deepest `[` nesting in a right context
};

}  // namespace ramus::detail
