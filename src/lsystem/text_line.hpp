// Internal helpers of the .lsys parser: one source line with its position (for error locations)
// and the character classes of the language (docs/lsystem.md, "Lexical structure").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "ramus/error.hpp"

namespace ramus::detail {

/// One line of a .lsys text, already stripped of its comment, with its place in the file.
struct TextLine {
    std::string_view text;              ///< the line without line break and comment
    int number = 0;                     ///< 1-based line number
    const std::string* file = nullptr;  ///< file name for messages (never null when used)

    /// Location of byte `offset` of the line. Columns are 1-based and count characters
    /// (UTF-8 code points), so `→` counts as one column.
    SourceLoc locAt(std::size_t offset) const;
    /// Throws Error at byte `offset` with `message`.
    [[noreturn]] void fail(std::size_t offset, const std::string& message) const;
};

/// std::string_view::npos, short.
inline constexpr std::size_t kNpos = std::string_view::npos;

inline bool isSpaceChar(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}
inline bool isDigitChar(char c) { return c >= '0' && c <= '9'; }
inline bool isIdentStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool isIdentChar(char c) { return isIdentStart(c) || isDigitChar(c); }

/// Characters that are syntax, never part of a module name: parameter lists `( , )`, the
/// comment `#`, and the production separators `< > :`. Whitespace separates modules.
inline bool isSyntaxChar(char c) {
    return c == '(' || c == ')' || c == ',' || c == '#' || c == '<' || c == '>' || c == ':';
}

/// True for bytes that may start a module: printable ASCII that is not syntax, or the lead byte
/// of a UTF-8 sequence. Control characters are rejected.
inline bool isModuleStart(char c) {
    auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) return u >= 0xC2 && u <= 0xF4;
    return u > 0x20 && u < 0x7F && !isSyntaxChar(c);
}

/// First byte at or after `pos` that is not a space (or text.size()).
std::size_t skipSpaces(std::string_view text, std::size_t pos);

/// Bytes of the character starting at `pos`: the length of a well-formed UTF-8 sequence, else 1.
std::size_t charLength(std::string_view text, std::size_t pos);

/// The character at `pos` quoted for a message ("'x'"), or "end of line".
std::string describeChar(std::string_view text, std::size_t pos);

/// `text` in single quotes, for messages: 'F'.
std::string quoted(std::string_view text);

/// `text` with leading and trailing spaces removed.
std::string_view trimSpaces(std::string_view text);

}  // namespace ramus::detail
