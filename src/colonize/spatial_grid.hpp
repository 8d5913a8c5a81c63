// Based on: uniform grid hashing for fixed-radius neighbour search (e.g. Green, "Particle
// Simulation using CUDA", 2010, counting-sort cell order). The attraction points are static, so
// they are sorted once into cell order (a cell's points are contiguous, a row of cells is one
// range); nodes are added over time into per-cell linked lists.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "ramus/math.hpp"

namespace ramus::colonize_detail {

/// A box of cubic cells over the attraction points, with a margin of cells around it wide
/// enough to hold every node that can be within the influence radius of a point.
class SpatialGrid {
public:
    SpatialGrid() = default;

    /// Builds the grid over the points (xs[i], ys[i], zs[i]) (any count; none gives a 1-cell
    /// grid) with cells of about influenceRadius / subdivision, coarser if that would need more
    /// than ~maxCells cells. `order` receives the point indices in cell order (stable);
    /// cellBegin()/cellEnd() give each cell's range in that order.
    SpatialGrid(std::span<const float> xs, std::span<const float> ys, std::span<const float> zs,
                double influenceRadius, int subdivision, std::size_t maxCells,
                std::vector<std::uint32_t>& order);

    std::size_t cellCount() const { return cellStart_.empty() ? 0 : cellStart_.size() - 1; }
    double cellSize() const { return cellSize_; }

    /// Cell of p, or -1 when p lies outside the grid.
    std::int64_t cellOf(const Vec3& p) const;

    /// Calls visit(first, last) for ranges [first, last) of cell-ordered points that cover
    /// every point within `radius` of `center` (and some farther ones).
    template <typename Visit>
    void forEachPointRange(const Vec3& center, double radius, Visit&& visit) const {
        forEachRow(center, radius, [&](std::size_t rowCell, int x0, int x1, double) {
            visit(cellStart_[rowCell + static_cast<std::size_t>(x0)],
                  cellStart_[rowCell + static_cast<std::size_t>(x1) + 1]);
        });
    }

    /// Calls visit(cell) for every cell that may hold a position within `radius` of `center`.
    template <typename Visit>
    void forEachCell(const Vec3& center, double radius, Visit&& visit) const {
        forEachRow(center, radius, [&](std::size_t rowCell, int x0, int x1, double) {
            for (int x = x0; x <= x1; ++x) visit(rowCell + static_cast<std::size_t>(x));
        });
    }

    /// As forEachCell, and also passes a lower bound of the squared distance from `center` to
    /// the cell's box (slightly shrunk, so rounding never makes it too large). Cells whose
    /// bound is not below radius² are left out.
    template <typename Visit>
    void forEachCellWithGap(const Vec3& center, double radius, Visit&& visit) const {
        constexpr int kMaxSpan = 24;
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            if (center[a] + radius < origin_[a] ||
                center[a] - radius > origin_[a] + cellSize_ * count_[a]) {
                return;
            }
            lo[a] = clampIndex(std::floor((center[a] - radius - origin_[a]) * inverseCell_), a);
            hi[a] = clampIndex(std::floor((center[a] + radius - origin_[a]) * inverseCell_), a);
        }
        if (hi[0] - lo[0] >= kMaxSpan || hi[1] - lo[1] >= kMaxSpan || hi[2] - lo[2] >= kMaxSpan) {
            forEachRow(center, radius, [&](std::size_t rowCell, int x0, int x1, double rowGap2) {
                for (int x = x0; x <= x1; ++x) {
                    const double dx = axisGap(center.x(), x, 0);
                    visit(rowCell + static_cast<std::size_t>(x), rowGap2 + dx * dx);
                }
            });
            return;
        }
        // Squared gaps per axis, once per query.
        double gap2[3][kMaxSpan];
        for (int a = 0; a < 3; ++a) {
            for (int i = lo[a]; i <= hi[a]; ++i) {
                const double d = axisGap(center[a], i, a);
                gap2[a][i - lo[a]] = d * d;
            }
        }
        const double r2 = radius * radius;
        for (int z = lo[2]; z <= hi[2]; ++z) {
            const double gz = gap2[2][z - lo[2]];
            if (gz >= r2) continue;
            for (int y = lo[1]; y <= hi[1]; ++y) {
                const double gyz = gz + gap2[1][y - lo[1]];
                if (gyz >= r2) continue;
                const std::size_t row =
                    (static_cast<std::size_t>(z) * count_[1] + static_cast<std::size_t>(y)) *
                    count_[0];
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    const double g = gyz + gap2[0][x - lo[0]];
                    if (g < r2) visit(row + static_cast<std::size_t>(x), g);
                }
            }
        }
    }

    /// The cell-ordered points of `cell` are [cellBegin(cell), cellEnd(cell)).
    std::uint32_t cellBegin(std::size_t cell) const { return cellStart_[cell]; }
    std::uint32_t cellEnd(std::size_t cell) const { return cellStart_[cell + 1]; }

    /// Largest absolute coordinate of any point of the grid's box.
    double maxAbsCoordinate() const {
        double m = 0.0;
        for (int a = 0; a < 3; ++a) {
            m = std::max({m, std::abs(origin_[a]), std::abs(origin_[a] + cellSize_ * count_[a])});
        }
        return m;
    }

    /// True when the ball of `radius` around `center` lies inside the grid.
    bool containsBall(const Vec3& center, double radius) const;

    /// Bytes used by the grid's own arrays.
    std::size_t memoryBytes() const { return cellStart_.capacity() * sizeof(std::uint32_t); }

private:
    // Calls visit(cellIndexOfRowStart, x0, x1, rowGap2) for each row (y, z) of cells touched by
    // the ball, with the x range narrowed to the ball's chord in that row; rowGap2 bounds the
    // squared distance in y and z from below.
    template <typename Visit>
    void forEachRow(const Vec3& c, double r, Visit&& visit) const {
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = clampIndex(std::floor((c[a] - r - origin_[a]) * inverseCell_), a);
            hi[a] = clampIndex(std::floor((c[a] + r - origin_[a]) * inverseCell_), a);
            if (c[a] + r < origin_[a] || c[a] - r > origin_[a] + cellSize_ * count_[a]) return;
        }
        const double r2 = r * r;
        for (int z = lo[2]; z <= hi[2]; ++z) {
            const double dz = axisGap(c.z(), z, 2);
            const double dz2 = dz * dz;
            if (dz2 > r2) continue;
            for (int y = lo[1]; y <= hi[1]; ++y) {
                const double dy = axisGap(c.y(), y, 1);
                const double rest = r2 - dz2 - dy * dy;
                if (rest < 0.0) continue;
                const double w = std::sqrt(rest);
                const int x0 = clampIndex(std::floor((c.x() - w - origin_.x()) * inverseCell_), 0);
                const int x1 = clampIndex(std::floor((c.x() + w - origin_.x()) * inverseCell_), 0);
                const std::size_t row =
                    (static_cast<std::size_t>(z) * count_[1] + static_cast<std::size_t>(y)) *
                    count_[0];
                visit(row, x0, x1, dz2 + dy * dy);
            }
        }
    }

    int clampIndex(double cell, int axis) const {
        if (!(cell >= 0.0)) return 0;
        return cell >= count_[axis] - 1 ? count_[axis] - 1 : static_cast<int>(cell);
    }

    // Distance along `axis` from coordinate v to the slab of cell i (0 inside), less a
    // millionth of a cell so that points rounded into the cell are never closer than this.
    double axisGap(double v, int i, int axis) const {
        const double slack = 1e-6 * cellSize_;
        const double lo = origin_[axis] + cellSize_ * i - slack;
        if (v < lo) return lo - v;
        const double hi = lo + cellSize_ + 2.0 * slack;
        return v > hi ? v - hi : 0.0;
    }

    Vec3 origin_ = Vec3::Zero();
    double cellSize_ = 1.0;
    double inverseCell_ = 1.0;
    int count_[3] = {1, 1, 1};
    std::vector<std::uint32_t> cellStart_;
};

}  // namespace ramus::colonize_detail
