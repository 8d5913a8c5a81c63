// PNG previews: a small CPU rasterizer (z-buffer, Lambert + ambient lighting, framing to the
// model's bounds). Deterministic: same scene and params → identical pixels.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ramus/image.hpp"
#include "ramus/scene.hpp"

namespace ramus {

/// Camera directions, in glTF's axes (Y up, front +Z, the model's left at +X). Every view keeps
/// +Y up on screen except Top.
enum class View {
    Side,         ///< from -X toward +X: the model's right side, its front (+Z) facing right
    Front,        ///< from +Z toward -Z: facing the model, its left (+X) on the right
    Top,          ///< from +Y down: +X right, the front (+Z) toward the bottom of the image
    ThreeQuarter  ///< from front-left and above: azimuth 45° from +Z toward +X, elevation 25°
};

/// Parses "side", "front", "top" or "three-quarter" (also "threequarter" and "3q"); throws
/// Error listing the accepted names.
View parseView(const std::string& name);

/// An image size in pixels.
struct ImageSize {
    int width = 800;
    int height = 800;
};

/// Parses "WxH" (decimal integers separated by 'x' or 'X', e.g. "800x600") with
/// 16 <= W, H <= 8192; throws Error quoting the text and the expected form otherwise.
ImageSize parseImageSize(const std::string& text);

struct RenderParams {
    int width = 800;   ///< pixels, 1..16384
    int height = 800;  ///< pixels, 1..16384
    View view = View::ThreeQuarter;
    Vec4f background{1.0f, 1.0f, 1.0f, 1.0f};  ///< linear RGBA like material colours
    bool groundShadow = false;                 ///< reserved for skeleton previews
};

/// Renders the scene (all nodes with meshes, world transforms applied) with an orthographic
/// camera fitted to its bounds. An empty scene gives an image of the background colour.
/// Lighting: ambient + a key and a fill light fixed to the camera (Lambert) times the material's
/// base colour (times its baseColorTexture, sampled nearest with REPEAT, when the mesh has
/// uvs), written as sRGB; 3×3 supersampling. Back faces of single-sided materials are culled;
/// double-sided materials are lit from the side facing the camera. Alpha-masked materials
/// discard samples below their cutoff; other alpha is ignored (opaque). Normal maps are not
/// used. Throws Error for sizes outside 1..16384 or a scene that fails the exporters'
/// checks (e.g. indices out of range).
Image renderScene(const Scene& scene, const RenderParams& params = {});

/// One tile of a contact sheet: a rendered image and the label drawn under it.
struct SheetTile {
    Image image;
    std::string label;  ///< printable ASCII; other bytes print as '?'; cut to fit the tile
};

/// Layout of a contact sheet.
struct SheetParams {
    int columns = 0;  ///< tiles per row; 0 = the smallest n with n·n ≥ tile count
    int gap = 8;      ///< pixels between tiles and around the sheet
    bool labels = true;
    std::array<std::uint8_t, 4> background{255, 255, 255, 255};
    std::array<std::uint8_t, 4> text{30, 30, 30, 255};
};

/// Tiles images row by row into one image (issue 8 contact sheets): each cell is as large as
/// the largest tile (smaller tiles are centred), with the label under the tile in a simple
/// built-in font (stb_easy_font, scaled 2×). Throws Error for no tiles, a negative gap or
/// column count, or a sheet larger than 16384 px on a side.
Image composeContactSheet(const std::vector<SheetTile>& tiles, const SheetParams& params = {});

/// Encodes PNG bytes (stb_image_write).
std::string encodePng(const Image& image);

/// Writes a PNG atomically.
void writePng(const Image& image, const std::string& path);

}  // namespace ramus
