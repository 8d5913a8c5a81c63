// Based on: the Wavefront OBJ format through io::parseObjGeometry (`v` and `f` statements,
// relative indices); glTF 2.0 through readGltf (include/ramus/export.hpp). SPEC §C: attraction
// points inside a closed mesh.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "io/obj_reader.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"
#include "ramus/mesh_volume.hpp"
#include "ramus/scene.hpp"

namespace ramus {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

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

}  // namespace

MeshVolume parseObjVolume(const std::string& text, const std::string& fileName) {
    io::ObjGeometry obj = io::parseObjGeometry(text, fileName);
    std::vector<Triangle> triangles;
    triangles.reserve(obj.triangles.size());
    for (const auto& t : obj.triangles) {
        triangles.push_back({t[0].position, t[1].position, t[2].position});
    }
    try {
        return MeshVolume(std::move(obj.positions), std::move(triangles));
    } catch (const Error& e) {
        throw Error(SourceLoc{fileName, 0, 0}, e.message());
    }
}

MeshVolume readMeshVolume(const std::string& path, std::size_t maxBytes) {
    const std::string ext = lowerExtension(path);
    if (ext == ".obj") return parseObjVolume(readFile(path, maxBytes), path);
    if (ext == ".glb" || ext == ".gltf") return sceneVolume(readGltf(path, maxBytes), path);
    throw Error(path + ": unknown mesh file extension '" + ext + "'; expected .obj, .glb or .gltf");
}

}  // namespace ramus
