// Based on: the Wavefront OBJ format ("Object Files (.obj)", Wavefront Advanced Visualizer
// manual, appendix B: `v`, `vn` and `f` statements, relative (negative) indices).
#include "io/obj_reader.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "ramus/error.hpp"

namespace ramus::io {

namespace {

bool isObjSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// Whitespace-separated tokens of a line, with their 1-based columns.
struct Token {
    std::string_view text;
    int column;
};

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isObjSpace(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isObjSpace(line[i])) ++i;
        if (i > start)
            tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return tokens;
}

class ObjParser {
public:
    explicit ObjParser(const std::string& fileName) : file_(fileName) {}

    void readLine(std::string_view line, int lineNumber) {
        line_ = lineNumber;
        const std::size_t hash = line.find('#');
        if (hash != std::string_view::npos) line = line.substr(0, hash);
        const std::vector<Token> tokens = tokenize(line);
        if (tokens.empty()) return;
        Vec3 p;
        Vec3f f;
        if (tokens[0].text == "v") {
            readVector(tokens, "vertex", p, f);
            geometry_.positions.push_back(p);
            geometry_.floatPositions.push_back(f);
        }
        if (tokens[0].text == "vn") {
            readVector(tokens, "normal", p, f);
            geometry_.normals.push_back(f);
        }
        if (tokens[0].text == "f") readFace(tokens);
    }

    ObjGeometry finish() { return std::move(geometry_); }

private:
    [[noreturn]] void fail(int column, const std::string& message) const {
        throw Error(SourceLoc{file_, line_, column}, message);
    }

    // Three coordinates as doubles (validated) and each also parsed as a float (the cast of the
    // double where the float parse is out of range).
    void readVector(const std::vector<Token>& tokens, const char* what, Vec3& p, Vec3f& f) const {
        if (tokens.size() < 4) {
            fail(tokens[0].column, std::string("a ") + what + " needs three coordinates x y z");
        }
        for (int k = 0; k < 3; ++k) {
            const Token& t = tokens[static_cast<std::size_t>(k + 1)];
            std::string_view s = t.text;
            if (!s.empty() && s.front() == '+') s.remove_prefix(1);
            const auto r = std::from_chars(s.data(), s.data() + s.size(), p[k]);
            if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(p[k])) {
                fail(t.column,
                     "invalid coordinate '" + std::string(t.text) + "'; expected a finite number");
            }
            if (std::from_chars(s.data(), s.data() + s.size(), f[k]).ec != std::errc()) {
                f[k] = static_cast<float>(p[k]);
            }
        }
    }

    // A 1-based or negative reference among `count` defined items → 0-based index.
    std::int64_t resolve(const Token& t, std::string_view s, std::size_t count,
                         const char* what) const {
        long long i = 0;
        const auto r = std::from_chars(s.data(), s.data() + s.size(), i);
        if (r.ec != std::errc() || r.ptr != s.data() + s.size() || i == 0) {
            fail(t.column, "invalid " + std::string(what) + " reference '" + std::string(t.text) +
                               "'; expected a non-zero integer index");
        }
        const auto defined = static_cast<long long>(count);
        const long long index = i > 0 ? i - 1 : defined + i;
        if (index < 0 || index >= defined) {
            fail(t.column, std::string(what) + " index " + std::to_string(i) + " refers to no " +
                               what + " (" + std::to_string(defined) + " defined above)");
        }
        return index;
    }

    // "i", "i/t", "i//n" or "i/t/n".
    ObjCorner corner(const Token& t) const {
        const std::size_t slash = t.text.find('/');
        ObjCorner c;
        c.position = static_cast<std::uint32_t>(
            resolve(t, t.text.substr(0, slash), geometry_.positions.size(), "vertex"));
        if (slash == std::string_view::npos) return c;
        const std::size_t second = t.text.find('/', slash + 1);
        if (second == std::string_view::npos || second + 1 == t.text.size()) return c;
        c.normal = resolve(t, t.text.substr(second + 1), geometry_.normals.size(), "normal");
        return c;
    }

    void readFace(const std::vector<Token>& tokens) {
        if (tokens.size() < 4) fail(tokens[0].column, "a face needs at least three vertices");
        const ObjCorner first = corner(tokens[1]);
        ObjCorner previous = corner(tokens[2]);
        for (std::size_t k = 3; k < tokens.size(); ++k) {  // fan triangulation
            const ObjCorner next = corner(tokens[k]);
            geometry_.triangles.push_back({first, previous, next});
            geometry_.triangleLines.push_back(line_);
            previous = next;
        }
    }

    std::string file_;
    int line_ = 0;
    ObjGeometry geometry_;
};

}  // namespace

ObjGeometry parseObjGeometry(std::string_view text, const std::string& fileName) {
    ObjParser parser(fileName);
    std::size_t pos = 0;
    int lineNumber = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        parser.readLine(line, ++lineNumber);
        pos = end + 1;
    }
    return parser.finish();
}

}  // namespace ramus::io
