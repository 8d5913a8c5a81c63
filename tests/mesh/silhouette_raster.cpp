#include "silhouette_raster.hpp"

#include <algorithm>
#include <cmath>

namespace ramus::test {

Camera fitCamera(const Aabb& box, int axis, int resolution, double margin) {
    static constexpr int kImageAxes[3][2] = {{2, 1}, {0, 2}, {0, 1}};
    Camera camera;
    camera.axisU = kImageAxes[axis][0];
    camera.axisV = kImageAxes[axis][1];
    const double extentU = box.extent()[camera.axisU], extentV = box.extent()[camera.axisV];
    const double frame = margin * std::max({extentU, extentV, 1e-9});
    camera.pixel = (std::max(extentU, extentV) + 2.0 * frame) / resolution;
    camera.width = static_cast<int>(std::ceil((extentU + 2.0 * frame) / camera.pixel));
    camera.height = static_cast<int>(std::ceil((extentV + 2.0 * frame) / camera.pixel));
    camera.u0 = box.min[camera.axisU] - frame;
    camera.v0 = box.max[camera.axisV] + frame;
    return camera;
}

bool insideFrame(const Camera& camera, const Aabb& box) {
    const Vec2 lo = camera.project(box.min), hi = camera.project(box.max);
    return std::min(lo.x(), hi.x()) >= 0.0 && std::max(lo.x(), hi.x()) <= camera.width &&
           std::min(lo.y(), hi.y()) >= 0.0 && std::max(lo.y(), hi.y()) <= camera.height;
}

std::size_t Mask::area() const {
    std::size_t count = 0;
    for (const std::uint8_t* p = covered.data(); p != covered.data() + covered.size(); ++p) {
        count += *p;
    }
    return count;
}

namespace {

// The hot loops below use plain doubles, arrays and pointers: the sanitizer build compiles
// tests at -O0, where Eigen's and the standard library's small functions are not inlined
// (they took two thirds of this test's time there).

// A triangle's edge functions in pixel coordinates, double precision: e_k(x, y) = nx_k x +
// ny_k y + c_k, ≥ 0 on the inner side of edge k. The inner side is taken from the sign of the
// triangle's area, so either winding counts (a closed surface shows front and back faces).
// Over a pixel's square (half side 1/2) e_k is largest at a corner, by reach_k = (|nx_k| +
// |ny_k|) / 2 above its value at the centre.
struct EdgeFunctions {
    double nx[3], ny[3], c[3], reach[3];
    double xMin, xMax, yMin, yMax;  // the triangle's bounds
};

// From the corners (x[k], y[k]); false for a triangle without area.
bool edgeFunctions(const double x[3], const double y[3], EdgeFunctions& f) {
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (area == 0.0) return false;
    const double sign = area > 0.0 ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k) {
        const int next = (k + 1) % 3;
        f.nx[k] = -sign * (y[next] - y[k]);
        f.ny[k] = sign * (x[next] - x[k]);
        f.c[k] = -(f.nx[k] * x[k] + f.ny[k] * y[k]);
        f.reach[k] = 0.5 * (std::fabs(f.nx[k]) + std::fabs(f.ny[k]));
    }
    f.xMin = x[0] < x[1] ? (x[0] < x[2] ? x[0] : x[2]) : (x[1] < x[2] ? x[1] : x[2]);
    f.xMax = x[0] > x[1] ? (x[0] > x[2] ? x[0] : x[2]) : (x[1] > x[2] ? x[1] : x[2]);
    f.yMin = y[0] < y[1] ? (y[0] < y[2] ? y[0] : y[2]) : (y[1] < y[2] ? y[1] : y[2]);
    f.yMax = y[0] > y[1] ? (y[0] > y[2] ? y[0] : y[2]) : (y[1] > y[2] ? y[1] : y[2]);
    return true;
}

// The columns of row `y` where a pixel's square can touch the triangle (a long thin triangle
// has a large bounding box but a short span per row), widened by 1e-6 pixel against rounding;
// `row` receives e_k − nx_k x, the part of each edge function that is constant along the row.
void rowSpan(const EdgeFunctions& f, int y, int x0, int x1, double row[3], int& first, int& last) {
    constexpr double kSlack = 1e-6;
    double left = x0, right = x1;
    for (int k = 0; k < 3; ++k) {
        row[k] = f.ny[k] * (y + 0.5) + f.c[k];
        const double top = row[k] + f.reach[k];  // e_k + reach_k = nx_k (x + 1/2) + top
        if (f.nx[k] > 0.0) left = std::fmax(left, std::ceil(-top / f.nx[k] - 0.5 - kSlack));
        if (f.nx[k] < 0.0) right = std::fmin(right, std::floor(-top / f.nx[k] - 0.5 + kSlack));
        if (f.nx[k] == 0.0 && top < 0.0) right = left - 1.0;
    }
    first = static_cast<int>(std::fmin(left, x1 + 1.0));
    last = static_cast<int>(std::fmax(right, x0 - 1.0));
}

// Marks the pixels whose centre the triangle covers (e_k ≥ 0 at the centre for all k) and
// those whose square it touches (e_k ≥ −reach_k for all k, within its bounds: the separating
// axis test of a square and a triangle).
void fillTriangle(const EdgeFunctions& f, Silhouette& silhouette) {
    const int width = silhouette.centres.width, height = silhouette.centres.height;
    std::uint8_t* centres = silhouette.centres.covered.data();
    std::uint8_t* touched = silhouette.touched.covered.data();
    const int x0 = std::max(0, static_cast<int>(std::floor(f.xMin)));
    const int x1 = std::min(width - 1, static_cast<int>(std::floor(f.xMax)));
    const int y0 = std::max(0, static_cast<int>(std::floor(f.yMin)));
    const int y1 = std::min(height - 1, static_cast<int>(std::floor(f.yMax)));
    for (int y = y0; y <= y1; ++y) {
        double row[3];
        int first = 0, last = -1;
        rowSpan(f, y, x0, x1, row, first, last);
        for (int x = first; x <= last; ++x) {
            const double px = x + 0.5;
            const double e0 = f.nx[0] * px + row[0], e1 = f.nx[1] * px + row[1],
                         e2 = f.nx[2] * px + row[2];
            const std::size_t i = std::size_t(y) * width + x;
            if (e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0) centres[i] = 1;
            if (e0 >= -f.reach[0] && e1 >= -f.reach[1] && e2 >= -f.reach[2]) touched[i] = 1;
        }
    }
}

constexpr double kFar = 1e20;  // f of pixels without a feature (finite: the envelope divides)

// Felzenszwalb & Huttenlocher 2012, "Distance transforms of sampled functions": the lower
// envelope of the parabolas (q − i)² + f(i), i = 0 … n−1, at every q; `nearest` gets its i.
// `vertex` (n) and `boundary` (n + 1) are scratch space.
void distanceTransform1d(const double* f, int n, double* d, int* nearest, int* vertex,
                         double* boundary) {
    int k = 0;
    vertex[0] = 0;
    boundary[0] = -kFar * kFar;
    boundary[1] = kFar * kFar;
    for (int q = 1; q < n; ++q) {
        double s = 0.0;
        while (true) {
            const int v = vertex[k];
            s = ((f[q] + double(q) * q) - (f[v] + double(v) * v)) / (2.0 * (q - v));
            if (s > boundary[k]) break;
            --k;  // parabola v is below the new one nowhere: drop it
        }
        vertex[++k] = q;
        boundary[k] = s;
        boundary[k + 1] = kFar * kFar;
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (boundary[k + 1] < q) ++k;
        d[q] = double(q - vertex[k]) * (q - vertex[k]) + f[vertex[k]];
        nearest[q] = vertex[k];
    }
}

}  // namespace

Silhouette rasterize(const Mesh& mesh, const Camera& camera) {
    const Mask empty{camera.width, camera.height,
                     std::vector<std::uint8_t>(std::size_t(camera.width) * camera.height, 0)};
    Silhouette silhouette{empty, empty};
    std::vector<double> xs(mesh.positions.size()), ys(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const float* p = mesh.positions[v].data();
        xs[v] = (p[camera.axisU] - camera.u0) / camera.pixel;
        ys[v] = (camera.v0 - p[camera.axisV]) / camera.pixel;
    }
    const std::uint32_t* index = mesh.indices.data();
    EdgeFunctions f;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t, index += 3) {
        const double x[3] = {xs[index[0]], xs[index[1]], xs[index[2]]};
        const double y[3] = {ys[index[0]], ys[index[1]], ys[index[2]]};
        if (edgeFunctions(x, y, f)) fillTriangle(f, silhouette);
    }
    return silhouette;
}

// Exact Euclidean distance transform: the 1-d transform down every column, then along every
// row of the column results (both linear in the pixel count).
DistanceField distanceTo(const Mask& mask) {
    const int w = mask.width, h = mask.height, n = std::max(w, h);
    std::vector<double> columnSquared(std::size_t(w) * h), f(n), d(n), boundary(n + 1);
    std::vector<int> columnNearest(std::size_t(w) * h), nearest(n), vertex(n);
    const std::uint8_t* covered = mask.covered.data();
    for (int x = 0; x < w; ++x) {
        for (int y = 0; y < h; ++y) f[y] = covered[std::size_t(y) * w + x] ? 0.0 : kFar;
        distanceTransform1d(f.data(), h, d.data(), nearest.data(), vertex.data(), boundary.data());
        for (int y = 0; y < h; ++y) {
            columnSquared[std::size_t(y) * w + x] = d[y];
            columnNearest[std::size_t(y) * w + x] = nearest[y];
        }
    }
    DistanceField field{std::vector<double>(std::size_t(w) * h),
                        std::vector<int>(std::size_t(w) * h)};
    for (int y = 0; y < h; ++y) {
        const std::size_t row = std::size_t(y) * w;
        distanceTransform1d(columnSquared.data() + row, w, field.squared.data() + row,
                            nearest.data(), vertex.data(), boundary.data());
        for (int x = 0; x < w; ++x) {
            field.nearest[row + x] = columnNearest[row + nearest[x]] * w + nearest[x];
        }
    }
    return field;
}

}  // namespace ramus::test
