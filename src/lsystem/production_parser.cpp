// Based on: productions of ABOP §1.8 (context-sensitive, "al < a > ar"), §1.7 (stochastic),
// §2.1–2.2 (parametric, with conditions), written in cpfg order
// "left < pred > right : condition -> successor : weight" (docs/lsystem.md, "Productions").
#include <algorithm>

#include "lsystem/parser.hpp"

namespace ramus::detail {
namespace {

/// First `c` in text[begin, end) outside parentheses, or npos.
std::size_t findTopLevel(std::string_view text, std::size_t begin, std::size_t end, char c) {
    int depth = 0;
    for (std::size_t i = begin; i < end && i < text.size(); ++i) {
        if (text[i] == '(') {
            ++depth;
        } else if (text[i] == ')') {
            if (depth > 0) --depth;
        } else if (depth == 0 && text[i] == c) {
            return i;
        }
    }
    return kNpos;
}

}  // namespace

void LSystemParser::parseProduction(const TextLine& line, std::size_t arrow,
                                    std::size_t arrowLength) {
    std::string_view t = line.text;
    Rule rule;
    rule.line = line.number;
    rule.column = line.locAt(skipSpaces(t, 0)).column;

    // Predecessor with contexts, then the condition between ':' and the arrow.
    std::size_t colon = findTopLevel(t, 0, arrow, ':');
    std::vector<std::string> formals;
    parsePredecessor(line, colon == kNpos ? arrow : colon, rule, formals);
    ExprScope scope{&formals, &constants_, true, "in this production"};
    // cpfg/ABOP write `: *` for "no condition".
    if (colon != kNpos && trimSpaces(t.substr(colon + 1, arrow - colon - 1)) != "*") {
        rule.condition = compileClause(line, colon + 1, arrow, scope, "'->'");
        const ExprInfo& cond = rules_->exprs[rule.condition];
        const Instr& first = rules_->code[cond.codeBegin];
        if (cond.codeEnd == cond.codeBegin + 1 && first.op == Op::Const && first.value != 0.0) {
            rule.condition = kNoExpr;  // always true
        }
    }

    // Successor, then the stochastic weight after a second ':'.
    std::size_t succBegin = arrow + arrowLength;
    std::size_t weightColon = findTopLevel(t, succBegin, t.size(), ':');
    std::size_t succEnd = weightColon == kNpos ? t.size() : weightColon;
    auto word = parseWord(line, succBegin, succEnd, WordMode::Successor, &scope);
    checkBrackets(line, word, "successor");
    buildSuccessor(line, word, rule);
    if (weightColon != kNpos) {
        rule.weight = compileClause(line, weightColon + 1, t.size(), scope, "the end of line");
    }
    fileRules_.push_back(rule);
}

void LSystemParser::parsePredecessor(const TextLine& line, std::size_t end, Rule& rule,
                                     std::vector<std::string>& formals) {
    std::string_view t = line.text;
    auto [lt, gt] = findContextMarkers(line, end);
    std::size_t predBegin = lt == kNpos ? 0 : lt + 1;
    std::size_t predEnd = gt == kNpos ? end : gt;
    auto pred = parseWord(line, predBegin, predEnd, WordMode::Pattern, nullptr);
    if (pred.empty()) {
        line.fail(skipSpaces(t, predBegin), "missing predecessor; expected a module before " +
                                                std::string(gt != kNpos ? "'>'" : "'->'"));
    }
    if (pred.size() > 1) {
        line.fail(pred[1].offset, "a production rewrites one module, but a second one follows '" +
                                      system_.symbols.names[pred[0].symbol] +
                                      "'; expected '->', or '<' and '>' around context modules");
    }
    const std::string& name = system_.symbols.names[pred[0].symbol];
    if (name == "[" || name == "]" || name == "%") {
        line.fail(pred[0].offset, "'" + name + "' cannot be rewritten (" +
                                      (name == "%" ? "it is the cut symbol" : "it is a bracket") +
                                      "); expected another predecessor module");
    }
    rule.symbol = pred[0].symbol;
    rule.arity = static_cast<std::uint16_t>(pred[0].formals.size());
    std::vector<std::size_t> offsets;
    addPattern(line, pred, formals, offsets, false);

    // cpfg/ABOP write `*` for "any context": `* < A > * -> B` is the same as `A -> B`.
    if (lt != kNpos && trimSpaces(t.substr(0, lt)) != "*") {
        parseLeftContext(line, lt, rule, formals, offsets);
    }
    if (gt != kNpos && trimSpaces(t.substr(gt + 1, end - gt - 1)) != "*") {
        parseRightContext(line, gt, end, rule, formals, offsets);
    }
    if (formals.size() > 65535) line.fail(0, "too many formal parameters; expected at most 65535");
    rule.slotCount = static_cast<std::uint16_t>(formals.size());
    rules_->maxSlots = std::max(rules_->maxSlots, rule.slotCount);
}

std::pair<std::size_t, std::size_t> LSystemParser::findContextMarkers(const TextLine& line,
                                                                      std::size_t end) const {
    std::string_view t = line.text;
    std::size_t lt = findTopLevel(t, 0, end, '<');
    std::size_t gt = findTopLevel(t, 0, end, '>');
    if (lt != kNpos && findTopLevel(t, lt + 1, end, '<') != kNpos) {
        line.fail(findTopLevel(t, lt + 1, end, '<'),
                  "second '<' in the predecessor; expected 'left < predecessor > right'");
    }
    if (gt != kNpos && findTopLevel(t, gt + 1, end, '>') != kNpos) {
        line.fail(findTopLevel(t, gt + 1, end, '>'),
                  "second '>' in the predecessor; expected 'left < predecessor > right'");
    }
    if (lt != kNpos && gt != kNpos && gt < lt) {
        line.fail(gt, "'>' before '<'; expected 'left < predecessor > right'");
    }
    return {lt, gt};
}

void LSystemParser::parseLeftContext(const TextLine& line, std::size_t lt, Rule& rule,
                                     std::vector<std::string>& formals,
                                     std::vector<std::size_t>& offsets) {
    auto left = parseWord(line, 0, lt, WordMode::Pattern, nullptr);
    if (left.empty()) line.fail(lt, "empty left context; expected modules before '<'");
    for (const auto& m : left) {
        if (m.symbol == rules_->openSymbol || m.symbol == rules_->closeSymbol) {
            line.fail(m.offset,
                      "brackets are not allowed in a left context (branches are skipped "
                      "there); expected modules");
        }
    }
    rule.leftBegin = static_cast<std::uint32_t>(rules_->patterns.size());
    addPattern(line, left, formals, offsets, true);
    rule.leftEnd = static_cast<std::uint32_t>(rules_->patterns.size());
    rules_->hasLeftContext = true;
}

void LSystemParser::parseRightContext(const TextLine& line, std::size_t gt, std::size_t end,
                                      Rule& rule, std::vector<std::string>& formals,
                                      std::vector<std::size_t>& offsets) {
    auto right = parseWord(line, gt + 1, end, WordMode::Pattern, nullptr);
    if (right.empty()) line.fail(gt, "empty right context; expected modules after '>'");
    checkBrackets(line, right, "right context");
    rule.rightBegin = static_cast<std::uint32_t>(rules_->patterns.size());
    addPattern(line, right, formals, offsets, true);
    rule.rightEnd = static_cast<std::uint32_t>(rules_->patterns.size());
    rules_->hasRightContext = true;
    // The matcher keeps a stack of entered branches as deep as the deepest pattern.
    int depth = 0;
    for (const auto& m : right) {
        if (m.symbol == rules_->openSymbol) {
            rules_->hasRightBrackets = true;
            ++depth;
            rules_->maxRightDepth =
                std::max(rules_->maxRightDepth, static_cast<std::uint16_t>(depth));
        } else if (m.symbol == rules_->closeSymbol) {
            --depth;
        }
    }
}

void LSystemParser::addPattern(const TextLine& line, const std::vector<WordModule>& word,
                               std::vector<std::string>& formals,
                               std::vector<std::size_t>& formalOffsets, bool isContext) {
    for (const auto& m : word) {
        if (isContext && isIgnored(m.symbol)) {
            line.fail(m.offset, "'" + system_.symbols.names[m.symbol] +
                                    "' is skipped when matching contexts (ignore:/consider:), "
                                    "so it can never match here; expected a module that is "
                                    "not ignored");
        }
        PatternModule p;
        p.symbol = m.symbol;
        p.arity = static_cast<std::uint16_t>(m.formals.size());
        p.firstSlot = static_cast<std::uint16_t>(std::min<std::size_t>(formals.size(), 65535));
        for (const auto& [name, offset] : m.formals) {
            auto it = std::find(formals.begin(), formals.end(), name);
            if (it != formals.end()) {
                int column = line.locAt(formalOffsets[it - formals.begin()]).column;
                line.fail(offset, "formal parameter '" + name +
                                      "' is already used in this production (column " +
                                      std::to_string(column) + "); expected a distinct name");
            }
            formals.push_back(name);
            formalOffsets.push_back(offset);
        }
        if (isContext) rules_->patterns.push_back(p);
    }
}

std::int32_t LSystemParser::addExpr(const TextLine& line, const CompiledExpr& expr) {
    ExprInfo info;
    info.codeBegin = expr.begin;
    info.codeEnd = expr.end;
    info.line = line.number;
    info.column = line.locAt(expr.textBegin).column;
    info.text = std::string(line.text.substr(expr.textBegin, expr.textEnd - expr.textBegin));
    rules_->exprs.push_back(std::move(info));
    return static_cast<std::int32_t>(rules_->exprs.size() - 1);
}

void LSystemParser::buildSuccessor(const TextLine& line, const std::vector<WordModule>& word,
                                   Rule& rule) {
    CompiledRules& r = *rules_;
    rule.moduleBegin = static_cast<std::uint32_t>(r.successorModules.size());
    rule.paramBegin = static_cast<std::uint32_t>(r.successorParams.size());
    rule.dynamicBegin = static_cast<std::uint32_t>(r.dynamicParams.size());
    std::uint32_t relative = 0;
    for (const auto& m : word) {
        Module mod;
        mod.symbol = m.symbol;
        mod.paramCount = static_cast<std::uint16_t>(m.params.size());
        mod.paramOffset = m.params.empty() ? 0 : relative;
        for (const auto& e : m.params) {
            if (e.constant) {
                r.successorParams.push_back(e.value);
            } else {
                r.successorParams.push_back(0.0);
                DynamicParam d;
                d.paramIndex = relative;
                d.expr = static_cast<std::uint32_t>(addExpr(line, e));
                r.dynamicParams.push_back(d);
            }
            ++relative;
        }
        rule.successorHasParams = rule.successorHasParams || !m.params.empty();
        r.successorModules.push_back(mod);
    }
    rule.moduleEnd = static_cast<std::uint32_t>(r.successorModules.size());
    rule.paramEnd = static_cast<std::uint32_t>(r.successorParams.size());
    rule.dynamicEnd = static_cast<std::uint32_t>(r.dynamicParams.size());
    r.maxSuccessorModules = std::max(r.maxSuccessorModules, rule.moduleEnd - rule.moduleBegin);
    r.maxSuccessorParams = std::max(r.maxSuccessorParams, rule.paramEnd - rule.paramBegin);
}

std::int32_t LSystemParser::compileClause(const TextLine& line, std::size_t begin, std::size_t end,
                                          const ExprScope& scope, const char* expectedAfter) {
    TextLine sub = line;
    sub.text = line.text.substr(0, end);
    std::size_t pos = begin;
    CompiledExpr e = compileExpression(sub, pos, scope, rules_->code);
    pos = skipSpaces(sub.text, pos);
    if (pos < end) {
        line.fail(pos, "unexpected " + describeChar(sub.text, pos) +
                           " after the expression; expected an operator or " + expectedAfter);
    }
    return addExpr(line, e);
}

}  // namespace ramus::detail
