// Bone model meshes as files (bones/bone_files.hpp): reading OBJ/glTF/GLB models of a user
// library, the closed/outward/non-degenerate checks, and the OBJ text the library is written as.
//
// Based on: the Wavefront OBJ format (io/obj_reader.hpp); glTF 2.0 through readGltf; the
// divergence theorem for the signed volume of a closed triangle mesh (Σ a·(b×c)/6).
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <unordered_map>

#include "bones/bone_files.hpp"
#include "io/obj_reader.hpp"
#include "io/scene_check.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "skeleton/number_text.hpp"

namespace ramus::detail {
namespace {

/// Ids that are equal exactly for vertices at equal positions (−0 = +0), in vertex order.
std::vector<std::uint32_t> weldedIds(const std::vector<Vec3f>& positions) {
    struct Hash {
        std::size_t operator()(const std::array<std::uint32_t, 3>& k) const {
            return (std::size_t{k[0]} * 0x9E3779B1u) ^ (std::size_t{k[1]} * 0x85EBCA77u) ^
                   (std::size_t{k[2]} * 0xC2B2AE3Du);
        }
    };
    std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, Hash> ids;
    std::vector<std::uint32_t> out(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const Vec3f& p = positions[i];
        const std::array<std::uint32_t, 3> key = {std::bit_cast<std::uint32_t>(p.x() + 0.0f),
                                                  std::bit_cast<std::uint32_t>(p.y() + 0.0f),
                                                  std::bit_cast<std::uint32_t>(p.z() + 0.0f)};
        out[i] = ids.emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
    }
    return out;
}

Vec3 corner(const Mesh& mesh, std::size_t t, int k) {
    return mesh.positions[mesh.indices[3 * t + static_cast<std::size_t>(k)]].cast<double>();
}

Vec3 triangleCross(const Mesh& mesh, std::size_t t) {
    const Vec3 a = corner(mesh, t, 0);
    return (corner(mesh, t, 1) - a).cross(corner(mesh, t, 2) - a);
}

class MeshChecker {
public:
    MeshChecker(const Mesh& mesh, const std::string& file, const std::vector<int>& lines)
        : mesh_(mesh), file_(file), lines_(lines) {}

    void run() {
        if (mesh_.indices.empty() || mesh_.indices.size() % 3 != 0) {
            throw Error(SourceLoc{file_, 0, 0},
                        "the mesh has no triangles; expected a closed triangle mesh");
        }
        for (const Vec3f& p : mesh_.positions) {
            if (!p.allFinite()) throw Error(SourceLoc{file_, 0, 0}, "a vertex is not finite");
        }
        ids_ = weldedIds(mesh_.positions);
        checkTriangles();
        checkEdges();
        checkVolume();
    }

private:
    [[noreturn]] void fail(std::size_t triangle, const std::string& message) const {
        const int line = triangle < lines_.size() ? lines_[triangle] : 0;
        const std::string which =
            line > 0 ? "face" : "triangle " + std::to_string(triangle + 1) + " (1-based)";
        throw Error(SourceLoc{file_, line, 0}, which + " " + message);
    }

    std::uint32_t id(std::size_t t, int k) const {
        return ids_[mesh_.indices[3 * t + static_cast<std::size_t>(k)]];
    }

    void checkTriangles() const {
        for (std::size_t t = 0; t < mesh_.triangleCount(); ++t) {
            const bool repeated =
                id(t, 0) == id(t, 1) || id(t, 1) == id(t, 2) || id(t, 0) == id(t, 2);
            if (repeated || !(triangleCross(mesh_, t).norm() > 0.0)) {
                fail(t,
                     "is degenerate (zero area); expected triangles with three distinct, "
                     "non-collinear corners");
            }
        }
    }

    static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
        return (std::uint64_t{a} << 32) | b;
    }

    // Closed and consistently oriented: every directed edge once, and its reverse once.
    void checkEdges() const {
        std::unordered_map<std::uint64_t, int> uses;
        uses.reserve(mesh_.indices.size());
        for (std::size_t t = 0; t < mesh_.triangleCount(); ++t) {
            for (int k = 0; k < 3; ++k) ++uses[key(id(t, k), id(t, (k + 1) % 3))];
        }
        std::size_t open = 0, flipped = 0, firstBad = mesh_.triangleCount();
        for (std::size_t t = 0; t < mesh_.triangleCount(); ++t) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = id(t, k), b = id(t, (k + 1) % 3);
                const auto back = uses.find(key(b, a));
                const bool bad = uses[key(a, b)] > 1 || back == uses.end() || back->second > 1;
                if (back == uses.end()) ++open;
                if (uses[key(a, b)] > 1) ++flipped;
                if (bad) firstBad = std::min(firstBad, t);
            }
        }
        if (firstBad == mesh_.triangleCount()) return;
        fail(firstBad, "has an edge that is " + std::string(open > 0 ? "open" : "shared wrongly") +
                           " (the mesh has " + std::to_string(open) + " open edge(s) and " +
                           std::to_string(flipped) +
                           " edge use(s) repeated in one direction); expected a closed mesh, "
                           "each edge shared by two triangles facing the same way");
    }

    void checkVolume() const {
        double volume = 0.0;
        for (std::size_t t = 0; t < mesh_.triangleCount(); ++t) {
            volume += corner(mesh_, t, 0).dot(corner(mesh_, t, 1).cross(corner(mesh_, t, 2)));
        }
        volume /= 6.0;
        if (!(volume > 0.0)) {
            throw Error(SourceLoc{file_, 0, 0},
                        "the mesh encloses a signed volume of " + detail::shortest(volume) +
                            "; expected a positive one (triangles counter-clockwise seen from "
                            "outside; flip the normals / face orientation)");
        }
    }

    const Mesh& mesh_;
    const std::string& file_;
    const std::vector<int>& lines_;
    std::vector<std::uint32_t> ids_;
};

/// Area-weighted vertex normals, summed over vertices at equal positions.
void computeNormals(Mesh& mesh) {
    const std::vector<std::uint32_t> ids = weldedIds(mesh.positions);
    std::vector<Vec3> sums(mesh.positions.size(), Vec3::Zero());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 cross = triangleCross(mesh, t);
        for (int k = 0; k < 3; ++k) sums[ids[mesh.indices[3 * t + k]]] += cross;
    }
    mesh.normals.resize(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& s = sums[ids[i]];
        mesh.normals[i] =
            s.norm() > 0.0 ? Vec3f(s.normalized().cast<float>()) : Vec3f(Vec3f::UnitX());
    }
}

/// The OBJ's vertices: the distinct (position, normal) pairs of the face corners, ascending.
Mesh objMesh(const io::ObjGeometry& obj) {
    bool normals = !obj.triangles.empty();
    for (const auto& t : obj.triangles) {
        for (const io::ObjCorner& c : t) normals = normals && c.normal >= 0;
    }
    std::vector<std::pair<std::uint32_t, std::int64_t>> pairs;
    pairs.reserve(obj.triangles.size() * 3);
    for (const auto& t : obj.triangles) {
        for (const io::ObjCorner& c : t) pairs.emplace_back(c.position, normals ? c.normal : -1);
    }
    std::vector<std::pair<std::uint32_t, std::int64_t>> vertices = pairs;
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    Mesh mesh;
    for (const auto& [p, n] : vertices) {
        mesh.positions.push_back(obj.floatPositions[p]);
        if (normals) mesh.normals.push_back(obj.normals[static_cast<std::size_t>(n)]);
    }
    mesh.indices.reserve(pairs.size());
    for (const auto& pair : pairs) {
        const auto at = std::lower_bound(vertices.begin(), vertices.end(), pair);
        mesh.indices.push_back(static_cast<std::uint32_t>(at - vertices.begin()));
    }
    return mesh;
}

/// Every mesh of a glTF scene placed by its node, merged (positions, normals, triangles).
Mesh sceneMesh(const Scene& scene, const std::string& path) {
    io::checkScene(scene, path);
    Mesh out;
    bool normals = true;
    for (const io::MeshInstance& inst : io::meshInstances(scene)) {
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(inst.mesh)];
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        const bool identity = inst.world == Mat4::Identity();
        const Eigen::Matrix3d m = inst.world.topLeftCorner<3, 3>();
        const Eigen::Matrix3d normalMatrix = m.inverse().transpose();
        for (const Vec3f& p : mesh.positions) {
            out.positions.push_back(
                identity
                    ? p
                    : Vec3f((inst.world * p.cast<double>().homogeneous()).head<3>().cast<float>()));
        }
        normals = normals && mesh.normals.size() == mesh.positions.size();
        for (std::size_t i = 0; normals && i < mesh.normals.size(); ++i) {
            const Vec3 n = normalMatrix * mesh.normals[i].cast<double>();
            out.normals.push_back(identity ? mesh.normals[i] : Vec3f(n.normalized().cast<float>()));
        }
        const bool mirrored = m.determinant() < 0.0;  // turn the triangles back outwards
        for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
            out.indices.push_back(base + mesh.indices[k]);
            out.indices.push_back(base + mesh.indices[mirrored ? k + 2 : k + 1]);
            out.indices.push_back(base + mesh.indices[mirrored ? k + 1 : k + 2]);
        }
    }
    if (!normals) out.normals.clear();
    return out;
}

}  // namespace

void checkBoneMesh(const Mesh& mesh, const std::string& file,
                   const std::vector<int>& triangleLines) {
    MeshChecker(mesh, file, triangleLines).run();
}

Mesh readBoneMesh(const std::string& path, const std::string& name) {
    const std::string ext = lowerExtension(path);
    Mesh mesh;
    std::vector<int> lines;
    if (ext == ".obj") {
        io::ObjGeometry obj = io::parseObjGeometry(readFile(path), path);
        mesh = objMesh(obj);
        lines = std::move(obj.triangleLines);
    } else if (ext == ".glb" || ext == ".gltf") {
        mesh = sceneMesh(readGltf(path), path);
    } else {
        throw Error(SourceLoc{path, 0, 0},
                    "unknown mesh file extension '" + ext + "'; expected .obj, .gltf or .glb");
    }
    checkBoneMesh(mesh, path, lines);
    for (const Vec3f& n : mesh.normals) {
        if (!n.allFinite() || !(n.norm() > 0.0f)) {
            throw Error(SourceLoc{path, 0, 0}, "a normal is zero or not finite");
        }
    }
    if (mesh.normals.empty()) computeNormals(mesh);
    mesh.name = name;
    return mesh;
}

std::string boneMeshObj(const Mesh& mesh, const std::string& title) {
    std::string out = "# " + title + "\n";
    out.reserve(mesh.positions.size() * 70 + mesh.indices.size() * 8);
    auto vector = [&out](const char* tag, const Vec3f& v) {
        out += tag;
        for (int k = 0; k < 3; ++k) out += ' ' + io::formatFloat(v[k]);
        out += '\n';
    };
    for (const Vec3f& p : mesh.positions) vector("v", p);
    for (const Vec3f& n : mesh.normals) vector("vn", n);
    const bool normals = mesh.normals.size() == mesh.positions.size();
    for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
        out += 'f';
        for (int c = 0; c < 3; ++c) {
            const std::string i = std::to_string(mesh.indices[k + c] + 1);
            out += ' ' + (normals ? i + "//" + i : i);
        }
        out += '\n';
    }
    return out;
}

}  // namespace ramus::detail
