// Contact sheets: rendered previews tiled into one labelled image (include/ramus/render.hpp).
// Text comes from stb_easy_font, which describes each glyph as axis-aligned quads.
#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ramus/error.hpp"
#include "ramus/render.hpp"

namespace ramus {
namespace {

constexpr int kFontScale = 2;
constexpr int kGlyphHeight = 7;  // stb_easy_font's cap height in its own units
constexpr int kLabelHeight = (kGlyphHeight + 5) * kFontScale;
constexpr int kMaxSide = 16384;

void fill(Image& image, int x0, int y0, int x1, int y1, const std::array<std::uint8_t, 4>& c) {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y) {
        std::uint8_t* row = image.rgba.data() + (static_cast<std::size_t>(y) * image.width) * 4;
        for (int x = x0; x < x1; ++x) std::copy(c.begin(), c.end(), row + x * 4);
    }
}

void blit(Image& sheet, const Image& tile, int x0, int y0) {
    for (int y = 0; y < tile.height; ++y) {
        const auto* src = tile.rgba.data() + static_cast<std::size_t>(y) * tile.width * 4;
        auto* dst =
            sheet.rgba.data() +
            (static_cast<std::size_t>(y0 + y) * sheet.width + static_cast<std::size_t>(x0)) * 4;
        std::copy(src, src + static_cast<std::size_t>(tile.width) * 4, dst);
    }
}

/// The label as printable ASCII, cut so it fits `width` pixels.
std::string fitLabel(const std::string& label, int width) {
    std::string text;
    for (char ch : label) text += (ch >= 32 && ch < 127) ? ch : '?';
    while (!text.empty() && stb_easy_font_width(text.data()) * kFontScale > width) {
        text.pop_back();
    }
    return text;
}

/// Draws `text` with its top-left corner at (x, y), scaled kFontScale×.
void drawText(Image& image, const std::string& label, int x, int y, int width,
              const std::array<std::uint8_t, 4>& color) {
    std::string text = fitLabel(label, width);
    if (text.empty()) return;
    std::vector<float> quads(text.size() * 4 * 4 * 16);  // ample: ≤ ~70 quads per glyph
    const int count = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, quads.data(),
                                          static_cast<int>(quads.size() * sizeof(float)));
    // Each vertex is 16 bytes: x, y, z (floats) and a colour; quads are axis-aligned.
    for (int q = 0; q < count; ++q) {
        const float* v = quads.data() + static_cast<std::size_t>(q) * 16;
        const int qx0 = x + static_cast<int>(std::lround(v[0] * kFontScale));
        const int qy0 = y + static_cast<int>(std::lround(v[1] * kFontScale));
        const int qx1 = x + static_cast<int>(std::lround(v[8] * kFontScale));
        const int qy1 = y + static_cast<int>(std::lround(v[9] * kFontScale));
        fill(image, std::min(qx0, qx1), std::min(qy0, qy1), std::max(qx0, qx1), std::max(qy0, qy1),
             color);
    }
}

}  // namespace

Image composeContactSheet(const std::vector<SheetTile>& tiles, const SheetParams& params) {
    if (tiles.empty()) throw Error("contact sheet: expected at least one image, got none");
    if (params.gap < 0 || params.columns < 0) {
        throw Error("contact sheet: expected a gap and a column count >= 0");
    }
    int cellW = 1, cellH = 1;
    for (const SheetTile& t : tiles)
        cellW = std::max(cellW, t.image.width), cellH = std::max(cellH, t.image.height);
    const int n = static_cast<int>(tiles.size());
    int columns = params.columns;
    if (columns == 0) columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    columns = std::min(columns, n);
    const int rows = (n + columns - 1) / columns;
    const int labelH = params.labels ? kLabelHeight : 0;
    const long long width = static_cast<long long>(columns) * (cellW + params.gap) + params.gap;
    const long long height =
        static_cast<long long>(rows) * (cellH + labelH + params.gap) + params.gap;
    if (width > kMaxSide || height > kMaxSide) {
        throw Error("contact sheet: " + std::to_string(width) + "x" + std::to_string(height) +
                    " pixels; expected at most " + std::to_string(kMaxSide) +
                    " on a side (fewer or smaller tiles)");
    }
    Image sheet;
    sheet.width = static_cast<int>(width);
    sheet.height = static_cast<int>(height);
    sheet.rgba.resize(static_cast<std::size_t>(sheet.width) * sheet.height * 4);
    fill(sheet, 0, 0, sheet.width, sheet.height, params.background);
    for (int i = 0; i < n; ++i) {
        const Image& image = tiles[static_cast<std::size_t>(i)].image;
        const int cellX = params.gap + (i % columns) * (cellW + params.gap);
        const int cellY = params.gap + (i / columns) * (cellH + labelH + params.gap);
        blit(sheet, image, cellX + (cellW - image.width) / 2, cellY + (cellH - image.height) / 2);
        if (params.labels) {
            drawText(sheet, tiles[static_cast<std::size_t>(i)].label, cellX,
                     cellY + cellH + 3 * kFontScale, cellW, params.text);
        }
    }
    return sheet;
}

}  // namespace ramus
