// PNG encoding (stb_image_write) and the small parsers of the preview renderer's options.
#include <charconv>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/render.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>

namespace ramus {

namespace {

void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
}

// A whole decimal number in [lo, hi], or -1.
int parseDimension(std::string_view text, int lo, int hi) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc{} || end != text.data() + text.size()) return -1;
    return value >= lo && value <= hi ? value : -1;
}

}  // namespace

View parseView(const std::string& name) {
    if (name == "side") return View::Side;
    if (name == "front") return View::Front;
    if (name == "top") return View::Top;
    if (name == "three-quarter" || name == "threequarter" || name == "3q") {
        return View::ThreeQuarter;
    }
    throw Error("unknown view '" + name + "'; expected one of side, front, top, three-quarter");
}

ImageSize parseImageSize(const std::string& text) {
    constexpr int kMin = 16, kMax = 8192;
    const std::size_t x = text.find_first_of("xX");
    if (x != std::string::npos) {
        const std::string_view all(text);
        const int w = parseDimension(all.substr(0, x), kMin, kMax);
        const int h = parseDimension(all.substr(x + 1), kMin, kMax);
        if (w > 0 && h > 0) return ImageSize{w, h};
    }
    throw Error("invalid image size '" + text + "'; expected WIDTHxHEIGHT with each between " +
                std::to_string(kMin) + " and " + std::to_string(kMax) + ", e.g. 800x600");
}

std::string encodePng(const Image& image) {
    const std::size_t expected = static_cast<std::size_t>(std::max(image.width, 0)) *
                                 static_cast<std::size_t>(std::max(image.height, 0)) * 4;
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != expected) {
        throw Error("cannot encode a PNG of " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " pixels from " +
                    std::to_string(image.rgba.size()) + " bytes; expected a non-empty image " +
                    "with 4 bytes (RGBA) per pixel");
    }
    std::string png;
    const int ok = stbi_write_png_to_func(appendBytes, &png, image.width, image.height, 4,
                                          image.rgba.data(), image.width * 4);
    if (!ok) throw Error("PNG encoding failed");
    return png;
}

void writePng(const Image& image, const std::string& path) {
    writeFileAtomic(path, encodePng(image));
}

}  // namespace ramus
