// Procedural tree textures. Tileable value noise (Perlin, "An Image Synthesizer", SIGGRAPH
// 1985; lattice values from a hash, smoothstep interpolation) with integer periods per octave
// so every octave wraps exactly at the image border; ridged noise (Musgrave, "Texturing and
// Modeling: A Procedural Approach" ch. 16) makes the bark's furrows. Normal map by central
// differences of the same (wrapping) height field. All integer hashing and double arithmetic:
// the same bytes on every run.
#include "ramus/tree_textures.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ramus/error.hpp"
#include "ramus/leaves.hpp"
#include "ramus/rng.hpp"

namespace ramus {

namespace {

bool powerOfTwoInRange(int v) { return v >= 16 && v <= 4096 && (v & (v - 1)) == 0; }

// Value noise on a lattice of periodX × periodY cells over the unit square, wrapping.
double periodicNoise(double x, double y, int periodX, int periodY, std::uint64_t seed) {
    const double fx = x * periodX, fy = y * periodY;
    const double ix = std::floor(fx), iy = std::floor(fy);
    const double tx = fx - ix, ty = fy - iy;
    auto lattice = [&](double cx, double cy) {
        const auto gx = static_cast<std::uint64_t>(
            ((static_cast<long long>(cx) % periodX) + periodX) % periodX);
        const auto gy = static_cast<std::uint64_t>(
            ((static_cast<long long>(cy) % periodY) + periodY) % periodY);
        const std::uint64_t h = hashCombine(hashCombine(seed, gx), gy);
        return static_cast<double>(h >> 11) * 0x1.0p-53;
    };
    const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
    const double a = lattice(ix, iy), b = lattice(ix + 1, iy);
    const double c = lattice(ix, iy + 1), d = lattice(ix + 1, iy + 1);
    return (a + (b - a) * sx) * (1.0 - sy) + (c + (d - c) * sx) * sy;
}

std::uint8_t toByte(double v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

}  // namespace

void validateBarkTextureParams(const BarkTextureParams& p) {
    if (!powerOfTwoInRange(p.width) || !powerOfTwoInRange(p.height)) {
        throw Error("bark texture size " + std::to_string(p.width) + "x" +
                    std::to_string(p.height) + "; expected powers of two from 16 to 4096");
    }
    if (p.furrows < 1) {
        throw Error("bark texture furrows is " + std::to_string(p.furrows) + "; expected >= 1");
    }
}

std::vector<float> barkHeightField(const BarkTextureParams& p) {
    validateBarkTextureParams(p);
    const int w = p.width, h = p.height;
    const int f = p.furrows;
    // Texels are square on the tree (uvAspect = h / w), so v spans `aspect` times the world
    // length u spans: periods along v scale by it to keep features proportioned.
    const int aspect = std::max(1, h / w);
    std::vector<float> field(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        const double v = (y + 0.5) / h;
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) / w;
            // Sideways warp so furrows wander, then ridged noise across, stretched along v.
            const double warp = periodicNoise(u, v, 3, 2 * aspect, p.seed + 1) - 0.5;
            const double across = u + 0.35 * warp / f;
            const double ridge =
                1.0 - std::abs(2.0 * periodicNoise(across, v, f, aspect, p.seed + 2) - 1.0);
            const double breaks = periodicNoise(u, v, 2 * f, 6 * aspect, p.seed + 3);
            const double grain = periodicNoise(u, v, 32, 32 * aspect, p.seed + 4);
            const double height = 0.6 * std::pow(ridge, 1.5) + 0.25 * breaks * ridge + 0.15 * grain;
            field[static_cast<std::size_t>(y) * w + x] =
                static_cast<float>(std::clamp(height, 0.0, 1.0));
        }
    }
    return field;
}

Image makeBarkTexture(const BarkTextureParams& p) {
    const std::vector<float> field = barkHeightField(p);
    Image image{p.width, p.height, std::vector<std::uint8_t>(field.size() * 4)};
    // sRGB colours of furrow and ridge; a second noise tints the ridges greyer or browner.
    const double dark[3] = {0.16, 0.11, 0.08}, light[3] = {0.55, 0.47, 0.39};
    for (std::size_t i = 0; i < field.size(); ++i) {
        const double t = std::pow(field[i], 0.8);
        const int x = static_cast<int>(i % p.width), y = static_cast<int>(i / p.width);
        const double tint =
            periodicNoise((x + 0.5) / p.width, (y + 0.5) / p.height, 4, 8, p.seed + 5) - 0.5;
        for (int c = 0; c < 3; ++c) {
            const double shade =
                dark[c] + (light[c] - dark[c]) * t + 0.08 * tint * (c == 2 ? -1 : 1);
            image.rgba[4 * i + c] = toByte(shade);
        }
        image.rgba[4 * i + 3] = 255;
    }
    return image;
}

Image makeBarkNormalMap(const BarkTextureParams& p) {
    const std::vector<float> field = barkHeightField(p);
    const int w = p.width, h = p.height;
    Image image{w, h, std::vector<std::uint8_t>(field.size() * 4)};
    const double strength = 3.0;  // height units per texel across the image: relief depth
    auto at = [&](int x, int y) {
        return static_cast<double>(field[static_cast<std::size_t>((y + h) % h) * w + (x + w) % w]);
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // +X = increasing u (x), +Y = image up (decreasing row index).
            const double dx = (at(x + 1, y) - at(x - 1, y)) * 0.5 * strength;
            const double dy = (at(x, y - 1) - at(x, y + 1)) * 0.5 * strength;
            const Vec3 n = Vec3(-dx, -dy, 1.0).normalized();
            std::uint8_t* out = image.rgba.data() + (static_cast<std::size_t>(y) * w + x) * 4;
            out[0] = toByte(0.5 * (n.x() + 1.0));
            out[1] = toByte(0.5 * (n.y() + 1.0));
            out[2] = toByte(0.5 * (n.z() + 1.0));
            out[3] = 255;
        }
    }
    return image;
}

Image makeLeafTexture(int size) {
    if (!powerOfTwoInRange(size)) {
        throw Error("leaf texture size " + std::to_string(size) +
                    "; expected a power of two from 16 to 4096");
    }
    Image image{size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size * 4)};
    const double base[3] = {0.22, 0.42, 0.12}, tip[3] = {0.36, 0.56, 0.18};
    for (int py = 0; py < size; ++py) {
        const double y = 1.0 - (py + 0.5) / size;  // 0 at the base (bottom), 1 at the tip
        const double half = leafOutlineHalfWidth(y);
        for (int px = 0; px < size; ++px) {
            const double x = (px + 0.5) / size - 0.5;
            const double across = half > 0.0 ? std::abs(x) / half : 2.0;
            // Midrib, and veins running out and up from it at about 40°.
            const double rib = std::max(0.0, 1.0 - std::abs(x) * size / 2.5);
            const double vein =
                std::pow(std::abs(std::cos(kPi * 9.0 * (y - 0.8 * std::abs(x)))), 12.0) *
                (1.0 - across);
            const double light = std::clamp(0.55 * rib + 0.25 * vein, 0.0, 1.0);
            std::uint8_t* out = image.rgba.data() + (static_cast<std::size_t>(py) * size + px) * 4;
            for (int c = 0; c < 3; ++c) {
                const double green = base[c] + (tip[c] - base[c]) * y - 0.06 * across;
                out[c] = toByte(green + (0.75 - green) * 0.45 * light);
            }
            out[3] = across < 1.0 ? 255 : 0;
        }
    }
    return image;
}

TreeTextures makeTreeTextures(const BarkTextureParams& bark, int leafSize) {
    TreeTextures t;
    t.barkColor = std::make_shared<const Image>(makeBarkTexture(bark));
    t.barkNormal = std::make_shared<const Image>(makeBarkNormalMap(bark));
    t.leafColor = std::make_shared<const Image>(makeLeafTexture(leafSize));
    t.barkAspect = static_cast<double>(bark.height) / bark.width;
    return t;
}

}  // namespace ramus
