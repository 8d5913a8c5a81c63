// Based on: SPEC §C ("points from a file"); formats: plain XYZ point lists, CSV (RFC 4180
// subset: no quoting), and the ASCII variant of the PLY format (Turk 1994,
// http://paulbourke.net/dataformats/ply/).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

#include "ramus/envelope.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"

namespace ramus {

namespace {

struct LineReader {
    std::string_view text;
    std::size_t pos = 0;
    int lineNumber = 0;

    bool next(std::string_view& line) {
        if (pos >= text.size()) return false;
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        line = text.substr(pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos = end + 1;
        ++lineNumber;
        return true;
    }
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// Splits at any character of `separators`, dropping empty fields when `skipEmpty`.
std::vector<std::string_view> split(std::string_view s, std::string_view separators,
                                    bool skipEmpty) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i) {
        if (i == s.size() || separators.find(s[i]) != std::string_view::npos) {
            std::string_view field = trim(s.substr(start, i - start));
            if (!field.empty() || !skipEmpty) fields.push_back(field);
            start = i + 1;
        }
    }
    return fields;
}

// A whole field as a double; `ec` tells a number beyond double range (1e999) from no number.
bool parseNumber(std::string_view s, double& value, std::errc* ec = nullptr) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    const auto result = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec) *ec = result.ec;
    return result.ec == std::errc() && result.ptr == s.data() + s.size();
}

[[noreturn]] void fail(const std::string& file, int line, const std::string& message) {
    throw Error(SourceLoc{file, line, 0}, message);
}

// Reads three coordinates from fields[ix], fields[iy], fields[iz].
Vec3 readXyz(const std::vector<std::string_view>& fields, const int index[3],
             const std::string& file, int line) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
        const std::string_view field = fields[static_cast<std::size_t>(index[k])];
        std::errc ec{};
        if (!parseNumber(field, p[k], &ec)) {
            fail(file, line,
                 ec == std::errc::result_out_of_range
                     ? "coordinate '" + std::string(field) +
                           "' is outside the range of a double; expected a finite number"
                     : "invalid coordinate '" + std::string(field) + "'; expected a number");
        }
        if (!std::isfinite(p[k])) {
            fail(file, line, "coordinate '" + std::string(field) + "' is not finite");
        }
    }
    return p;
}

std::vector<Vec3> parseXyzOrCsv(std::string_view text, bool csv, const std::string& file) {
    std::vector<Vec3> points;
    LineReader reader{text};
    std::string_view line;
    const int index[3] = {0, 1, 2};
    bool first = true;
    while (reader.next(line)) {
        line = trim(line);
        if (line.empty() || line.front() == '#') continue;
        const auto fields = csv ? split(line, ",", false) : split(line, " \t", true);
        double ignored = 0;
        if (csv && first && !fields.empty() && !parseNumber(fields[0], ignored)) {
            first = false;  // a header line such as "x,y,z"
            continue;
        }
        first = false;
        if (fields.size() < 3) {
            fail(file, reader.lineNumber,
                 "expected 3 coordinates x" + std::string(csv ? "," : " ") + "y" +
                     std::string(csv ? "," : " ") + "z; got " + std::to_string(fields.size()) +
                     " field(s)");
        }
        points.push_back(readXyz(fields, index, file, reader.lineNumber));
    }
    return points;
}

constexpr double kMaxPlyVertices = 4294967295.0;

struct PlyHeader {
    std::size_t vertexCount = 0;
    std::size_t propertyCount = 0;
    int xyz[3] = {-1, -1, -1};
    bool vertexFirst = true;  // the vertex element is the first element
};

PlyHeader readPlyHeader(LineReader& reader, const std::string& file) {
    PlyHeader header;
    std::string_view line;
    if (!reader.next(line) || trim(line) != "ply") fail(file, 1, "not a PLY file; expected 'ply'");
    bool inVertex = false, sawElement = false;
    while (reader.next(line)) {
        const auto words = split(trim(line), " \t", true);
        if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
        if (words[0] == "end_header") {
            if (header.xyz[0] < 0 || header.xyz[1] < 0 || header.xyz[2] < 0) {
                fail(file, reader.lineNumber, "the vertex element lacks property x, y or z");
            }
            return header;
        }
        if (words[0] == "format") {
            if (words.size() < 2 || words[1] != "ascii") {
                fail(file, reader.lineNumber,
                     "unsupported PLY format; expected 'format ascii 1.0'");
            }
        } else if (words[0] == "element" && words.size() >= 3) {
            inVertex = words[1] == "vertex";
            if (inVertex) {
                header.vertexFirst = !sawElement;
                double count = 0;
                if (!parseNumber(words[2], count) || !(count >= 0) || count > kMaxPlyVertices ||
                    count != std::floor(count)) {
                    fail(file, reader.lineNumber,
                         "invalid vertex count '" + std::string(words[2]) +
                             "'; expected an integer from 0 to 4294967295");
                }
                header.vertexCount = static_cast<std::size_t>(count);
            }
            sawElement = true;
        } else if (words[0] == "property" && inVertex) {
            if (words.size() >= 3 && words[1] == "list") {
                fail(file, reader.lineNumber, "list properties on vertices are not supported");
            }
            const std::string_view name = words.back();
            for (int k = 0; k < 3; ++k) {
                if (name == std::string_view("xyz").substr(static_cast<std::size_t>(k), 1)) {
                    header.xyz[k] = static_cast<int>(header.propertyCount);
                }
            }
            ++header.propertyCount;
        }
    }
    fail(file, reader.lineNumber, "the PLY header has no 'end_header'");
}

std::vector<Vec3> parsePly(std::string_view text, const std::string& file) {
    LineReader reader{text};
    const PlyHeader header = readPlyHeader(reader, file);
    if (!header.vertexFirst) {
        fail(file, reader.lineNumber, "the vertex element must be the first PLY element");
    }
    std::vector<Vec3> points;
    // The header's count is not trusted for the reservation: a vertex line takes at least
    // 6 bytes ("0 0 0\n"), so the rest of the text bounds how many can follow.
    const std::size_t rest = text.size() - std::min(reader.pos, text.size());
    points.reserve(std::min(header.vertexCount, rest / 6));
    std::string_view line;
    while (points.size() < header.vertexCount) {
        if (!reader.next(line)) {
            fail(file, reader.lineNumber,
                 "the file ends after " + std::to_string(points.size()) + " of " +
                     std::to_string(header.vertexCount) + " vertices");
        }
        line = trim(line);
        if (line.empty()) continue;
        const auto fields = split(line, " \t", true);
        if (fields.size() < header.propertyCount) {
            fail(file, reader.lineNumber,
                 "expected " + std::to_string(header.propertyCount) + " vertex properties; got " +
                     std::to_string(fields.size()));
        }
        points.push_back(readXyz(fields, header.xyz, file, reader.lineNumber));
    }
    return points;
}

}  // namespace

std::vector<Vec3> parsePoints(const std::string& text, const std::string& format,
                              const std::string& fileName) {
    if (format == "xyz") return parseXyzOrCsv(text, false, fileName);
    if (format == "csv") return parseXyzOrCsv(text, true, fileName);
    if (format == "ply") return parsePly(text, fileName);
    throw Error(fileName + ": unknown point format '" + format + "'; expected xyz, csv or ply");
}

std::vector<Vec3> readPointsFile(const std::string& path, std::size_t maxBytes) {
    std::string ext = lowerExtension(path);
    if (!ext.empty()) ext.erase(0, 1);  // without the dot
    if (ext == "txt") ext = "xyz";
    if (ext != "xyz" && ext != "csv" && ext != "ply") {
        throw Error(path + ": unsupported point file extension '." + ext +
                    "'; expected .xyz, .txt, .csv or .ply");
    }
    return parsePoints(readFile(path, maxBytes), ext, path);
}

}  // namespace ramus
