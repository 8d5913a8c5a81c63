// Based on: RFC 8259 (The JavaScript Object Notation (JSON) Data Interchange Format) §2–§8:
// grammar, string escapes, number syntax, UTF-8; RFC 3629 §4 (valid UTF-8 byte sequences).
#include "io/json_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "core/float_text.hpp"
#include "ramus/error.hpp"

namespace ramus::io {

namespace {

// Length of the valid UTF-8 sequence starting at s[i] with lead byte ≥ 0x80, or 0 if invalid
// (RFC 3629 §4: no overlong forms, no surrogates, nothing above U+10FFFF).
std::size_t utf8Length(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) -> unsigned {
        return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u;
    };
    const auto cont = [](unsigned b, unsigned lo = 0x80, unsigned hi = 0xBF) {
        return b >= lo && b <= hi;
    };
    const unsigned lead = byte(0);
    if (lead >= 0xC2 && lead <= 0xDF) return cont(byte(1)) ? 2 : 0;
    if (lead >= 0xE0 && lead <= 0xEF) {
        const unsigned lo = lead == 0xE0 ? 0xA0 : 0x80, hi = lead == 0xED ? 0x9F : 0xBF;
        return cont(byte(1), lo, hi) && cont(byte(2)) ? 3 : 0;
    }
    if (lead >= 0xF0 && lead <= 0xF4) {
        const unsigned lo = lead == 0xF0 ? 0x90 : 0x80, hi = lead == 0xF4 ? 0x8F : 0xBF;
        return cont(byte(1), lo, hi) && cont(byte(2)) && cont(byte(3)) ? 4 : 0;
    }
    return 0;
}

// Characters a JSON string may hold unescaped and that need no UTF-8 check.
bool plainAscii(unsigned char c) { return c >= 0x20 && c < 0x80 && c != '"' && c != '\\'; }

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool isJsonSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

int hexValue(char c) {
    if (isDigit(c)) return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

struct ScanError {
    std::size_t pos;
    const char* expected;
};

// Validates one JSON value (recursive descent, depth-limited); remembers whether any
// whitespace outside strings was skipped. Reads the text's terminating NUL instead of checking
// bounds: no JSON token continues over a NUL, so scanning stops there (and reports it as an
// error when it is not the end).
class JsonScanner {
public:
    explicit JsonScanner(const std::string& text) : s_(text.c_str()), size_(text.size()) {}

    bool scanDocument() {
        skipSpace();
        scanValue(0);
        skipSpace();
        if (i_ != size_) fail("the end of the text");
        return hadSpace_;
    }

private:
    static constexpr int kMaxDepth = 256;

    [[noreturn]] void fail(const char* expected) const { throw ScanError{i_, expected}; }
    char peek() const { return s_[i_]; }
    void expect(char c, const char* what) {
        if (peek() != c) fail(what);
        ++i_;
    }
    void skipSpace() {
        const std::size_t start = i_;
        while (isJsonSpace(s_[i_])) ++i_;
        hadSpace_ = hadSpace_ || i_ != start;
    }
    void scanLiteral(std::string_view word) {
        if (std::string_view(s_ + i_, std::min(word.size(), size_ - i_)) != word) {
            fail("a JSON value");
        }
        i_ += word.size();
    }

    void scanValue(int depth);
    void scanContainer(int depth, char close, bool object);
    void scanString();
    unsigned scanEscapedUnit();
    void scanNumber();
    void scanDigits() {
        if (!isDigit(peek())) fail("a digit");
        while (isDigit(peek())) ++i_;
    }

    const char* s_;  // NUL-terminated
    std::size_t size_;
    std::size_t i_ = 0;
    bool hadSpace_ = false;
};

void JsonScanner::scanValue(int depth) {
    switch (peek()) {
        case '{':
            return scanContainer(depth, '}', true);
        case '[':
            return scanContainer(depth, ']', false);
        case '"':
            return scanString();
        case 't':
            return scanLiteral("true");
        case 'f':
            return scanLiteral("false");
        case 'n':
            return scanLiteral("null");
        default:
            if (peek() == '-' || isDigit(peek())) return scanNumber();
            fail("a JSON value");
    }
}

void JsonScanner::scanContainer(int depth, char close, bool object) {
    if (depth >= kMaxDepth) fail("at most 256 nested arrays and objects");
    ++i_;
    skipSpace();
    if (peek() == close) {
        ++i_;
        return;
    }
    for (;;) {
        if (object) {
            if (peek() != '"') fail("'\"' (an object key)");
            scanString();
            skipSpace();
            expect(':', "':'");
            skipSpace();
        }
        scanValue(depth + 1);
        skipSpace();
        if (peek() == close) {
            ++i_;
            return;
        }
        expect(',', object ? "',' or '}'" : "',' or ']'");
        skipSpace();
    }
}

// \uXXXX after the backslash and 'u' were consumed: the UTF-16 code unit.
unsigned JsonScanner::scanEscapedUnit() {
    unsigned unit = 0;
    for (int k = 0; k < 4; ++k) {
        const int h = hexValue(peek());
        if (h < 0) fail("a hexadecimal digit");
        unit = unit * 16 + static_cast<unsigned>(h);
        ++i_;
    }
    return unit;
}

void JsonScanner::scanString() {
    ++i_;  // opening quote
    for (;;) {
        while (plainAscii(static_cast<unsigned char>(s_[i_]))) ++i_;
        if (i_ >= size_) fail("'\"' (end of the string)");
        const auto c = static_cast<unsigned char>(s_[i_]);
        if (c == '"') {
            ++i_;
            return;
        }
        if (c < 0x20) fail("an escaped control character");
        if (c >= 0x80) {
            const std::size_t n = utf8Length({s_, size_}, i_);
            if (n == 0) fail("valid UTF-8");
            i_ += n;
            continue;
        }
        ++i_;  // backslash
        const char e = peek();
        ++i_;
        if (e == 'u') {
            const unsigned unit = scanEscapedUnit();
            if (unit >= 0xDC00 && unit <= 0xDFFF) fail("no lone low surrogate");
            if (unit >= 0xD800 && unit <= 0xDBFF) {
                if (peek() != '\\' || s_[i_ + 1] != 'u') {
                    fail("a low surrogate \\uDC00…\\uDFFF");
                }
                i_ += 2;
                const unsigned low = scanEscapedUnit();
                if (low < 0xDC00 || low > 0xDFFF) fail("a low surrogate \\uDC00…\\uDFFF");
            }
        } else if (e != '"' && e != '\\' && e != '/' && e != 'b' && e != 'f' && e != 'n' &&
                   e != 'r' && e != 't') {
            --i_;
            fail("an escape (\\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX)");
        }
    }
}

void JsonScanner::scanNumber() {
    if (peek() == '-') ++i_;
    if (peek() == '0') {
        ++i_;
    } else {
        scanDigits();
    }
    if (peek() == '.') {
        ++i_;
        scanDigits();
    }
    if (peek() == 'e' || peek() == 'E') {
        ++i_;
        if (peek() == '+' || peek() == '-') ++i_;
        scanDigits();
    }
}

// Copies validated JSON without whitespace outside strings.
void appendWithoutSpace(std::string& out, std::string_view text) {
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            out += c;
            if (c == '\\') {
                out += text[++i];
            } else if (c == '"') {
                inString = false;
            }
        } else if (!isJsonSpace(c)) {
            out += c;
            inString = c == '"';
        }
    }
}

std::string describe(std::string_view text, std::size_t pos) {
    if (pos >= text.size()) return "the end of the text";
    const auto c = static_cast<unsigned char>(text[pos]);
    if (c >= 0x20 && c < 0x7F) return std::string("'") + static_cast<char>(c) + "'";
    constexpr char kHex[] = "0123456789ABCDEF";
    return std::string("byte 0x") + kHex[c >> 4] + kHex[c & 15];
}

}  // namespace

bool appendJsonString(std::string& out, std::string_view text) {
    // Names (the common case) need no escaping: one append, quotes included.
    if (text.size() <= 62 && std::all_of(text.begin(), text.end(), [](char c) {
            return plainAscii(static_cast<unsigned char>(c));
        })) {
        char buffer[64];
        buffer[0] = '"';
        std::memcpy(buffer + 1, text.data(), text.size());
        buffer[text.size() + 1] = '"';
        out.append(buffer, text.size() + 2);
        return true;
    }
    const std::size_t start = out.size();
    out += '"';
    std::size_t i = 0;
    while (i < text.size()) {
        std::size_t run = i;
        while (run < text.size() && plainAscii(static_cast<unsigned char>(text[run]))) ++run;
        out.append(text.data() + i, run - i);
        if (run == text.size()) break;
        const auto c = static_cast<unsigned char>(text[run]);
        if (c >= 0x80) {
            const std::size_t n = utf8Length(text, run);
            if (n == 0) {
                out.resize(start);
                return false;
            }
            out.append(text.data() + run, n);
            i = run + n;
            continue;
        }
        out += '\\';
        switch (c) {
            case '"':
                out += '"';
                break;
            case '\\':
                out += '\\';
                break;
            case '\b':
                out += 'b';
                break;
            case '\f':
                out += 'f';
                break;
            case '\n':
                out += 'n';
                break;
            case '\r':
                out += 'r';
                break;
            case '\t':
                out += 't';
                break;
            default: {
                constexpr char kHex[] = "0123456789abcdef";
                out += "u00";
                out += kHex[c >> 4];
                out += kHex[c & 15];
            }
        }
        i = run + 1;
    }
    out += '"';
    return true;
}

void appendJsonNumber(std::string& out, float value) {
    char buffer[32];
    out.append(buffer, detail::writeShortest(buffer, buffer + sizeof buffer, value));
}

void appendJsonNumber(std::string& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

std::string appendCompactJson(std::string& out, const std::string& text) {
    try {
        if (JsonScanner(text).scanDocument()) {
            appendWithoutSpace(out, text);
        } else {
            out.append(text);
        }
        return {};
    } catch (const ScanError& e) {
        return "byte " + std::to_string(e.pos) + ": expected " + e.expected + ", got " +
               describe(text, e.pos);
    }
}

// Each call below appends its text, comma included, with one append: the document of a scene
// of many small meshes (a skeleton's bones) is thousands of short keys and numbers, where
// several appends per item cost more than formatting them.

void JsonWriter::key(std::string_view name) {
    char buffer[64];
    if (name.size() + 4 > sizeof buffer) {
        if (needComma_) out_ += ',';
        out_ += '"';
        out_.append(name);
        out_ += "\":";
    } else {
        char* p = buffer;
        if (needComma_) *p++ = ',';
        *p++ = '"';
        std::memcpy(p, name.data(), name.size());
        p += name.size();
        *p++ = '"';
        *p++ = ':';
        out_.append(buffer, static_cast<std::size_t>(p - buffer));
    }
    needComma_ = false;
}

void JsonWriter::value(std::string_view text) {
    separate();
    if (!appendJsonString(out_, text)) {
        throw Error("the text '" + std::string(text) + "' is not valid UTF-8");
    }
}

void JsonWriter::value(bool flag) {
    separate();
    out_ += flag ? "true" : "false";
}

char* JsonWriter::separator(char* p) {
    if (needComma_) *p++ = ',';
    needComma_ = true;
    return p;
}

// Floats through detail::writeShortest (−0 written as 0, whole numbers fast) or the cache.
template <typename T>
char* JsonWriter::writeNumber(char* first, char* last, T value) {
    if constexpr (std::is_same_v<T, float>) {
        return floats_ != nullptr ? floats_->write(first, last, value)
                                  : detail::writeShortest(first, last, value);
    } else {
        return std::to_chars(first, last, value).ptr;
    }
}

template <typename T>
void JsonWriter::number(T number) {
    char buffer[kNumberChars];
    char* p = separator(buffer);
    p = writeNumber(p, buffer + sizeof buffer, number);
    out_.append(buffer, static_cast<std::size_t>(p - buffer));
}

void JsonWriter::value(std::int64_t number) { this->number(number); }
void JsonWriter::value(std::uint64_t number) { this->number(number); }
void JsonWriter::value(float number) { this->number(number); }
void JsonWriter::value(double number) { this->number(number); }

template <typename T>
void JsonWriter::numberArray(const T* values, std::size_t count) {
    constexpr std::size_t kBatch = 16;
    char buffer[kBatch * kNumberChars + 2];
    char* p = separator(buffer);
    *p++ = '[';
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0) *p++ = ',';
        p = writeNumber(p, buffer + sizeof buffer, values[i]);
        if (i % kBatch == kBatch - 1) {  // flush: room for the next kBatch numbers
            out_.append(buffer, static_cast<std::size_t>(p - buffer));
            p = buffer;
        }
    }
    *p++ = ']';
    out_.append(buffer, static_cast<std::size_t>(p - buffer));
}

template void JsonWriter::numberArray(const int*, std::size_t);
template void JsonWriter::numberArray(const float*, std::size_t);
template void JsonWriter::numberArray(const double*, std::size_t);

std::string JsonWriter::jsonValue(const std::string& json) {
    separate();
    return appendCompactJson(out_, json);
}

void JsonWriter::rawValue(std::string_view json) {
    separate();
    out_.append(json);
}

}  // namespace ramus::io
