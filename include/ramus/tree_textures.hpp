// Procedural default textures for exported trees (issue 9): a tileable bark colour and normal
// map and an alpha-masked leaf, generated deterministically by code (no image files shipped).
#pragma once

#include <cstdint>
#include <memory>

#include "ramus/image.hpp"

namespace ramus {

/// Bark texture settings. The image tiles seamlessly in u and v (all noise is periodic over
/// the image); width × height in pixels, each a power of two in 16..4096. The tube mesher maps
/// u once around a branch, so TubeMeshParams::uvAspect should be height / width (the default,
/// 512 / 256 = 2) to keep texels square.
struct BarkTextureParams {
    int width = 256;
    int height = 512;
    int furrows = 7;  ///< vertical furrows across the width (≥ 1)
    std::uint64_t seed = 0;
};

/// Throws Error for sizes that are not powers of two in 16..4096 or furrows < 1.
void validateBarkTextureParams(const BarkTextureParams& params);

/// The bark's height field in [0, 1] (1 = ridge, 0 = bottom of a furrow), width × height
/// values row by row: vertical furrows from periodic ridged value noise, warped sideways and
/// broken up along v, plus fine grain.
std::vector<float> barkHeightField(const BarkTextureParams& params);

/// Bark colour (sRGB, opaque): dark in the furrows, lighter grey-brown on the ridges.
Image makeBarkTexture(const BarkTextureParams& params = {});

/// Tangent-space normal map of the same height field (glTF convention: +X = +u, +Y = image up
/// = decreasing v), encoded as (n + 1) / 2 in RGB, alpha 255.
Image makeBarkNormalMap(const BarkTextureParams& params = {});

/// A single leaf filling the image (base at the bottom centre, tip at the top centre, outline
/// leafOutlineHalfWidth), green with a lighter midrib and veins; alpha 255 inside, 0 outside
/// (for alphaMode MASK). `size` × `size` pixels, a power of two in 16..4096.
Image makeLeafTexture(int size = 256);

/// The default textures, made once and shared (meshes hold them by pointer).
struct TreeTextures {
    std::shared_ptr<const Image> barkColor, barkNormal, leafColor;
    double barkAspect = 2.0;  ///< height / width of the bark images (TubeMeshParams::uvAspect)
};
TreeTextures makeTreeTextures(const BarkTextureParams& bark = {}, int leafSize = 256);

}  // namespace ramus
