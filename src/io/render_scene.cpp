// Based on: Pineda, "A Parallel Algorithm for Polygon Rasterization" (SIGGRAPH 1988) — edge
// functions over a bounding box; fixed-point vertices and the top-left fill rule as in the
// Direct3D rasterization rules, so triangles sharing an edge never both or neither cover a
// sample; z-buffer; Gouraud-interpolated Lambert lighting; box-filtered 3×3 supersampling; the
// sRGB transfer function of IEC 61966-2-1.
#include <algorithm>
#include <cmath>
#include <limits>

#include "io/scene_check.hpp"
#include "ramus/error.hpp"
#include "ramus/render.hpp"

namespace ramus {

namespace {

constexpr int kSupersample = 3;                // samples per pixel along each axis
constexpr std::int64_t kSubpixel = 256;        // fixed-point steps per sample
constexpr double kMargin = 0.06;               // free border on each side, fraction of the size
constexpr std::size_t kBandSamples = 1 << 21;  // samples per band: bounds the buffers' memory
constexpr int kMaxSize = 16384;

// Orthonormal camera frame: screen right, screen up, and the viewing direction.
struct Camera {
    Vec3 right, up, forward;
};

Camera cameraFor(View view) {
    Vec3 forward = -Vec3::UnitZ(), up = Vec3::UnitY();
    switch (view) {
        case View::Side:
            forward = Vec3::UnitX();
            break;
        case View::Front:
            forward = -Vec3::UnitZ();
            break;
        case View::Top:
            forward = -Vec3::UnitY();
            up = -Vec3::UnitZ();
            break;
        case View::ThreeQuarter: {
            const double az = degToRad(45.0), el = degToRad(25.0);
            forward = -Vec3(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
            break;
        }
    }
    const Vec3 right = forward.cross(up).normalized();
    return Camera{right, right.cross(forward), forward};
}

// Lambert lighting with lights fixed to the camera (camera space: x right, y up, z toward the
// viewer): ambient, a key light from the upper left and a weaker fill from the lower right. The
// brightest possible sum stays below 1 so lit colours are not clipped.
float lightIntensity(const Vec3& n) {
    static constexpr double kAmbient = 0.2, kKey = 0.75, kFill = 0.2;
    static const Vec3 key = Vec3(-0.45, 0.65, 0.6).normalized();
    static const Vec3 fill = Vec3(0.7, -0.1, 0.7).normalized();
    const double lit =
        kAmbient + kKey * std::max(0.0, n.dot(key)) + kFill * std::max(0.0, n.dot(fill));
    return static_cast<float>(lit);
}

// A vertex after projection: fixed-point sample coordinates (y down), depth along the view,
// camera-space position (for flat normals) and the light intensity of its normal and of the
// flipped normal (for the back of double-sided faces).
struct ScreenVertex {
    std::int32_t x, y;
    float depth;
    Vec3f cam;
    float litFront, litBack;
    Vec2f uv;
};

struct Projected {
    std::vector<ScreenVertex> vertices;
    std::vector<std::size_t> firstVertex;  // per mesh instance
};

// Camera-space positions and intensities of every instance's vertices (sample coordinates are
// filled in later, once the framing is known).
Projected project(const Scene& scene, const std::vector<io::MeshInstance>& instances,
                  const Camera& cam) {
    Projected out;
    Mat3 toCamera;
    toCamera << cam.right.transpose(), cam.up.transpose(), (-cam.forward).transpose();
    for (const io::MeshInstance& inst : instances) {
        const Mesh& mesh = scene.meshes[inst.mesh];
        const Mat3 m = inst.world.topLeftCorner<3, 3>();
        const Vec3 t = inst.world.topRightCorner<3, 1>();
        Mat3 cofactor;  // transforms normals (inverse transpose up to a positive scale)
        cofactor << m.col(1).cross(m.col(2)), m.col(2).cross(m.col(0)), m.col(0).cross(m.col(1));
        if (m.determinant() < 0.0) cofactor = -cofactor;
        const Mat3 normalToCamera = toCamera * cofactor;
        out.firstVertex.push_back(out.vertices.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const Vec3 p = toCamera * (m * mesh.positions[i].cast<double>() + t);
            ScreenVertex v{
                0, 0, static_cast<float>(-p.z()), p.cast<float>(), 0.0f, 0.0f, Vec2f::Zero()};
            if (!mesh.uvs.empty()) v.uv = mesh.uvs[i];
            if (!mesh.normals.empty()) {
                Vec3 n = normalToCamera * mesh.normals[i].cast<double>();
                const double len = n.norm();
                n = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
                v.litFront = lightIntensity(n);
                v.litBack = lightIntensity(-n);
            }
            out.vertices.push_back(v);
        }
    }
    return out;
}

// Scales and centres the camera-space x/y bounds into the sample grid with a margin.
void frame(Projected& projected, int sampleWidth, int sampleHeight) {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d hi = -lo;
    for (const ScreenVertex& v : projected.vertices) {
        const Eigen::Vector2d p(v.cam.x(), v.cam.y());
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const Eigen::Vector2d extent = hi - lo, center = (hi + lo) * 0.5;
    const double usableW = sampleWidth * (1.0 - 2.0 * kMargin);
    const double usableH = sampleHeight * (1.0 - 2.0 * kMargin);
    double scale = std::min(extent.x() > 0.0 ? usableW / extent.x() : HUGE_VAL,
                            extent.y() > 0.0 ? usableH / extent.y() : HUGE_VAL);
    if (!std::isfinite(scale)) scale = 1.0;  // a single point
    for (ScreenVertex& v : projected.vertices) {
        const double sx = (v.cam.x() - center.x()) * scale + 0.5 * sampleWidth;
        const double sy = 0.5 * sampleHeight - (v.cam.y() - center.y()) * scale;
        v.x = static_cast<std::int32_t>(std::llround(sx * kSubpixel));
        v.y = static_cast<std::int32_t>(std::llround(sy * kSubpixel));
    }
}

// Depth and linear colour of the samples of a horizontal band of the image.
struct Band {
    int width = 0;     // samples
    int firstRow = 0;  // sample row of the band's top
    int rows = 0;      // sample rows
    std::vector<float> depth;
    std::vector<Vec3f> color;
};

// Which triangle owns a sample exactly on an edge: a rule antisymmetric in the edge direction,
// so of two triangles sharing an edge exactly one covers it.
bool ownsEdge(std::int64_t dx, std::int64_t dy) { return dy > 0 || (dy == 0 && dx < 0); }

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

struct Corner {
    std::int64_t x, y;
    float depth, lit;
    Vec2f uv;
};

// A primitive's surface: base colour, and optionally its texture (sampled nearest, REPEAT;
// the camera is orthographic, so screen-space interpolation of uvs is exact) and alpha mask.
struct Surface {
    Vec3f color;
    const Image* texture = nullptr;
    bool mask = false;
    float cutoff = 0.5f;
    float alpha = 1.0f;               // the base colour's alpha
    const float* toLinear = nullptr;  // 256 entries: sRGB byte → linear
    bool textured() const { return texture != nullptr; }
};

// Colour of a textured sample, or false when the alpha mask discards it.
bool sampleTexture(const Surface& surface, const Vec2f& uv, Vec3f& color) {
    const Image& t = *surface.texture;
    const float u = uv.x() - std::floor(uv.x()), v = uv.y() - std::floor(uv.y());
    const int x = std::min(t.width - 1, static_cast<int>(u * static_cast<float>(t.width)));
    const int y = std::min(t.height - 1, static_cast<int>(v * static_cast<float>(t.height)));
    const std::uint8_t* px = t.rgba.data() + (static_cast<std::size_t>(y) * t.width + x) * 4;
    if (surface.mask && surface.alpha * (px[3] / 255.0f) < surface.cutoff) return false;
    color = surface.color.cwiseProduct(
        Vec3f(surface.toLinear[px[0]], surface.toLinear[px[1]], surface.toLinear[px[2]]));
    return true;
}

// Rasterizes one triangle with positive orientation (a, b, c) into the band.
void fillTriangle(Band& band, const Corner& a, const Corner& b, const Corner& c, std::int64_t area,
                  const Surface& surface) {
    const std::int64_t half = kSubpixel / 2;
    // Sample i has its centre at i·kSubpixel + half: the first at or after lo, the last at or
    // before hi.
    auto firstSample = [&](std::int64_t lo) {
        return static_cast<int>(-floorDiv(-(lo - half), kSubpixel));
    };
    auto lastSample = [&](std::int64_t hi) {
        return static_cast<int>(floorDiv(hi - half, kSubpixel));
    };
    const int x0 = std::max(0, firstSample(std::min({a.x, b.x, c.x})));
    const int x1 = std::min(band.width - 1, lastSample(std::max({a.x, b.x, c.x})));
    const int y0 = std::max(band.firstRow, firstSample(std::min({a.y, b.y, c.y})));
    const int y1 = std::min(band.firstRow + band.rows - 1, lastSample(std::max({a.y, b.y, c.y})));
    if (x0 > x1 || y0 > y1) return;

    // Edge function of edge p→q at sample (x, y), minus 1 when the edge does not own the
    // samples on it (integers, so the test is exact).
    auto edgeAt = [&](const Corner& p, const Corner& q, std::int64_t sx, std::int64_t sy) {
        const std::int64_t dx = q.x - p.x, dy = q.y - p.y;
        return dx * (sy - p.y) - dy * (sx - p.x) - (ownsEdge(dx, dy) ? 0 : 1);
    };
    const std::int64_t sx0 = x0 * kSubpixel + half, sy0 = y0 * kSubpixel + half;
    std::int64_t row0 = edgeAt(b, c, sx0, sy0), row1 = edgeAt(c, a, sx0, sy0),
                 row2 = edgeAt(a, b, sx0, sy0);
    const std::int64_t stepX0 = -(c.y - b.y) * kSubpixel, stepY0 = (c.x - b.x) * kSubpixel;
    const std::int64_t stepX1 = -(a.y - c.y) * kSubpixel, stepY1 = (a.x - c.x) * kSubpixel;
    const std::int64_t stepX2 = -(b.y - a.y) * kSubpixel, stepY2 = (b.x - a.x) * kSubpixel;
    const float inv = 1.0f / static_cast<float>(area);
    for (int y = y0; y <= y1; ++y) {
        std::int64_t w0 = row0, w1 = row1, w2 = row2;
        const std::size_t rowStart = static_cast<std::size_t>(y - band.firstRow) * band.width;
        for (int x = x0; x <= x1; ++x) {
            if ((w0 | w1 | w2) >= 0) {
                const float l0 = static_cast<float>(w0) * inv, l1 = static_cast<float>(w1) * inv;
                const float l2 = 1.0f - l0 - l1;
                const float z = l0 * a.depth + l1 * b.depth + l2 * c.depth;
                const std::size_t s = rowStart + x;
                Vec3f color = surface.color;
                if (z < band.depth[s] &&
                    (!surface.textured() ||
                     sampleTexture(surface, l0 * a.uv + l1 * b.uv + l2 * c.uv, color))) {
                    band.depth[s] = z;
                    band.color[s] = color * (l0 * a.lit + l1 * b.lit + l2 * c.lit);
                }
            }
            w0 += stepX0;
            w1 += stepX1;
            w2 += stepX2;
        }
        row0 += stepY0;
        row1 += stepY1;
        row2 += stepY2;
    }
}

// Culls back faces of single-sided materials, picks the lighting of the side facing the camera
// (interpolated vertex normals, or the face normal for meshes without normals) and orients the
// triangle for fillTriangle.
void drawTriangle(Band& band, const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                  bool smooth, bool mirrored, bool doubleSided, const Surface& surface) {
    const std::int64_t top = std::int64_t{band.firstRow} * kSubpixel;
    const std::int64_t bottom = std::int64_t{band.firstRow + band.rows} * kSubpixel;
    if (std::max({a.y, b.y, c.y}) < top || std::min({a.y, b.y, c.y}) > bottom) return;
    std::int64_t area =
        std::int64_t{b.x - a.x} * (c.y - a.y) - std::int64_t{b.y - a.y} * (c.x - a.x);
    if (area == 0) return;
    // Screen y points down, so a counter-clockwise (front) face has negative screen area.
    const bool front = (area < 0) != mirrored;
    if (!front && !doubleSided) return;
    Corner ca{a.x, a.y, a.depth, 0.0f, a.uv}, cb{b.x, b.y, b.depth, 0.0f, b.uv},
        cc{c.x, c.y, c.depth, 0.0f, c.uv};
    if (smooth) {
        ca.lit = front ? a.litFront : a.litBack;
        cb.lit = front ? b.litFront : b.litBack;
        cc.lit = front ? c.litFront : c.litBack;
    } else {
        Vec3 n = (b.cam - a.cam).cross(c.cam - a.cam).cast<double>();
        const double len = n.norm();
        n = len > 0.0 ? Vec3(n / len) : Vec3(Vec3::UnitZ());
        if (n.z() < 0.0) n = -n;  // the side facing the camera
        ca.lit = cb.lit = cc.lit = lightIntensity(n);
    }
    if (area < 0) {
        std::swap(cb, cc);
        area = -area;
    }
    fillTriangle(band, ca, cb, cc, area, surface);
}

struct DrawList {
    const Scene& scene;
    const std::vector<io::MeshInstance>& instances;
    const Projected& projected;
    const float* toLinear;  // sRGB byte → linear, 256 entries
};

void drawBand(Band& band, const DrawList& list) {
    std::fill(band.depth.begin(), band.depth.end(), std::numeric_limits<float>::infinity());
    std::fill(band.color.begin(), band.color.end(), Vec3f::Zero());
    for (std::size_t k = 0; k < list.instances.size(); ++k) {
        const io::MeshInstance& inst = list.instances[k];
        const Mesh& mesh = list.scene.meshes[inst.mesh];
        const ScreenVertex* v = list.projected.vertices.data() + list.projected.firstVertex[k];
        const bool mirrored = inst.world.topLeftCorner<3, 3>().determinant() < 0.0;
        const bool smooth = !mesh.normals.empty();
        for (const MeshPrimitive& prim : io::drawnPrimitives(mesh)) {
            const Material& material = io::primitiveMaterial(mesh, prim);
            Surface surface{material.baseColor.head<3>()};
            if (!mesh.uvs.empty()) surface.texture = material.baseColorTexture.get();
            surface.mask = material.alphaMask;
            surface.cutoff = material.alphaCutoff;
            surface.alpha = material.baseColor.w();
            surface.toLinear = list.toLinear;
            const std::uint32_t* idx = mesh.indices.data() + prim.firstIndex;
            for (std::uint32_t t = 0; t < prim.indexCount; t += 3) {
                drawTriangle(band, v[idx[t]], v[idx[t + 1]], v[idx[t + 2]], smooth, mirrored,
                             material.doubleSided, surface);
            }
        }
    }
}

// Linear [0, 1] → 8-bit sRGB, tabulated at 4096 steps.
std::vector<std::uint8_t> srgbTable() {
    std::vector<std::uint8_t> table(4096);
    for (std::size_t i = 0; i < table.size(); ++i) {
        const double v = static_cast<double>(i) / static_cast<double>(table.size() - 1);
        const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
        table[i] = static_cast<std::uint8_t>(std::lround(s * 255.0));
    }
    return table;
}

// 8-bit sRGB → linear [0, 1] (IEC 61966-2-1), for texture samples.
std::vector<float> linearTable() {
    std::vector<float> table(256);
    for (std::size_t i = 0; i < table.size(); ++i) {
        const double s = static_cast<double>(i) / 255.0;
        table[i] =
            static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
    }
    return table;
}

// Averages each pixel's samples (alpha-weighted, in linear light) into the image.
void resolveBand(const Band& band, const Vec4f& background, const std::vector<std::uint8_t>& lut,
                 Image& image) {
    const int s = kSupersample;
    const float n = static_cast<float>(s * s);
    auto encode = [&](float v) {
        return lut[static_cast<std::size_t>(std::clamp(v, 0.0f, 1.0f) * 4095.0f + 0.5f)];
    };
    for (int py = band.firstRow / s; py < (band.firstRow + band.rows) / s; ++py) {
        for (int px = 0; px < image.width; ++px) {
            Vec3f rgb = Vec3f::Zero();
            float alpha = 0.0f;
            for (int sy = 0; sy < s; ++sy) {
                const std::size_t row =
                    static_cast<std::size_t>(py * s + sy - band.firstRow) * band.width;
                for (int sx = 0; sx < s; ++sx) {
                    const std::size_t i = row + static_cast<std::size_t>(px * s + sx);
                    const bool covered = band.depth[i] < std::numeric_limits<float>::infinity();
                    const float a = covered ? 1.0f : background.w();
                    rgb += (covered ? Vec3f(band.color[i].cwiseMin(1.0f))
                                    : Vec3f(background.head<3>())) *
                           a;
                    alpha += a;
                }
            }
            if (alpha > 0.0f) rgb /= alpha;
            std::uint8_t* out =
                image.rgba.data() + (static_cast<std::size_t>(py) * image.width + px) * 4;
            out[0] = encode(rgb.x());
            out[1] = encode(rgb.y());
            out[2] = encode(rgb.z());
            out[3] =
                static_cast<std::uint8_t>(std::lround(std::clamp(alpha / n, 0.0f, 1.0f) * 255.0f));
        }
    }
}

}  // namespace

Image renderScene(const Scene& scene, const RenderParams& params) {
    if (params.width < 1 || params.width > kMaxSize || params.height < 1 ||
        params.height > kMaxSize) {
        throw Error("render size " + std::to_string(params.width) + "x" +
                    std::to_string(params.height) + " is out of range; expected 1..16384 pixels");
    }
    io::checkScene(scene, "scene");
    Image image{
        params.width, params.height,
        std::vector<std::uint8_t>(static_cast<std::size_t>(params.width) * params.height * 4)};
    const std::vector<io::MeshInstance> instances = io::meshInstances(scene);
    Projected projected = project(scene, instances, cameraFor(params.view));
    const int sampleWidth = params.width * kSupersample;
    frame(projected, sampleWidth, params.height * kSupersample);

    // Draw in horizontal bands so memory stays bounded for large images.
    const int bandPixels = std::clamp(
        static_cast<int>(kBandSamples / (static_cast<std::size_t>(sampleWidth) * kSupersample)), 1,
        params.height);
    Band band;
    band.width = sampleWidth;
    band.depth.resize(static_cast<std::size_t>(sampleWidth) * bandPixels * kSupersample);
    band.color.resize(band.depth.size());
    const std::vector<float> toLinear = linearTable();
    const DrawList list{scene, instances, projected, toLinear.data()};
    const std::vector<std::uint8_t> lut = srgbTable();
    for (int py = 0; py < params.height; py += bandPixels) {
        band.firstRow = py * kSupersample;
        band.rows = std::min(bandPixels, params.height - py) * kSupersample;
        drawBand(band, list);
        resolveBand(band, params.background, lut, image);
    }
    return image;
}

}  // namespace ramus
