// Based on: the .lsys format of DESIGN.md ("L-system files") documented in docs/lsystem.md,
// which follows the cpfg L-system file format (Prusinkiewicz, Hanan, Mech: "An L-system-based
// plant modeling language", AGTIVE 1999) and the notation of ABOP ch. 1–2.
#include "lsystem/parser.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>

#include "ramus/file_util.hpp"

namespace ramus::detail {
namespace {

/// The production arrow `->`, `-->` or `→` at parenthesis depth 0: {offset, length}, or npos.
std::pair<std::size_t, std::size_t> findArrow(std::string_view text) {
    int depth = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '(') {
            ++depth;
        } else if (c == ')') {
            if (depth > 0) --depth;
        } else if (depth == 0) {
            if (c == '-' && i + 1 < text.size() && text[i + 1] == '>') {
                if (i > 0 && text[i - 1] == '-') return {i - 1, 3};
                return {i, 2};
            }
            if (text.compare(i, 3, "\xE2\x86\x92") == 0) return {i, 3};
        }
    }
    return {kNpos, 0};
}

/// True when `word` stands at `pos`, followed by a space or the end of the text.
bool wordAt(std::string_view text, std::size_t pos, std::string_view word) {
    return text.compare(pos, word.size(), word) == 0 &&
           (pos + word.size() == text.size() || isSpaceChar(text[pos + word.size()]));
}

constexpr const char* kHeaderKeys =
    "axiom, derivations, angle, step, seed, ignore, consider, tropism, tropism_mode, width, "
    "module, #define";

bool isKey(std::string_view key, std::string_view name) { return key == name; }

/// The header key before `colon`, trimmed and lower-cased (keys are case-insensitive, so
/// L-Py's `Axiom:` and cpfg's `Derivation length:` work).
std::string headerKey(std::string_view text, std::size_t colon) {
    std::string key(trimSpaces(text.substr(0, colon)));
    for (char& c : key) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    }
    return key;
}

bool isDerivationsKey(std::string_view key) {
    return key == "derivations" || key == "n" || key == "iterations" || key == "derivation length";
}

bool looksLikeKey(std::string_view key) {
    if (key.empty()) return false;
    return std::all_of(key.begin(), key.end(), [](char c) { return isIdentChar(c) || c == ' '; });
}

}  // namespace

LSystemParser::LSystemParser(std::string_view text, const std::string& fileName,
                             const ParseOptions& options)
    : fileName_(fileName), options_(options), rules_(std::make_shared<CompiledRules>()) {
    system_.fileName = fileName;
    for (const auto& [name, value] : options.constantOverrides) {
        bool valid = !name.empty() && isIdentStart(name[0]) &&
                     std::all_of(name.begin(), name.end(), isIdentChar);
        if (!valid) {
            throw Error(SourceLoc{fileName, 0, 0},
                        "--set '" + name +
                            "': not a constant name; expected letters, digits "
                            "and '_', starting with a letter");
        }
        if (!std::isfinite(value)) {
            throw Error(SourceLoc{fileName, 0, 0},
                        "--set " + name + ": value is not finite; expected a number");
        }
        Constant* existing = nullptr;
        for (auto& c : constants_.items) {
            if (c.name == name) existing = &c;
        }
        if (existing) {
            existing->value = value;
        } else {
            constants_.items.push_back(Constant{name, value, false, true, false, 0});
        }
    }
    splitLines(text);
}

void LSystemParser::splitLines(std::string_view text) {
    int number = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t nl = text.find('\n', start);
        std::string_view raw = text.substr(start, nl == kNpos ? kNpos : nl - start);
        ++number;
        // Strip the comment: `#` starts one anywhere, except the `#define` keyword itself.
        std::size_t first = skipSpaces(raw, 0);
        std::size_t searchFrom = 0;
        if (wordAt(raw, first, "#define")) {
            searchFrom = first + 7;
        } else {
            for (std::string_view d :
                 {"#include", "#if", "#ifdef", "#ifndef", "#else", "#endif", "#undef"}) {
                if (wordAt(raw, first, d)) {
                    TextLine{raw, number, &fileName_}.fail(
                        first, "preprocessor directive '" + std::string(d) +
                                   "' is not supported; expected '#define NAME value' or a "
                                   "comment ('# text')");
                }
            }
        }
        std::size_t hash = raw.find('#', searchFrom);
        lines_.push_back(TextLine{raw.substr(0, hash), number, &fileName_});
        if (nl == kNpos) break;
        start = nl + 1;
    }
    isDeclaration_.assign(lines_.size(), 0);
}

LSystem LSystemParser::run() {
    declarationPass();
    mainPass();
    finish();
    return std::move(system_);
}

/// Pass 1: `#define` and `module` lines in file order, then ignore:/consider: lists, so that
/// constants and multi-letter names can be used anywhere in the file.
void LSystemParser::declarationPass() {
    std::vector<std::size_t> lists;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        const TextLine& line = lines_[i];
        std::size_t pos = skipSpaces(line.text, 0);
        if (pos == line.text.size()) {
            isDeclaration_[i] = 1;
        } else if (wordAt(line.text, pos, "#define")) {
            parseDefine(line, pos + 7);
            isDeclaration_[i] = 1;
        } else if (findArrow(line.text).first != kNpos) {
            continue;  // a production
        } else if (wordAt(line.text, pos, "module")) {
            parseModuleDeclaration(line, pos + 6);
            isDeclaration_[i] = 1;
        } else {
            std::size_t colon = line.text.find(':');
            if (colon == kNpos) continue;
            std::string key = headerKey(line.text, colon);
            if (key == "ignore" || key == "consider") {
                lists.push_back(i);
                isDeclaration_[i] = 1;
            }
        }
    }
    for (std::size_t i : lists) {
        const TextLine& line = lines_[i];
        std::size_t colon = line.text.find(':');
        parseSymbolList(line, colon + 1, headerKey(line.text, colon) == "consider");
    }
}

void LSystemParser::mainPass() {
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        if (isDeclaration_[i]) continue;
        const TextLine& line = lines_[i];
        auto [arrow, arrowLength] = findArrow(line.text);
        if (arrow != kNpos) {
            parseProduction(line, arrow, arrowLength);
            continue;
        }
        std::size_t colon = line.text.find(':');
        // cpfg frames a system with `Lsystem: <name>` … `endlsystem`; both carry nothing here.
        if (trimSpaces(line.text) == "endlsystem") continue;
        if (colon != kNpos && headerKey(line.text, colon) == "lsystem") continue;
        if (colon == kNpos) {
            std::size_t end = trimSpaces(line.text).size() + skipSpaces(line.text, 0);
            line.fail(end,
                      "missing '->'; expected a production 'predecessor -> successor' or "
                      "a header 'key: value'");
        }
        parseHeader(line, colon);
    }
}

void LSystemParser::parseDefine(const TextLine& line, std::size_t pos) {
    std::string_view t = line.text;
    pos = skipSpaces(t, pos);
    if (pos >= t.size() || !isIdentStart(t[pos])) {
        line.fail(pos, "expected a constant name after #define, got " + describeChar(t, pos));
    }
    std::size_t nameStart = pos;
    while (pos < t.size() && isIdentChar(t[pos])) ++pos;
    std::string name(t.substr(nameStart, pos - nameStart));
    if (pos < t.size() && !isSpaceChar(t[pos])) {
        line.fail(pos, "unexpected " + describeChar(t, pos) +
                           " in the name of a #define; "
                           "expected letters, digits or '_'");
    }
    if (isBuiltinFunction(name)) {
        line.fail(nameStart, "'" + name +
                                 "' is a built-in function; expected another constant "
                                 "name");
    }
    std::size_t valuePos = skipSpaces(t, pos);
    if (valuePos >= t.size()) {
        line.fail(valuePos,
                  "#define " + name + " has no value; expected '#define " + name + " value'");
    }
    Constant* existing = nullptr;
    for (auto& c : constants_.items) {
        if (c.name == name) existing = &c;
    }
    if (existing && existing->defined) {
        line.fail(nameStart, "constant '" + name + "' is already defined on line " +
                                 std::to_string(existing->line) +
                                 "; expected each #define name once");
    }
    double value = constantValue(line, valuePos, t.size(), "in #define");
    if (existing) {  // a --set override replaces the file's value
        existing->defined = true;
        existing->line = line.number;
    } else {
        constants_.items.push_back(Constant{name, value, true, false, false, line.number});
    }
}

void LSystemParser::parseModuleDeclaration(const TextLine& line, std::size_t pos) {
    std::string_view t = line.text;
    pos = skipSpaces(t, pos);
    if (pos >= t.size()) line.fail(pos, "expected module names after 'module'");
    while (pos < t.size()) {
        std::size_t start = pos;
        while (pos < t.size() && !isSpaceChar(t[pos]) && t[pos] != ',') {
            char c = t[pos];
            auto u = static_cast<unsigned char>(c);
            if (c == '[' || c == ']' || (u < 0x80 && !isModuleStart(c)) ||
                t.compare(pos, 3, "\xE2\x86\x92") == 0) {
                line.fail(pos, "module name contains " + describeChar(t, pos) +
                                   "; expected letters, digits or other characters that are "
                                   "not syntax ( ) , # < > : [ ]");
            }
            ++pos;
        }
        std::string_view name = t.substr(start, pos - start);
        if (charLength(t, start) < name.size()) {
            if (std::find(multiNames_.begin(), multiNames_.end(), name) == multiNames_.end()) {
                multiNames_.emplace_back(name);
            }
        }
        if (name.empty()) line.fail(pos, "expected a module name, got ','");
        internSymbol(name);
        pos = skipSpaces(t, pos);
        if (pos < t.size() && t[pos] == ',') pos = skipSpaces(t, pos + 1);
    }
}

void LSystemParser::parseSymbolList(const TextLine& line, std::size_t pos, bool consider) {
    if (listLine_ != 0 && considerMode_ != consider) {
        line.fail(skipSpaces(line.text, 0),
                  "'ignore:' and 'consider:' cannot both be used (the other is on line " +
                      std::to_string(listLine_) + "); expected only one of them");
    }
    if (listLine_ == 0) listLine_ = line.number;
    considerMode_ = consider;
    auto word = parseWord(line, pos, line.text.size(), WordMode::Plain, nullptr);
    for (const auto& m : word) {
        if (m.symbol == rules_->openSymbol || m.symbol == rules_->closeSymbol) {
            line.fail(m.offset,
                      "brackets cannot be ignored or considered; they always "
                      "delimit branches; expected other modules");
        }
        if (listed_.size() <= m.symbol) listed_.resize(m.symbol + 1, 0);
        listed_[m.symbol] = 1;
    }
}

void LSystemParser::parseHeader(const TextLine& line, std::size_t colon) {
    std::string_view t = line.text;
    std::size_t keyPos = skipSpaces(t, 0);
    std::string key = headerKey(t, colon);
    std::size_t valuePos = skipSpaces(t, colon + 1);
    bool known = isDerivationsKey(key) || isKey(key, "axiom") || isKey(key, "angle") ||
                 isKey(key, "step") || isKey(key, "seed") || isKey(key, "tropism") ||
                 isKey(key, "tropism_mode") || isKey(key, "width");
    if (!known) {
        if (looksLikeKey(key)) {
            line.fail(keyPos, "unknown header '" + key + "'; expected one of " + kHeaderKeys +
                                  ", or a production 'predecessor -> successor'");
        }
        line.fail(trimSpaces(t).size() + keyPos,
                  "missing '->'; expected a production 'predecessor -> successor'");
    }
    std::string canonical = isDerivationsKey(key) ? "derivations" : key;
    auto [it, inserted] = headerLines_.emplace(canonical, line.number);
    if (!inserted) {
        line.fail(keyPos, "'" + canonical + ":' is given twice (first on line " +
                              std::to_string(it->second) + "); expected it once");
    }
    if (valuePos >= t.size()) {
        line.fail(valuePos, "missing value after '" + key + ":'; expected " +
                                (key == "axiom" ? "a word of modules" : "a value"));
    }
    if (canonical == "axiom") return parseAxiom(line, valuePos);
    if (canonical == "tropism") return parseTropism(line, valuePos);
    if (canonical == "tropism_mode") {
        std::string_view mode = trimSpaces(t.substr(valuePos));
        if (mode != "rotate" && mode != "blend") {
            line.fail(valuePos,
                      "unknown tropism mode '" + std::string(mode) + "'; expected rotate or blend");
        }
        system_.settings.tropismMode = mode == "rotate" ? TropismMode::Rotate : TropismMode::Blend;
        return;
    }
    parseNumericHeader(line, canonical, valuePos);
}

void LSystemParser::parseNumericHeader(const TextLine& line, const std::string& key,
                                       std::size_t valuePos) {
    LSystemSettings& s = system_.settings;
    std::string_view t = line.text;
    if (key == "seed") {
        // Whole seeds are read exactly (all 64 bits); expressions go through doubles below.
        std::string_view digits = trimSpaces(t.substr(valuePos));
        if (std::all_of(digits.begin(), digits.end(), isDigitChar)) {
            auto res = std::from_chars(digits.data(), digits.data() + digits.size(), s.seed);
            if (res.ec != std::errc()) {
                line.fail(valuePos, "seed is out of range; expected an integer below 2^64");
            }
            return;
        }
    }
    double v = constantValue(line, valuePos, t.size(), "in a header");
    if (key == "derivations" || key == "seed") {
        double limit = key == "seed" ? 9007199254740992.0 : double(INT_MAX);
        if (v < 0 || v != std::floor(v) || v > limit) {
            line.fail(valuePos,
                      key + " must be a whole number from 0 to " +
                          (key == "seed" ? std::string("2^53") : std::to_string(INT_MAX)) +
                          "; got " + std::to_string(v));
        }
        if (key == "seed") {
            s.seed = static_cast<std::uint64_t>(v);
        } else {
            s.derivations = static_cast<int>(v);
        }
    } else if (key == "angle") {
        s.angleDegrees = v;
    } else if (key == "step") {
        s.step = v;
    } else if (key == "width") {
        if (v < 0) line.fail(valuePos, "width must be >= 0; got " + std::to_string(v));
        s.width = v;
    }
}

void LSystemParser::parseAxiom(const TextLine& line, std::size_t pos) {
    haveAxiom_ = true;
    ExprScope scope{nullptr, &constants_, false, "in the axiom"};
    auto word = parseWord(line, pos, line.text.size(), WordMode::Axiom, &scope);
    checkBrackets(line, word, "axiom");
    ModuleString& axiom = system_.axiom;
    for (const auto& m : word) {
        Module mod;
        mod.symbol = m.symbol;
        mod.paramCount = static_cast<std::uint16_t>(m.params.size());
        mod.paramOffset = m.params.empty() ? 0 : static_cast<std::uint32_t>(axiom.params.size());
        for (const auto& p : m.params) axiom.params.push_back(p.value);
        axiom.modules.push_back(mod);
    }
}

void LSystemParser::parseTropism(const TextLine& line, std::size_t pos) {
    std::string_view t = line.text;
    double values[4] = {0, 0, 0, 0};
    int count = 0;
    while (pos < t.size()) {
        // One value: up to the next space or comma outside parentheses.
        std::size_t end = pos;
        int depth = 0;
        while (end < t.size() && (depth > 0 || (!isSpaceChar(t[end]) && t[end] != ','))) {
            if (t[end] == '(') ++depth;
            if (t[end] == ')') --depth;
            ++end;
        }
        if (count == 4) {
            line.fail(pos, "tropism has more than 4 values; expected 'tropism: x y z e'");
        }
        values[count++] = constantValue(line, pos, end, "in a header");
        pos = skipSpaces(t, end);
        if (pos < t.size() && t[pos] == ',') pos = skipSpaces(t, pos + 1);
    }
    if (count != 4) {
        line.fail(pos,
                  "tropism needs 4 values; expected 'tropism: x y z e' (direction T and "
                  "susceptibility e), got " +
                      std::to_string(count));
    }
    system_.settings.tropism = Vec3(values[0], values[1], values[2]);
    system_.settings.susceptibility = values[3];
}

double LSystemParser::constantValue(const TextLine& line, std::size_t begin, std::size_t end,
                                    const char* what) {
    TextLine sub = line;
    sub.text = line.text.substr(0, end);
    std::size_t pos = begin;
    std::vector<Instr> scratch;
    ExprScope scope{nullptr, &constants_, false, what};
    CompiledExpr e = compileExpression(sub, pos, scope, scratch);
    pos = skipSpaces(sub.text, pos);
    if (pos < end) {
        line.fail(pos, "unexpected " + describeChar(sub.text, pos) +
                           " after the value; expected an operator or the end of the value");
    }
    RAMUS_ASSERT(e.constant);
    return e.value;
}

void LSystemParser::finish() {
    if (!haveAxiom_) {
        int last = lines_.empty() ? 1 : lines_.back().number;
        throw Error(SourceLoc{fileName_, last, 1},
                    "no axiom; expected a line 'axiom: <modules>' (for example 'axiom: F')");
    }
    checkOverrides();
    buildSymbolRules();
    system_.rules = rules_;
}

void LSystemParser::checkOverrides() {
    for (const auto& c : constants_.items) {
        if (!c.fromOverride || c.defined || c.used) continue;
        std::string names;
        for (const auto& d : constants_.items) {
            if (d.defined) names += (names.empty() ? "" : ", ") + d.name;
        }
        throw Error(SourceLoc{fileName_, 0, 0},
                    "--set " + c.name + ": the file does not use a constant '" + c.name +
                        "'; expected " +
                        (names.empty() ? std::string("no --set (the file defines no constants)")
                                       : "one of " + names));
    }
}

void LSystemParser::buildSymbolRules() {
    CompiledRules& r = *rules_;
    std::size_t symbolCount = system_.symbols.names.size();
    r.rules = fileRules_;
    std::stable_sort(r.rules.begin(), r.rules.end(),
                     [](const Rule& a, const Rule& b) { return a.symbol < b.symbol; });
    r.bySymbol.assign(symbolCount, SymbolRules{});
    for (std::size_t i = 0; i < r.rules.size();) {
        std::size_t j = i;
        bool sameArity = true;
        while (j < r.rules.size() && r.rules[j].symbol == r.rules[i].symbol) {
            sameArity = sameArity && r.rules[j].arity == r.rules[i].arity;
            ++j;
        }
        SymbolRules& entry = r.bySymbol[r.rules[i].symbol];
        entry.ruleBegin = static_cast<std::uint32_t>(i);
        entry.ruleEnd = static_cast<std::uint32_t>(j);
        entry.kind =
            r.rules[i].isUnconditional() && sameArity ? SymbolKind::Always : SymbolKind::General;
        i = j;
    }
    auto cut = symbolIds_.find("%");
    if (cut != symbolIds_.end()) r.bySymbol[cut->second].kind = SymbolKind::Cut;
    r.ignored.assign(symbolCount, 0);
    for (std::size_t s = 0; s < symbolCount; ++s) {
        r.ignored[s] = isIgnored(static_cast<std::uint32_t>(s)) ? 1 : 0;
    }
}

}  // namespace ramus::detail

namespace ramus {

LSystem parseLSystem(std::string_view text, const std::string& fileName,
                     const ParseOptions& options) {
    detail::LSystemParser parser(text, fileName, options);
    return parser.run();
}

LSystem loadLSystem(const std::string& path, const ParseOptions& options) {
    std::string text = readFile(path);
    return parseLSystem(text, path, options);
}

}  // namespace ramus
