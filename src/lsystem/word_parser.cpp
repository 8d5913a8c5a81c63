// Based on: module words in ABOP notation (ABOP §1.10, §2.1: "A(a1,…,an)"); tokenization as in
// cpfg, where every character is a module unless multi-letter names are declared
// (docs/lsystem.md, "Modules").
#include <algorithm>

#include "lsystem/parser.hpp"

namespace ramus::detail {
namespace {

constexpr std::size_t kMaxParams = 65535;  // Module::paramCount is 16 bits

}  // namespace

std::uint32_t LSystemParser::internSymbol(std::string_view name) {
    auto it = symbolIds_.find(std::string(name));
    if (it != symbolIds_.end()) return it->second;
    auto id = static_cast<std::uint32_t>(system_.symbols.names.size());
    system_.symbols.names.emplace_back(name);
    symbolIds_.emplace(std::string(name), id);
    if (name == "[") rules_->openSymbol = id;
    if (name == "]") rules_->closeSymbol = id;
    return id;
}

std::size_t LSystemParser::moduleNameLength(std::string_view text, std::size_t pos) const {
    std::size_t best = charLength(text, pos);
    for (const auto& name : multiNames_) {
        if (name.size() > best && text.compare(pos, name.size(), name) == 0) best = name.size();
    }
    return best;
}

bool LSystemParser::isIgnored(std::uint32_t symbol) const {
    if (symbol == rules_->openSymbol || symbol == rules_->closeSymbol) return false;
    bool listed = symbol < listed_.size() && listed_[symbol];
    return considerMode_ ? !listed : listed;
}

std::vector<WordModule> LSystemParser::parseWord(const TextLine& line, std::size_t begin,
                                                 std::size_t end, WordMode mode,
                                                 const ExprScope* scope) {
    TextLine sub = line;  // the word ends at `end`: expressions must not run past it
    sub.text = line.text.substr(0, end);
    std::string_view t = sub.text;
    std::vector<WordModule> word;
    std::size_t pos = skipSpaces(t, begin);
    while (pos < t.size()) {
        char c = t[pos];
        if (c == '(') {
            sub.fail(pos, "unexpected '('; expected a module name before a parameter list");
        }
        if (c == ')' || c == ',') {
            sub.fail(pos, "unexpected '" + std::string(1, c) + "'; expected a module");
        }
        if (c == '<' || c == '>' || c == ':') {
            sub.fail(pos, quoted(std::string_view(&c, 1)) +
                              " separates the parts of a production; "
                              "expected a module (productions read 'left < pred > right : "
                              "condition -> successor : weight')");
        }
        if (t.compare(pos, 3, "\xE2\x86\x92") == 0) {
            sub.fail(pos,
                     "'\xE2\x86\x92' is the production arrow; expected a module (one "
                     "production per line)");
        }
        auto u = static_cast<unsigned char>(c);
        if (!isModuleStart(c) || (u >= 0x80 && charLength(t, pos) == 1)) {
            sub.fail(pos, "unexpected " + describeChar(t, pos) + "; expected a module");
        }
        std::size_t length = moduleNameLength(t, pos);
        WordModule m;
        m.symbol = internSymbol(t.substr(pos, length));
        m.offset = pos;
        pos = skipSpaces(t, pos + length);
        if (pos < t.size() && t[pos] == '(') {
            if (m.symbol == rules_->openSymbol || m.symbol == rules_->closeSymbol) {
                sub.fail(pos, "brackets take no parameters; expected a module after '" +
                                  system_.symbols.names[m.symbol] + "'");
            }
            parseParams(sub, pos, mode, scope, m);
        }
        word.push_back(std::move(m));
    }
    return word;
}

void LSystemParser::parseParams(const TextLine& line, std::size_t& pos, WordMode mode,
                                const ExprScope* scope, WordModule& module) {
    std::string_view t = line.text;
    const std::string& name = system_.symbols.names[module.symbol];
    if (mode == WordMode::Plain) {
        line.fail(pos,
                  "unexpected '(' after '" + name + "'; expected module names without parameters");
    }
    std::size_t open = pos;
    pos = skipSpaces(t, pos + 1);
    if (pos < t.size() && t[pos] == ')') {
        line.fail(open, "empty parameter list after '" + name +
                            "'; expected parameters, or no parentheses");
    }
    std::size_t count = 0;
    for (;;) {
        if (++count > kMaxParams) {
            line.fail(pos, "too many parameters for '" + name + "'; expected at most 65535");
        }
        if (mode == WordMode::Pattern) {
            if (pos >= t.size() || !isIdentStart(t[pos])) {
                line.fail(pos, "expected a formal parameter name in '" + name + "(…)', got " +
                                   describeChar(t, pos));
            }
            std::size_t start = pos;
            while (pos < t.size() && isIdentChar(t[pos])) ++pos;
            module.formals.emplace_back(std::string(t.substr(start, pos - start)), start);
            pos = skipSpaces(t, pos);
        } else {
            std::vector<Instr>& code = rules_->code;
            CompiledExpr e = compileExpression(line, pos, *scope, code);
            if (e.constant) code.resize(e.begin);  // the value is kept; the code is not needed
            RAMUS_ASSERT(mode != WordMode::Axiom || e.constant);
            module.params.push_back(e);
        }
        if (pos < t.size() && t[pos] == ',') {
            pos = skipSpaces(t, pos + 1);
            continue;
        }
        if (pos < t.size() && t[pos] == ')') {
            pos = skipSpaces(t, pos + 1);
            return;
        }
        line.fail(pos, "expected ',' or ')' in the parameters of '" + name + "', got " +
                           describeChar(t, pos));
    }
}

void LSystemParser::checkBrackets(const TextLine& line, const std::vector<WordModule>& word,
                                  const char* what) const {
    std::vector<std::size_t> open;
    for (const auto& m : word) {
        if (m.symbol == rules_->openSymbol) {
            open.push_back(m.offset);
        } else if (m.symbol == rules_->closeSymbol) {
            if (open.empty()) {
                line.fail(m.offset, std::string("unbalanced ']' in the ") + what +
                                        "; expected a '[' before it");
            }
            open.pop_back();
        }
    }
    if (!open.empty()) {
        line.fail(open.back(),
                  std::string("unclosed '[' in the ") + what + "; expected a matching ']'");
    }
}

}  // namespace ramus::detail
