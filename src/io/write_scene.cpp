#include <algorithm>
#include <cctype>
#include <filesystem>

#include "ramus/error.hpp"
#include "ramus/export.hpp"

namespace ramus {

void writeScene(const Scene& scene, const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".glb") {
        writeGlb(scene, path);
    } else if (ext == ".obj") {
        writeObj(scene, path);
    } else {
        throw Error(path + ": unsupported output format '" + ext + "'; expected .glb or .obj");
    }
}

}  // namespace ramus
