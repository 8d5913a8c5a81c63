#include "segment_grid.hpp"

#include <algorithm>
#include <cmath>

#include "welded_skeleton.hpp"

namespace ramus::detail {

namespace {
// Segments more than this many cells across any axis are kept in a list of their own, which
// every query returns: a few huge trunk segments must not fill millions of cells.
constexpr std::int64_t kMaxCellsAcross = 64;
}  // namespace

SegmentGrid::SegmentGrid(const WeldSkeleton& s) {
    // Cells the size of a typical segment's box: each segment lands in a few cells.
    double total = 0.0;
    std::size_t count = 0;
    for (const WeldLimb& limb : s.limbs) {
        for (std::uint32_t k = 0; k + 1 < limb.count; ++k) {
            const std::uint32_t p = limb.first + k;
            total += (s.pointPosition[p + 1] - s.pointPosition[p]).norm() +
                     2.0 * std::max(s.pointRadius[p], s.pointRadius[p + 1]);
            ++count;
        }
    }
    cell_ = count > 0 && total > 0.0 ? total / static_cast<double>(count) : 1.0;
    points_ = s.pointPosition.size();
    for (const WeldLimb& limb : s.limbs) {
        for (std::uint32_t k = 0; k + 1 < limb.count; ++k) {
            const std::uint32_t p = limb.first + k;
            const double r = std::max(s.pointRadius[p], s.pointRadius[p + 1]);
            const Vec3 lo = s.pointPosition[p].cwiseMin(s.pointPosition[p + 1]) - Vec3::Constant(r);
            const Vec3 hi = s.pointPosition[p].cwiseMax(s.pointPosition[p + 1]) + Vec3::Constant(r);
            const auto a = cellOf(lo);
            const auto b = cellOf(hi);
            if (b[0] - a[0] > kMaxCellsAcross || b[1] - a[1] > kMaxCellsAcross ||
                b[2] - a[2] > kMaxCellsAcross) {
                large_.push_back(p);
                continue;
            }
            for (std::int64_t x = a[0]; x <= b[0]; ++x) {
                for (std::int64_t y = a[1]; y <= b[1]; ++y) {
                    for (std::int64_t z = a[2]; z <= b[2]; ++z)
                        entries_.emplace_back(keyOf({x, y, z}), p);
                }
            }
        }
    }
    std::sort(entries_.begin(), entries_.end());
}

std::array<std::int64_t, 3> SegmentGrid::cellOf(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)),
            static_cast<std::int64_t>(std::floor(p.y() / cell_)),
            static_cast<std::int64_t>(std::floor(p.z() / cell_))};
}

// Cells mixed into 64 bits; two cells with one key only add candidates, which the caller's
// exact distance test drops.
std::uint64_t SegmentGrid::keyOf(const std::array<std::int64_t, 3>& cell) {
    std::uint64_t key = 0x9e3779b97f4a7c15ull;
    for (const std::int64_t c : cell) {
        key ^= static_cast<std::uint64_t>(c) + 0x9e3779b97f4a7c15ull + (key << 6) + (key >> 2);
    }
    return key;
}

}  // namespace ramus::detail
