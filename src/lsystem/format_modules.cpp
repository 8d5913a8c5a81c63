// Writes derived words back in .lsys notation (docs/lsystem.md, "Modules"), so that the text
// parses to the same word again.
#include <cstdio>

#include "ramus/lsystem.hpp"

namespace ramus {
namespace {

bool isWordChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// Per symbol: the characters that may follow its name inside a longer symbol name. A
/// parameterless module followed by one of them must be written with a space in between, or
/// longest-match tokenization would read the longer name.
std::vector<std::string> continuations(const SymbolTable& symbols) {
    std::vector<std::string> result(symbols.names.size());
    for (std::size_t s = 0; s < symbols.names.size(); ++s) {
        const std::string& name = symbols.names[s];
        for (const auto& other : symbols.names) {
            if (other.size() > name.size() && other.compare(0, name.size(), name) == 0) {
                result[s] += other[name.size()];
            }
        }
    }
    return result;
}

}  // namespace

std::string formatModules(const SymbolTable& symbols, const ModuleString& word) {
    const std::vector<std::string> next = continuations(symbols);
    std::string text;
    text.reserve(word.modules.size() * 2);
    char number[32];
    for (std::size_t i = 0; i < word.modules.size(); ++i) {
        const Module& m = word.modules[i];
        const std::string& name = symbols.names[m.symbol];
        if (i > 0 && word.modules[i - 1].paramCount == 0) {
            // Separate from the previous parameterless module when the two could merge into a
            // longer name, and for readability between a multi-letter name and a letter.
            const std::string& prev = symbols.names[word.modules[i - 1].symbol];
            bool merge = next[word.modules[i - 1].symbol].find(name[0]) != std::string::npos;
            bool readable = (prev.size() > 1 || name.size() > 1) && isWordChar(prev.back()) &&
                            isWordChar(name[0]);
            if (merge || readable) text += ' ';
        }
        text += name;
        if (m.paramCount) {
            text += '(';
            const double* p = word.paramsOf(m);
            for (std::uint16_t k = 0; k < m.paramCount; ++k) {
                if (k) text += ',';
                std::snprintf(number, sizeof number, "%.10g", p[k]);
                text += number;
            }
            text += ')';
        }
    }
    return text;
}

}  // namespace ramus
