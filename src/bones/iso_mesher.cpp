// Marching tetrahedra on a regular grid (include: src/bones/iso_mesher.hpp).
//
// Based on: seed 000 §5.6 (bone models as meshes); A. Doi and A. Koide, "An Efficient Method of
// Triangulating Equi-Valued Surfaces by Using Tetrahedral Cells", IEICE Trans. E74(1), 1991.
// Every cube is split into six tetrahedra around its main diagonal (Kuhn/Freudenthal), so
// neighbouring cubes share their face triangulations and the surface is watertight. Every
// tetrahedron edge joins a grid vertex to one whose offset is in {0,1}³ \ {0}, so crossing
// vertices are stored in 7 slots per grid vertex and shared without any hashing.
#include "bones/iso_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ramus {
namespace {

constexpr double kNudge = 1e-9;
constexpr double kMinEdgeFraction = 0.01;
constexpr std::uint32_t kNone = 0xffffffffu;

/// The six Kuhn tetrahedra of a cube as corner bit patterns (bit 0 = x, 1 = y, 2 = z).
constexpr std::array<std::array<int, 4>, 6> kTets = {
    {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

struct Grid {
    Vec3 origin;
    double cell = 1.0;
    int nx = 0, ny = 0, nz = 0;  // vertex counts
    std::vector<double> values;
    std::vector<std::uint32_t> edgeVertex;  // 7 slots per grid vertex

    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * ny + y) * nx + x;
    }
    Vec3 point(int x, int y, int z) const { return origin + Vec3(x, y, z) * cell; }
};

struct Builder {
    const DistanceFunction& distance;
    Grid& grid;
    Mesh mesh;

    Vec3 gradientNormal(const Vec3& p) const {
        const double h = grid.cell * 0.25;
        Vec3 g(distance(p + Vec3(h, 0, 0)) - distance(p - Vec3(h, 0, 0)),
               distance(p + Vec3(0, h, 0)) - distance(p - Vec3(0, h, 0)),
               distance(p + Vec3(0, 0, h)) - distance(p - Vec3(0, 0, h)));
        const double n = g.norm();
        return n > 0.0 ? Vec3(g / n) : Vec3::UnitY();
    }

    /// The vertex on the edge between grid corners (a) and (a + offset), created once.
    std::uint32_t edgeVertex(const std::array<int, 3>& a, int offset) {
        const std::size_t ia = grid.index(a[0], a[1], a[2]);
        std::uint32_t& slot = grid.edgeVertex[ia * 7 + (offset - 1)];
        if (slot != kNone) return slot;
        const int bx = a[0] + (offset & 1), by = a[1] + ((offset >> 1) & 1),
                  bz = a[2] + ((offset >> 2) & 1);
        const double va = grid.values[ia];
        const double vb = grid.values[grid.index(bx, by, bz)];
        const double t = std::clamp(va / (va - vb), kMinEdgeFraction, 1.0 - kMinEdgeFraction);
        const Vec3 p = grid.point(a[0], a[1], a[2]) * (1.0 - t) + grid.point(bx, by, bz) * t;
        slot = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(p.cast<float>());
        mesh.normals.push_back(gradientNormal(p).cast<float>());
        return slot;
    }

    /// Vertex on the tetrahedron edge between cube corners ca and cb (bit patterns).
    std::uint32_t tetEdge(int x, int y, int z, int ca, int cb) {
        if (ca > cb) std::swap(ca, cb);  // in a Kuhn tetrahedron the smaller pattern is a subset
        const std::array<int, 3> a = {x + (ca & 1), y + ((ca >> 1) & 1), z + ((ca >> 2) & 1)};
        return edgeVertex(a, cb ^ ca);
    }

    static Vec3 corner(int c) { return Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); }

    /// Emits triangle (a, b, c) whose edges' midpoints are ma, mb, mc, facing `outward`.
    void emit(std::uint32_t a, std::uint32_t b, std::uint32_t c, const Vec3& ma, const Vec3& mb,
              const Vec3& mc, const Vec3& outward) {
        if ((mb - ma).cross(mc - ma).dot(outward) < 0.0) std::swap(b, c);
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }

    void tetrahedron(int x, int y, int z, const std::array<int, 4>& tet,
                     const std::array<double, 8>& v) {
        std::array<int, 4> in{}, out{};
        int nIn = 0, nOut = 0;
        for (int c : tet) (v[c] < 0.0 ? in[nIn++] : out[nOut++]) = c;
        if (nIn == 0 || nOut == 0) return;
        Vec3 inC = Vec3::Zero(), outC = Vec3::Zero();
        for (int i = 0; i < nIn; ++i) inC += corner(in[i]) / nIn;
        for (int i = 0; i < nOut; ++i) outC += corner(out[i]) / nOut;
        const Vec3 outward = outC - inC;
        auto mid = [](int a, int b) -> Vec3 { return (corner(a) + corner(b)) * 0.5; };
        if (nIn == 1 || nOut == 1) {
            const int apex = nIn == 1 ? in[0] : out[0];
            const std::array<int, 3>& rest = nIn == 1 ? std::array<int, 3>{out[0], out[1], out[2]}
                                                      : std::array<int, 3>{in[0], in[1], in[2]};
            emit(tetEdge(x, y, z, apex, rest[0]), tetEdge(x, y, z, apex, rest[1]),
                 tetEdge(x, y, z, apex, rest[2]), mid(apex, rest[0]), mid(apex, rest[1]),
                 mid(apex, rest[2]), outward);
            return;
        }
        // Two inside, two outside: quad in0-out0, in0-out1, in1-out1, in1-out0 (a cycle).
        const std::uint32_t q0 = tetEdge(x, y, z, in[0], out[0]);
        const std::uint32_t q1 = tetEdge(x, y, z, in[0], out[1]);
        const std::uint32_t q2 = tetEdge(x, y, z, in[1], out[1]);
        const std::uint32_t q3 = tetEdge(x, y, z, in[1], out[0]);
        const Vec3 m0 = mid(in[0], out[0]), m1 = mid(in[0], out[1]);
        const Vec3 m2 = mid(in[1], out[1]), m3 = mid(in[1], out[0]);
        emit(q0, q1, q2, m0, m1, m2, outward);
        emit(q0, q2, q3, m0, m2, m3, outward);
    }
};

}  // namespace

Mesh meshIsosurface(const DistanceFunction& distance, const Vec3& lo, const Vec3& hi,
                    const std::array<int, 3>& cells) {
    Grid grid;
    const Vec3 size = hi - lo;
    grid.cell = std::max({size.x() / cells[0], size.y() / cells[1], size.z() / cells[2]});
    const Vec3 centre = (lo + hi) * 0.5;
    grid.nx = cells[0] + 3;
    grid.ny = cells[1] + 3;
    grid.nz = cells[2] + 3;
    grid.origin = centre - Vec3(grid.nx - 1, grid.ny - 1, grid.nz - 1) * (grid.cell * 0.5);
    grid.values.resize(static_cast<std::size_t>(grid.nx) * grid.ny * grid.nz);
    for (int z = 0; z < grid.nz; ++z) {
        for (int y = 0; y < grid.ny; ++y) {
            for (int x = 0; x < grid.nx; ++x) {
                const bool border = x == 0 || y == 0 || z == 0 || x == grid.nx - 1 ||
                                    y == grid.ny - 1 || z == grid.nz - 1;
                double v = border ? grid.cell : distance(grid.point(x, y, z));
                if (std::abs(v) < kNudge) v = kNudge;
                grid.values[grid.index(x, y, z)] = v;
            }
        }
    }
    grid.edgeVertex.assign(grid.values.size() * 7, kNone);
    Builder builder{distance, grid, Mesh{}};
    builder.mesh.name = "isosurface";
    std::array<double, 8> v{};
    for (int z = 0; z + 1 < grid.nz; ++z) {
        for (int y = 0; y + 1 < grid.ny; ++y) {
            for (int x = 0; x + 1 < grid.nx; ++x) {
                int nIn = 0;
                for (int c = 0; c < 8; ++c) {
                    v[c] = grid.values[grid.index(x + (c & 1), y + ((c >> 1) & 1),
                                                  z + ((c >> 2) & 1))];
                    nIn += v[c] < 0.0 ? 1 : 0;
                }
                if (nIn == 0 || nIn == 8) continue;
                for (const auto& tet : kTets) builder.tetrahedron(x, y, z, tet, v);
            }
        }
    }
    return std::move(builder.mesh);
}

Mesh meshIsosurfaceWithinBudget(const DistanceFunction& distance, const Vec3& lo, const Vec3& hi,
                                int maxTriangles, int maxCellsLongest) {
    // Grid sizes in quarter cells along the longest axis, so that the cell size can be tuned
    // finer than whole cells; the box grows to a whole number of cells of that size.
    constexpr int kSteps = 4;
    const Vec3 size = hi - lo;
    const double longest = size.maxCoeff();
    auto meshAt = [&](int quarters) {
        const double cell = longest * kSteps / quarters;
        std::array<int, 3> cells{};
        for (int a = 0; a < 3; ++a) {
            cells[a] = std::max(1, static_cast<int>(std::ceil(size[a] / cell - 1e-9)));
        }
        const Vec3 half = Vec3(cells[0], cells[1], cells[2]) * (cell * 0.5);
        const Vec3 centre = (lo + hi) * 0.5;
        return meshIsosurface(distance, centre - half, centre + half, cells);
    };
    auto fits = [&](const Mesh& mesh) {
        return static_cast<int>(mesh.triangleCount()) <= maxTriangles;
    };
    const int minQ = 2 * kSteps;
    const int maxQ = std::max(minQ, maxCellsLongest * kSteps);
    // Triangle counts grow about with n²: guess from a probe, then step down until it fits.
    int q = std::clamp(16 * kSteps, minQ, maxQ);
    const Mesh probe = meshAt(q);
    const double ratio = probe.triangleCount() > 0 ? static_cast<double>(maxTriangles) /
                                                         static_cast<double>(probe.triangleCount())
                                                   : 1.0;
    q = std::clamp(static_cast<int>(std::floor(q * std::sqrt(ratio))), minQ, maxQ);
    Mesh mesh = meshAt(q);
    while (q > minQ && !fits(mesh)) mesh = meshAt(--q);  // coarsen until it fits
    // Counts are not monotonic in the grid size: look a few sizes finer, keep the finest fit.
    constexpr int kLookAhead = 2 * kSteps;
    const int last = std::min(maxQ, q + kLookAhead);
    for (int m = q + 1; m <= last; ++m) {
        Mesh finer = meshAt(m);
        if (fits(finer)) mesh = std::move(finer);
    }
    return mesh;
}

}  // namespace ramus
