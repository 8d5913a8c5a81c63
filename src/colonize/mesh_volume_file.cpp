// Based on: the Wavefront OBJ format ("Object Files (.obj)", Wavefront Advanced Visualizer
// manual, appendix B: `v` and `f` statements, relative (negative) indices); glTF 2.0 through
// readGltf (include/ramus/export.hpp). SPEC §C: attraction points inside a closed mesh.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string_view>

#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/mesh_volume.hpp"
#include "ramus/scene.hpp"

namespace ramus {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// Whitespace-separated tokens of a line, with their 1-based columns.
struct Token {
    std::string_view text;
    int column;
};

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start)
            tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return tokens;
}

class ObjReader {
public:
    explicit ObjReader(const std::string& fileName) : file_(fileName) {}

    void readLine(std::string_view line, int lineNumber) {
        line_ = lineNumber;
        const std::size_t hash = line.find('#');
        if (hash != std::string_view::npos) line = line.substr(0, hash);
        const std::vector<Token> tokens = tokenize(line);
        if (tokens.empty()) return;
        if (tokens[0].text == "v") readVertex(tokens);
        if (tokens[0].text == "f") readFace(tokens);
        // Everything else (vt, vn, o, g, s, usemtl, mtllib, l, p, …) does not change the volume.
    }

    MeshVolume finish() {
        try {
            return MeshVolume(std::move(vertices_), std::move(triangles_));
        } catch (const Error& e) {
            throw Error(SourceLoc{file_, 0, 0}, e.message());
        }
    }

private:
    [[noreturn]] void fail(int column, const std::string& message) const {
        throw Error(SourceLoc{file_, line_, column}, message);
    }

    void readVertex(const std::vector<Token>& tokens) {
        if (tokens.size() < 4) fail(tokens[0].column, "a vertex needs three coordinates x y z");
        Vec3 p;
        for (int k = 0; k < 3; ++k) {
            const Token& t = tokens[static_cast<std::size_t>(k + 1)];
            std::string_view s = t.text;
            if (!s.empty() && s.front() == '+') s.remove_prefix(1);
            const auto r = std::from_chars(s.data(), s.data() + s.size(), p[k]);
            if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(p[k])) {
                fail(t.column,
                     "invalid coordinate '" + std::string(t.text) + "'; expected a finite number");
            }
        }
        vertices_.push_back(p);
    }

    // "i", "i/t", "i//n" or "i/t/n"; i is 1-based, or negative counting back from the last.
    std::uint32_t vertexIndex(const Token& t) const {
        const std::string_view s = t.text.substr(0, t.text.find('/'));
        long long i = 0;
        const auto r = std::from_chars(s.data(), s.data() + s.size(), i);
        if (r.ec != std::errc() || r.ptr != s.data() + s.size() || i == 0) {
            fail(t.column, "invalid vertex reference '" + std::string(t.text) +
                               "'; expected a non-zero integer index");
        }
        const auto count = static_cast<long long>(vertices_.size());
        const long long index = i > 0 ? i - 1 : count + i;
        if (index < 0 || index >= count) {
            fail(t.column, "vertex index " + std::to_string(i) + " refers to no vertex (" +
                               std::to_string(count) + " defined above)");
        }
        return static_cast<std::uint32_t>(index);
    }

    void readFace(const std::vector<Token>& tokens) {
        if (tokens.size() < 4) fail(tokens[0].column, "a face needs at least three vertices");
        const std::uint32_t first = vertexIndex(tokens[1]);
        std::uint32_t previous = vertexIndex(tokens[2]);
        for (std::size_t k = 3; k < tokens.size(); ++k) {  // fan triangulation
            const std::uint32_t next = vertexIndex(tokens[k]);
            triangles_.push_back({first, previous, next});
            previous = next;
        }
    }

    std::string file_;
    int line_ = 0;
    std::vector<Vec3> vertices_;
    std::vector<Triangle> triangles_;
};

// Every mesh instance of the scene in world coordinates, as one triangle soup.
MeshVolume sceneVolume(const Scene& scene, const std::string& path) {
    std::vector<Vec3> vertices;
    std::vector<Triangle> triangles;
    auto add = [&](const Mesh& mesh, const Mat4& world) {
        const auto base = static_cast<std::uint32_t>(vertices.size());
        for (const Vec3f& p : mesh.positions) {
            vertices.push_back((world * p.cast<double>().homogeneous()).head<3>());
        }
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            triangles.push_back(
                {base + mesh.indices[i], base + mesh.indices[i + 1], base + mesh.indices[i + 2]});
        }
    };
    if (scene.nodes.empty()) {
        for (const Mesh& mesh : scene.meshes) add(mesh, Mat4::Identity());
    }
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const int m = scene.nodes[n].mesh;
        if (m >= 0 && m < static_cast<int>(scene.meshes.size())) {
            add(scene.meshes[static_cast<std::size_t>(m)],
                scene.worldTransform(static_cast<int>(n)));
        }
    }
    try {
        return MeshVolume(std::move(vertices), std::move(triangles));
    } catch (const Error& e) {
        throw Error(path + ": " + e.message());
    }
}

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

MeshVolume parseObjVolume(const std::string& text, const std::string& fileName) {
    ObjReader reader(fileName);
    std::size_t pos = 0;
    int lineNumber = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        reader.readLine(line, ++lineNumber);
        pos = end + 1;
    }
    return reader.finish();
}

MeshVolume readMeshVolume(const std::string& path, std::size_t maxBytes) {
    const std::string ext = lowerExtension(path);
    if (ext == ".obj") return parseObjVolume(readFile(path, maxBytes), path);
    if (ext == ".glb" || ext == ".gltf") return sceneVolume(readGltf(path, maxBytes), path);
    throw Error(path + ": unknown mesh file extension '" + ext + "'; expected .obj, .glb or .gltf");
}

}  // namespace ramus
