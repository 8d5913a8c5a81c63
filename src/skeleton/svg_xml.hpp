// Internal: a small, non-validating XML reader for annotated SVG files — elements, attributes
// (entity references decoded), nesting; text, comments, processing instructions, CDATA and the
// DOCTYPE are skipped. Enough for what Inkscape and other editors write; no external entities,
// so nothing is ever fetched.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ramus::detail {

struct XmlElement {
    std::string name;  ///< qualified name as written ("path", "svg:path", "inkscape:label")
    std::vector<std::pair<std::string, std::string>> attributes;  ///< in document order
    int parent = -1;  ///< index into XmlDocument::elements; -1 for the root
    int line = 0;     ///< 1-based position of the '<'
    int column = 0;

    /// The attribute's decoded value, or nullptr.
    const std::string* attribute(std::string_view attributeName) const;
    /// The name without a namespace prefix ("svg:path" → "path").
    std::string_view localName() const;
};

struct XmlDocument {
    std::vector<XmlElement> elements;  ///< document order; elements[0] is the root
};

/// Parses `text`. Throws Error("fileName:line:col: …") for malformed markup: unclosed or
/// mismatched tags, bad attribute syntax, unterminated comments, more than one root element,
/// no root element, or nesting deeper than 256.
XmlDocument parseXml(std::string_view text, const std::string& fileName);

/// Escapes & < > " and tab/CR/LF (as character references) for an attribute value or text.
std::string escapeXml(std::string_view text);

}  // namespace ramus::detail
