// JSON text → nlohmann::json with errors located as file:line:col, and short renderings of
// values for messages. Header-only: nlohmann_json is a private dependency of the modules that
// read JSON (colonize, io, skeleton), not of core.
#pragma once

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

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

}  // namespace ramus::detail
