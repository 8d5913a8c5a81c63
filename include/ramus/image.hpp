// 8-bit RGBA images: render output, and the textures materials carry (include/ramus/mesh.hpp).
#pragma once

#include <cstdint>
#include <vector>

namespace ramus {

/// An 8-bit RGBA image, rows top to bottom (glTF's texture orientation: uv (0, 0) is the
/// top-left pixel). Colour channels are sRGB-encoded, alpha is linear.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  ///< width · height · 4 bytes
};

}  // namespace ramus
