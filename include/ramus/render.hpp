// PNG previews: a small CPU rasterizer (z-buffer, Lambert + ambient lighting, framing to the
// model's bounds). Deterministic: same scene and params → identical pixels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ramus/scene.hpp"

namespace ramus {

enum class View { Side, Front, Top, ThreeQuarter };

/// Parses "side|front|top|three-quarter"; throws Error listing the accepted names.
View parseView(const std::string& name);

struct RenderParams {
    int width = 800;
    int height = 800;
    View view = View::ThreeQuarter;
    Vec4f background{1.0f, 1.0f, 1.0f, 1.0f};
    bool groundShadow = false;  ///< reserved for skeleton previews
};

/// An 8-bit RGBA image, rows top to bottom.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

/// Renders the scene (all nodes with meshes, world transforms applied) with an orthographic
/// camera fitted to its bounds. An empty scene gives an image of the background colour.
Image renderScene(const Scene& scene, const RenderParams& params = {});

/// Encodes PNG bytes (stb_image_write).
std::string encodePng(const Image& image);

/// Writes a PNG atomically.
void writePng(const Image& image, const std::string& path);

}  // namespace ramus
