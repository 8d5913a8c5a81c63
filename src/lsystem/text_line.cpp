#include "lsystem/text_line.hpp"

namespace ramus::detail {

SourceLoc TextLine::locAt(std::size_t offset) const {
    int column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        // Count code points: every byte that is not a UTF-8 continuation byte.
        if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++column;
    }
    if (offset > text.size()) column += static_cast<int>(offset - text.size());
    return SourceLoc{file ? *file : std::string(), number, column};
}

void TextLine::fail(std::size_t offset, const std::string& message) const {
    throw Error(locAt(offset), message);
}

std::size_t skipSpaces(std::string_view text, std::size_t pos) {
    while (pos < text.size() && isSpaceChar(text[pos])) ++pos;
    return pos;
}

std::size_t charLength(std::string_view text, std::size_t pos) {
    auto lead = static_cast<unsigned char>(text[pos]);
    std::size_t n = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 1;
    if (lead >= 0x80 && lead < 0xC2) return 1;
    if (pos + n > text.size()) return 1;
    for (std::size_t i = 1; i < n; ++i) {
        if ((static_cast<unsigned char>(text[pos + i]) & 0xC0) != 0x80) return 1;
    }
    return n;
}

std::string describeChar(std::string_view text, std::size_t pos) {
    if (pos >= text.size()) return "end of line";
    auto u = static_cast<unsigned char>(text[pos]);
    static const char kHex[] = "0123456789abcdef";
    if (u < 0x20 || u == 0x7F) {
        return std::string("control character 0x") + kHex[u >> 4] + kHex[u & 15];
    }
    if (u >= 0x80 && charLength(text, pos) == 1) {
        return std::string("invalid UTF-8 byte 0x") + kHex[u >> 4] + kHex[u & 15];
    }
    return quoted(text.substr(pos, charLength(text, pos)));
}

std::string quoted(std::string_view text) {
    std::string s;
    s.reserve(text.size() + 2);
    s += '\'';
    s.append(text);
    s += '\'';
    return s;
}

std::string_view trimSpaces(std::string_view text) {
    std::size_t b = skipSpaces(text, 0);
    std::size_t e = text.size();
    while (e > b && isSpaceChar(text[e - 1])) --e;
    return text.substr(b, e - b);
}

}  // namespace ramus::detail
