// Based on: uniform grid with counting sort into cell order (see spatial_grid.hpp).
#include "spatial_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "ramus/error.hpp"

namespace ramus::colonize_detail {

SpatialGrid::SpatialGrid(std::span<const float> xs, std::span<const float> ys,
                         std::span<const float> zs, double influenceRadius, int subdivision,
                         std::size_t maxCells, std::vector<std::uint32_t>& order) {
    const std::size_t n = xs.size();
    auto point = [&](std::size_t i) { return Vec3(xs[i], ys[i], zs[i]); };
    Aabb box;
    for (std::size_t i = 0; i < n; ++i) box.add(point(i));
    if (box.empty()) box.add(Vec3::Zero());
    const Vec3 extent = box.extent();
    // No cell size covers an infinite extent: the search below would never end.
    if (!extent.allFinite()) throw Error("spatial grid over points that are not finite");

    // Cells of d_i / subdivision; a margin of cells wide enough for nodes within d_i of a point.
    // Counts are computed in doubles and only converted once they fit: a tiny radius against a
    // huge extent (fuzzed configs) would overflow int.
    const double limit = static_cast<double>(
        std::min<std::size_t>(std::max<std::size_t>(maxCells, 64), std::size_t{1} << 31));
    double cell = influenceRadius / std::max(1, subdivision);
    for (;;) {
        const double margin = std::ceil(influenceRadius / cell);
        std::array<double, 3> counts{};
        double total = 1.0;
        for (int a = 0; a < 3; ++a) {
            counts[a] = std::floor(extent[a] / cell) + 1.0 + 2.0 * margin;
            total *= counts[a];
        }
        if (total <= limit) {
            for (int a = 0; a < 3; ++a) count_[a] = static_cast<int>(counts[a]);
            origin_ = box.min - Vec3::Constant(margin * cell);
            break;
        }
        // Steps of 1.25 (the usual case: a few). Beyond a million times too many cells, first
        // a jump to about a million times (the steps then take ~20 more rounds).
        const double ratio = total / limit;
        if (!std::isfinite(ratio)) {
            cell *= 1e6;
        } else if (ratio > 1e6) {
            cell *= std::cbrt(ratio) / 100.0;
        } else {
            cell *= 1.25;
        }
    }
    cellSize_ = cell;
    inverseCell_ = 1.0 / cell;

    // Counting sort of the points into cell order (stable: equal cells keep index order).
    const std::size_t cells = static_cast<std::size_t>(count_[0]) * count_[1] * count_[2];
    cellStart_.assign(cells + 1, 0);
    std::vector<std::uint32_t> cellOfPoint(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<std::uint32_t>(cellOf(point(i)));
        cellOfPoint[i] = c;
        ++cellStart_[c + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) cellStart_[c + 1] += cellStart_[c];
    order.assign(n, 0);
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        order[fill[cellOfPoint[i]]++] = static_cast<std::uint32_t>(i);
    }
}

std::int64_t SpatialGrid::cellOf(const Vec3& p) const {
    std::int64_t index = 0;
    for (int a = 2; a >= 0; --a) {
        const double f = std::floor((p[a] - origin_[a]) * inverseCell_);
        if (!(f >= 0.0 && f < count_[a])) return -1;
        index = index * count_[a] + static_cast<std::int64_t>(f);
    }
    return index;
}

bool SpatialGrid::containsBall(const Vec3& center, double radius) const {
    for (int a = 0; a < 3; ++a) {
        if (center[a] - radius < origin_[a] ||
            center[a] + radius >= origin_[a] + cellSize_ * count_[a]) {
            return false;
        }
    }
    return true;
}

}  // namespace ramus::colonize_detail
