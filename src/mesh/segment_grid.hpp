// A uniform grid over the tapered segments of a welded skeleton's limbs, for finding the
// branches near a junction without scanning the whole tree (the junction shrinking in
// welded_junction_refine.cpp asks once per junction it refines: linear in the tree, not
// quadratic). Internal to src/mesh.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "ramus/math.hpp"

namespace ramus::detail {

struct WeldSkeleton;

class SegmentGrid {
public:
    /// Indexes every segment (limb point p to p + 1 of one limb), its box grown by its radii.
    explicit SegmentGrid(const WeldSkeleton& skeleton);

    /// Which segments a query has visited: one per thread asking (the grid itself is only
    /// read, so threads share it).
    struct Marks {
        std::vector<std::uint32_t> seen;  // per point: the last query that visited it
        std::uint32_t stamp = 0;
    };

    /// Calls visit(p) once for every segment whose box meets the box of the ball (centre,
    /// radius): a superset of the segments within `radius` of `centre`; stops early when
    /// visit returns false. Returns whether it went through all.
    template <class Visit>
    bool near(const Vec3& centre, double radius, Marks& marks, Visit visit) const {
        if (marks.seen.size() != points_) marks.seen.assign(points_, 0);
        const std::uint32_t stamp = ++marks.stamp;
        auto once = [&](std::uint32_t p) {
            if (marks.seen[p] == stamp) return true;
            marks.seen[p] = stamp;
            return visit(p);
        };
        for (const std::uint32_t p : large_) {
            if (!once(p)) return false;
        }
        const auto lo = cellOf(centre - Vec3::Constant(radius));
        const auto hi = cellOf(centre + Vec3::Constant(radius));
        double cells = 1.0;
        for (int d = 0; d < 3; ++d) cells *= static_cast<double>(hi[d] - lo[d] + 1);
        if (cells > static_cast<double>(entries_.size())) {  // a ball over most of the tree
            for (const auto& entry : entries_) {
                if (!once(entry.second)) return false;
            }
            return true;
        }
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
                for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
                    const std::uint64_t key = keyOf({x, y, z});
                    auto it = std::lower_bound(entries_.begin(), entries_.end(),
                                               std::pair<std::uint64_t, std::uint32_t>{key, 0});
                    for (; it != entries_.end() && it->first == key; ++it) {
                        if (!once(it->second)) return false;
                    }
                }
            }
        }
        return true;
    }

private:
    std::array<std::int64_t, 3> cellOf(const Vec3& p) const;
    static std::uint64_t keyOf(const std::array<std::int64_t, 3>& cell);

    double cell_ = 1.0;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries_;  // (cell key, point), sorted
    std::vector<std::uint32_t> large_;  // segments too large for cells: returned every time
    std::size_t points_ = 0;            // of the skeleton (Marks::seen's size)
};

}  // namespace ramus::detail
