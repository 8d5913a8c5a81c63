// A streaming JSON writer (RFC 8259) that appends compact JSON to one std::string, and a
// validating scanner that copies a JSON text compactly (for extras strings embedded verbatim).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "core/float_text.hpp"

namespace ramus::io {

/// Appends `text` as a JSON string literal: quotes, `"` and `\` escaped, control characters
/// as \b \f \n \r \t or \u00XX, everything else (UTF-8 included) copied. Returns false (out
/// unchanged) when `text` is not valid UTF-8 (overlong forms, surrogates and code points above
/// U+10FFFF are invalid).
bool appendJsonString(std::string& out, std::string_view text);

/// Appends a short decimal text that reads back as the same float (detail::writeShortest),
/// e.g. "0.1", "-2", "1e-8". Precondition: finite.
void appendJsonNumber(std::string& out, float value);
/// The same for doubles. Precondition: finite.
void appendJsonNumber(std::string& out, double value);

/// Checks that `text` is one JSON value (RFC 8259: objects, arrays, strings with valid escapes
/// and UTF-8, numbers, true/false/null, surrounded by optional whitespace, nested at most 256
/// deep) and appends it without the insignificant whitespace; the characters of strings and
/// numbers are copied as they are. Returns an empty string on success, else (out unchanged) a
/// message "byte N: expected X, got Y" (N counted from 0). Duplicate object keys are not
/// detected.
std::string appendCompactJson(std::string& out, const std::string& text);

/// Streams one JSON document into a string, inserting commas: call key() before each member
/// of an object, then exactly one value (a scalar or a begin…end pair). The caller keeps the
/// nesting balanced.
class JsonWriter {
public:
    /// Appends to `out` (not cleared; kept by reference); floats through `floats` when given
    /// (a cache shared by the writers of one document; same text either way).
    explicit JsonWriter(std::string& out, detail::FloatTextCache* floats = nullptr)
        : out_(out), floats_(floats) {}

    void beginObject() { open('{'); }
    void endObject() { close('}'); }
    void beginArray() { open('['); }
    void endArray() { close(']'); }

    /// `"name":`; `name` must not need escaping (a fixed ASCII identifier).
    void key(std::string_view name);
    /// The same for a string literal (its length known at compile time: the common case, kept
    /// cheap because a scene of many small meshes writes thousands of keys).
    template <std::size_t N>
    void key(const char (&name)[N]) {
        char buffer[N + 3];
        char* p = buffer;
        if (needComma_) *p++ = ',';
        *p++ = '"';
        std::memcpy(p, name, N - 1);
        p += N - 1;
        *p++ = '"';
        *p++ = ':';
        out_.append(buffer, static_cast<std::size_t>(p - buffer));
        needComma_ = false;
    }

    /// A string value; throws Error "… is not valid UTF-8" for invalid UTF-8.
    void value(std::string_view text);
    void value(const char* text) { value(std::string_view(text)); }
    void value(bool flag);
    void value(int number) { value(static_cast<std::int64_t>(number)); }
    void value(std::int64_t number);
    void value(std::uint64_t number);
    /// Short round-trip text (appendJsonNumber). Precondition: finite.
    void value(float number);
    void value(double number);
    /// An array of `count` numbers (int, float or double; shortest round-trip text).
    template <typename T>
    void numbers(const T* values, std::size_t count) {
        numberArray(values, count);
    }
    /// A value that is already compact, valid JSON, copied as is.
    void rawValue(std::string_view json);
    /// Members of the open object that are already compact, valid JSON (`"a":1,"b":[2]`),
    /// copied as they are after the comma they need; nothing for an empty text.
    void rawMembers(std::string_view members) {
        if (!members.empty()) rawValue(members);
    }
    /// Validates `json` and writes it compactly (appendCompactJson); returns its error message
    /// (empty on success; on failure the document is left incomplete).
    std::string jsonValue(const std::string& json);

private:
    // The longest number text plus a comma: a double's shortest form is at most 24 characters
    // ("-2.2250738585072014e-308").
    static constexpr std::size_t kNumberChars = 26;
    // Writes the comma a value needs at p (and marks that the next one needs one).
    char* separator(char* p);
    template <typename T>
    void number(T number);
    template <typename T>
    void numberArray(const T* values, std::size_t count);

    void separate() {
        if (needComma_) out_ += ',';
        needComma_ = true;
    }
    void open(char bracket) {
        separate();
        out_ += bracket;
        needComma_ = false;
    }
    void close(char bracket) {
        out_ += bracket;
        needComma_ = true;
    }

    // std::to_chars's text; floats through the cache when there is one.
    template <typename T>
    char* writeNumber(char* first, char* last, T value);

    std::string& out_;
    detail::FloatTextCache* floats_;
    bool needComma_ = false;
};

}  // namespace ramus::io
