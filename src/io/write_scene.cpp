#include <algorithm>
#include <cctype>
#include <filesystem>

#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/file_util.hpp"

namespace ramus {

void writeScene(const Scene& scene, const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".glb") {
        writeGlb(scene, path);
    } else if (ext == ".obj") {
        writeObj(scene, path);
    } else {
        throw Error(path + ": unsupported output format '" + ext + "'; expected .glb or .obj");
    }
}

}  // namespace ramus
