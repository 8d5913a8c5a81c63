// JSON text → nlohmann::json with errors located as file:line:col, and short renderings of
// values for messages. Header-only: nlohmann_json is a private dependency of the modules that
// read JSON (colonize, io, skeleton), not of core.
#pragma once

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/error.hpp"

namespace ramus::detail {

/// Line and column (1-based) of a byte offset in `text`.
inline SourceLoc sourceLocAtOffset(std::string_view text, std::size_t offset,
                                   const std::string& fileName) {
    SourceLoc loc{fileName, 1, 1};
    offset = std::min(offset, text.size());
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++loc.line;
            loc.column = 1;
        } else {
            ++loc.column;
        }
    }
    return loc;
}

/// A short rendering of a JSON value for "got …" in messages (at most 40 characters).
inline std::string describeJson(const nlohmann::json& value) {
    std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return text;
}

/// Parses JSON text. A syntax error throws Error "FILE:LINE:COL: invalid JSON: <reason>" with
/// the location computed from nlohmann's byte offset and its reason kept. A number too large
/// for a double (e.g. 1e400, which nlohmann reports without a position) throws Error
/// "FILE:LINE:COL: number '…' is out of range; expected a finite number", located at the
/// number's first occurrence in the text.
inline nlohmann::json parseJsonText(std::string_view text, const std::string& fileName) {
    try {
        return nlohmann::json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::parse_error& e) {
        // nlohmann's message: "[json.exception.parse_error.101] parse error at line L, column C:
        // <reason>"; the location is recomputed from the byte offset, the reason kept.
        std::string what = e.what();
        const std::size_t column = what.find(", column ");
        const std::size_t reason = what.find(": ", column == std::string::npos ? 0 : column);
        if (reason != std::string::npos) what = what.substr(reason + 2);
        throw Error(sourceLocAtOffset(text, e.byte > 0 ? e.byte - 1 : 0, fileName),
                    "invalid JSON: " + what);
    } catch (const nlohmann::json::out_of_range& e) {
        // "[json.exception.out_of_range.406] number overflow parsing '1e400'"
        const std::string what = e.what();
        const std::size_t open = what.find('\'');
        const std::size_t close = what.rfind('\'');
        const std::string number = open != std::string::npos && close > open
                                       ? what.substr(open + 1, close - open - 1)
                                       : std::string();
        const std::size_t at = number.empty() ? std::string_view::npos : text.find(number);
        throw Error(sourceLocAtOffset(text, at == std::string_view::npos ? 0 : at, fileName),
                    "number '" + number + "' is out of range; expected a finite number");
    }
}

namespace json_scan {

inline bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

inline void skipSpace(std::string_view t, std::size_t& i) {
    while (i < t.size() && isSpace(t[i])) ++i;
}

// From the opening quote to just past the closing one.
inline void skipString(std::string_view t, std::size_t& i) {
    for (++i; i < t.size() && t[i] != '"'; ++i) {
        if (t[i] == '\\') ++i;
    }
    ++i;
}

inline void skipValue(std::string_view t, std::size_t& i) {
    skipSpace(t, i);
    if (i >= t.size()) return;
    if (t[i] == '"') return skipString(t, i);
    if (t[i] == '{' || t[i] == '[') {
        int depth = 0;
        do {
            if (t[i] == '"') {
                skipString(t, i);
                continue;
            }
            if (t[i] == '{' || t[i] == '[') ++depth;
            if (t[i] == '}' || t[i] == ']') --depth;
            ++i;
        } while (i < t.size() && depth > 0);
        return;
    }
    while (i < t.size() && t[i] != ',' && t[i] != '}' && t[i] != ']' && !isSpace(t[i])) ++i;
}

// In the object starting at t[i]: moves i to the value of `key`; false if there is none.
inline bool enterMember(std::string_view t, std::size_t& i, std::string_view key) {
    for (++i;;) {
        skipSpace(t, i);
        if (i >= t.size() || t[i] != '"') return false;
        const std::size_t start = i;
        skipString(t, i);
        const std::string_view name = t.substr(start + 1, i - start - 2);
        skipSpace(t, i);
        ++i;  // ':'
        skipSpace(t, i);
        if (name == key) return true;
        skipValue(t, i);
        skipSpace(t, i);
        if (i < t.size() && t[i] == ',') ++i;
    }
}

// In the array starting at t[i]: moves i to element `index`; false if there is none.
inline bool enterElement(std::string_view t, std::size_t& i, std::string_view index) {
    std::size_t n = 0;
    for (char c : index) {
        if (c < '0' || c > '9') return false;
        n = n * 10 + static_cast<std::size_t>(c - '0');
    }
    ++i;
    for (std::size_t k = 0;; ++k) {
        skipSpace(t, i);
        if (i >= t.size() || t[i] == ']') return false;
        if (k == n) return true;
        skipValue(t, i);
        skipSpace(t, i);
        if (i < t.size() && t[i] == ',') ++i;
    }
}

}  // namespace json_scan

/// Where the value at `path` (object keys and array indices as text, e.g. {"models", "rib",
/// "child_joints", "0"}) starts in `text`, which must be valid JSON: its line and column, or
/// those of the deepest value of the path that exists (so a missing key is reported at its
/// object). Keys are compared as written (escapes are not decoded).
inline SourceLoc jsonValueLoc(std::string_view text, const std::vector<std::string>& path,
                              const std::string& fileName) {
    std::size_t i = 0;
    json_scan::skipSpace(text, i);
    std::size_t found = i;
    for (const std::string& key : path) {
        if (i >= text.size()) break;
        std::size_t at = i;
        const bool entered = (text[i] == '{' && json_scan::enterMember(text, at, key)) ||
                             (text[i] == '[' && json_scan::enterElement(text, at, key));
        if (!entered) break;
        i = found = at;
    }
    return sourceLocAtOffset(text, found, fileName);
}

}  // namespace ramus::detail
