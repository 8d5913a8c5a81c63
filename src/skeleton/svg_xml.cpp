// Based on: W3C XML 1.0 (Fifth Edition) §2–4 — the subset needed to read SVG documents.
#include "skeleton/svg_xml.hpp"

#include <cstdint>

#include "ramus/error.hpp"

namespace ramus::detail {

const std::string* XmlElement::attribute(std::string_view attributeName) const {
    for (const auto& [key, value] : attributes) {
        if (key == attributeName) return &value;
    }
    return nullptr;
}

std::string_view XmlElement::localName() const {
    const std::size_t colon = name.find(':');
    return colon == std::string::npos ? std::string_view(name)
                                      : std::string_view(name).substr(colon + 1);
}

std::string escapeXml(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            // Attribute-value normalization would turn these into spaces.
            case '\n':
                out += "&#10;";
                break;
            case '\r':
                out += "&#13;";
                break;
            case '\t':
                out += "&#9;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

namespace {

constexpr int kMaxDepth = 256;

bool isXmlSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isNameChar(char c) {
    return !isXmlSpace(c) && c != '=' && c != '>' && c != '/' && c != '<' && c != '"' &&
           c != '\'' && c != '\0';
}

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

// Decodes a character reference body ("#65", "#x41"); false when it is not one.
bool decodeCharRef(std::string_view body, std::string& out) {
    if (body.size() < 2 || body[0] != '#') return false;
    const bool hex = body[1] == 'x' || body[1] == 'X';
    std::uint32_t cp = 0;
    const std::size_t start = hex ? 2 : 1;
    if (start >= body.size() || body.size() - start > 8) return false;
    for (std::size_t i = start; i < body.size(); ++i) {
        const char c = body[i];
        std::uint32_t digit = 0;
        if (c >= '0' && c <= '9')
            digit = static_cast<std::uint32_t>(c - '0');
        else if (hex && c >= 'a' && c <= 'f')
            digit = static_cast<std::uint32_t>(c - 'a' + 10);
        else if (hex && c >= 'A' && c <= 'F')
            digit = static_cast<std::uint32_t>(c - 'A' + 10);
        else
            return false;
        cp = cp * (hex ? 16 : 10) + digit;
    }
    if (cp == 0 || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    appendUtf8(out, cp);
    return true;
}

// Unknown entities (e.g. &ns_svg; from a DOCTYPE) are kept as written.
std::string decodeEntities(std::string_view raw) {
    std::string out;
    out.reserve(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
        // Entity names are short; looking only a few bytes ahead keeps this linear.
        const std::size_t semi =
            raw[i] == '&' ? raw.substr(0, i + 13).find(';', i) : std::string_view::npos;
        if (semi == std::string_view::npos) {
            out += raw[i];
            continue;
        }
        const std::string_view body = raw.substr(i + 1, semi - i - 1);
        if (body == "amp")
            out += '&';
        else if (body == "lt")
            out += '<';
        else if (body == "gt")
            out += '>';
        else if (body == "quot")
            out += '"';
        else if (body == "apos")
            out += '\'';
        else if (!decodeCharRef(body, out))
            out.append(raw.substr(i, semi - i + 1));
        i = semi;
    }
    return out;
}

class XmlParser {
public:
    XmlParser(std::string_view text, const std::string& fileName) : text_(text), file_(fileName) {}

    XmlDocument parse() {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
        while (pos_ < text_.size()) {
            const std::size_t lt = text_.find('<', pos_);
            if (lt == std::string_view::npos) break;
            pos_ = lt;
            markup();
        }
        if (!open_.empty()) {
            const XmlElement& e = doc_.elements[open_.back()];
            fail(text_.size(), "unclosed <" + e.name + "> (opened at line " +
                                   std::to_string(e.line) + "); expected </" + e.name + ">");
        }
        if (doc_.elements.empty()) fail(text_.size(), "no root element; expected <svg …>");
        return std::move(doc_);
    }

private:
    [[noreturn]] void fail(std::size_t at, const std::string& message) const {
        int line = 1;
        int column = 1;
        for (std::size_t i = 0; i < at && i < text_.size(); ++i) {
            if (text_[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        throw Error(SourceLoc{file_, line, column}, message);
    }

    void skipPast(std::string_view terminator, const char* what) {
        const std::size_t end = text_.find(terminator, pos_);
        if (end == std::string_view::npos) fail(pos_, std::string("unterminated ") + what);
        pos_ = end + terminator.size();
    }

    bool startsWith(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }

    void markup() {
        if (startsWith("<!--")) return skipPast("-->", "comment; expected -->");
        if (startsWith("<![CDATA[")) return skipPast("]]>", "CDATA section; expected ]]>");
        if (startsWith("<?")) return skipPast("?>", "processing instruction; expected ?>");
        if (startsWith("<!")) return doctype();
        if (startsWith("</")) return endTag();
        startTag();
    }

    void doctype() {
        int depth = 0;
        for (std::size_t i = pos_ + 2; i < text_.size(); ++i) {
            if (text_[i] == '[')
                ++depth;
            else if (text_[i] == ']')
                --depth;
            else if (text_[i] == '>' && depth <= 0) {
                pos_ = i + 1;
                return;
            }
        }
        fail(pos_, "unterminated <!DOCTYPE …>; expected >");
    }

    std::string name() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
        if (pos_ == start) fail(start, "expected a name");
        return std::string(text_.substr(start, pos_ - start));
    }

    void skipSpace() {
        while (pos_ < text_.size() && isXmlSpace(text_[pos_])) ++pos_;
    }

    void endTag() {
        const std::size_t start = pos_;
        pos_ += 2;
        const std::string closing = name();
        skipSpace();
        if (pos_ >= text_.size() || text_[pos_] != '>') fail(pos_, "expected > after </" + closing);
        ++pos_;
        if (open_.empty()) fail(start, "unexpected </" + closing + ">; no element is open");
        const std::string& expected = doc_.elements[open_.back()].name;
        if (closing != expected) {
            fail(start, "mismatched end tag; expected </" + expected + ">, got </" + closing + ">");
        }
        open_.pop_back();
    }

    void startTag() {
        const std::size_t start = pos_;
        if (open_.empty() && !doc_.elements.empty()) {
            fail(start, "a second root element; expected a single <svg> root");
        }
        if (open_.size() >= kMaxDepth) fail(start, "elements nested deeper than 256");
        ++pos_;
        XmlElement element;
        element.name = name();
        element.parent = open_.empty() ? -1 : open_.back();
        locate(start, element);
        for (;;) {
            skipSpace();
            if (pos_ >= text_.size()) fail(start, "unterminated <" + element.name + " …>");
            if (text_[pos_] == '>' || startsWith("/>")) break;
            attribute(element);
        }
        const bool selfClosing = text_[pos_] == '/';
        pos_ += selfClosing ? 2 : 1;
        doc_.elements.push_back(std::move(element));
        if (!selfClosing) open_.push_back(static_cast<int>(doc_.elements.size()) - 1);
    }

    void attribute(XmlElement& element) {
        const std::string key = name();
        skipSpace();
        if (pos_ >= text_.size() || text_[pos_] != '=') {
            fail(pos_, "expected = after attribute " + key + " of <" + element.name + ">");
        }
        ++pos_;
        skipSpace();
        if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\'')) {
            fail(pos_, "expected a quoted value for attribute " + key);
        }
        const char quote = text_[pos_++];
        const std::size_t end = text_.find(quote, pos_);
        if (end == std::string_view::npos) fail(pos_, "unterminated value of attribute " + key);
        // Duplicates are kept; attribute() finds the first, as browsers do.
        element.attributes.emplace_back(key, decodeEntities(text_.substr(pos_, end - pos_)));
        pos_ = end + 1;
    }

    // Line/column of element starts, computed incrementally (elements come in order).
    void locate(std::size_t at, XmlElement& element) {
        for (; lineScan_ < at; ++lineScan_) {
            if (text_[lineScan_] == '\n') {
                ++line_;
                lineStart_ = lineScan_ + 1;
            }
        }
        element.line = line_;
        element.column = static_cast<int>(at - lineStart_) + 1;
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t pos_ = 0;
    XmlDocument doc_;
    std::vector<int> open_;
    std::size_t lineScan_ = 0;
    std::size_t lineStart_ = 0;
    int line_ = 1;
};

}  // namespace

XmlDocument parseXml(std::string_view text, const std::string& fileName) {
    return XmlParser(text, fileName).parse();
}

}  // namespace ramus::detail
