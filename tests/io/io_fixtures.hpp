// Scenes and helpers shared by the io tests.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

#include "ramus/export.hpp"
#include "ramus/scene.hpp"

namespace ramus::testing {

/// An axis-aligned cube centred at `center` with edge 2·half: 24 vertices (4 per face, flat
/// normals, uvs and tangents), 12 counter-clockwise triangles, one implicit primitive.
inline Mesh makeCube(float half = 0.5f, Vec3f center = Vec3f::Zero()) {
    Mesh mesh;
    mesh.name = "cube";
    const Vec3f normals[6] = {Vec3f::UnitX(),  -Vec3f::UnitX(), Vec3f::UnitY(),
                              -Vec3f::UnitY(), Vec3f::UnitZ(),  -Vec3f::UnitZ()};
    for (const Vec3f& n : normals) {
        const Vec3f t = n.x() != 0.0f ? Vec3f(0.0f, 0.0f, -n.x())
                                      : (n.y() != 0.0f ? Vec3f::UnitX() : Vec3f(n.z(), 0.0f, 0.0f));
        const Vec3f b = n.cross(t);  // t × b = n, so (t, b) corners in order are CCW from outside
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        const float st[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : st) {
            mesh.positions.push_back(center + (n + c[0] * t + c[1] * b) * half);
            mesh.normals.push_back(n);
            mesh.tangents.push_back(Vec4f(t.x(), t.y(), t.z(), 1.0f));
            mesh.uvs.push_back(Vec2f(0.5f * (c[0] + 1.0f), 0.5f * (c[1] + 1.0f)));
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    }
    return mesh;
}

/// Two meshes — a cube whose faces are split into two primitives ("bark": 4 faces, "leaves": 2
/// faces, double-sided and translucent) and a small plain cube — placed by a three-level node
/// hierarchy with extras: root → {trunk (cube), branch → twig (small cube)}.
inline Scene makeHierarchyScene() {
    Scene scene;
    Mesh tree = makeCube(0.5f);
    tree.name = "tree";
    tree.materials = {Material{"bark", {0.4f, 0.25f, 0.1f, 1.0f}, 0.0f, 0.95f, false},
                      Material{"leaves", {0.2f, 0.6f, 0.15f, 0.5f}, 0.0f, 0.6f, true}};
    tree.primitives = {MeshPrimitive{0, 24, 0, "bark"}, MeshPrimitive{24, 12, 1, "leaves"}};
    Mesh twig = makeCube(0.1f);
    twig.name = "twig";
    scene.meshes = {tree, twig};

    SceneNode root;
    root.name = "root";
    root.extrasJson = R"({"kind":"root","side":"center"})";
    SceneNode trunk;
    trunk.name = "trunk";
    trunk.parent = 0;
    trunk.mesh = 0;
    trunk.translation = Vec3(0.0, 0.5, 0.0);
    SceneNode branch;
    branch.name = "branch";
    branch.parent = 0;
    branch.translation = Vec3(0.25, 1.0, 0.0);
    branch.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Vec3::UnitZ()));
    branch.extrasJson = R"({"limb":"arm","limits":[-0.5,1.25]})";
    SceneNode leaf;
    leaf.name = "twig_L";
    leaf.parent = 2;
    leaf.mesh = 1;
    leaf.translation = Vec3(0.0, 0.4, 0.1);
    leaf.scale = Vec3(1.0, 2.0, 1.0);
    scene.nodes = {root, trunk, branch, leaf};
    scene.extrasJson = R"({"seed":7})";
    return scene;
}

/// A fresh empty directory under the system temp directory.
inline std::filesystem::path scratchDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ramus_io_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// Writes `scene` as $RAMUS_TEST_OUTPUT/io_<name>.glb for the glTF validator (no-op when the
/// variable is unset).
inline void exportForValidator(const Scene& scene, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir == nullptr || *dir == '\0') return;
    std::filesystem::create_directories(dir);
    writeGlb(scene, (std::filesystem::path(dir) / ("io_" + name + ".glb")).string());
}

/// Copies the hand-written glTF test file `gltfPath` and the .bin files next to it into
/// $RAMUS_TEST_OUTPUT/io_reader_<name>/ for the glTF validator (no-op when unset).
inline void exportGltfForValidator(const std::string& gltfPath, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir == nullptr || *dir == '\0') return;
    const std::filesystem::path target = std::filesystem::path(dir) / ("io_reader_" + name);
    std::filesystem::create_directories(target);
    const std::filesystem::path source(gltfPath);
    for (const auto& entry : std::filesystem::directory_iterator(source.parent_path())) {
        const std::string ext = entry.path().extension().string();
        if (ext == ".bin" || entry.path() == source) {
            std::filesystem::copy_file(entry.path(), target / entry.path().filename(),
                                       std::filesystem::copy_options::overwrite_existing);
        }
    }
}

}  // namespace ramus::testing
