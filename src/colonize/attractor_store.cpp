// Based on: Runions et al. 2007 §2, seed 002 §3.3 (steps 1 and 3), made incremental. Every
// decision is taken in double precision exactly as the brute-force definition takes it; single
// precision only pre-selects candidates, with a margin larger than its rounding error.
#include "attractor_store.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "growth_rules.hpp"

namespace ramus::colonize_detail {

namespace {

constexpr float kDeadKey = -std::numeric_limits<float>::infinity();
// Rounds a float key up so it is never below the double it stands for.
constexpr float kKeyUp = 1.0f + 0x1p-22f;
// Relative slack on keys and bounds, larger than the float rounding of a comparison.
constexpr float kSlack = 1.0f + 0x1p-20f;

}  // namespace

AttractorStore::AttractorStore(std::vector<float> xs, std::vector<float> ys, std::vector<float> zs,
                               double influenceRadius, double killRadius, int gridSubdivision)
    : influence2_(influenceRadius * influenceRadius),
      kill2_(killRadius * killRadius),
      x_(std::move(xs)),
      y_(std::move(ys)),
      z_(std::move(zs)) {
    const std::size_t n = x_.size();
    grid_ = SpatialGrid(x_, y_, z_, influenceRadius, gridSubdivision,
                        std::max<std::size_t>(n / 2, 4096), original_);
    // Into cell order, one coordinate at a time (4 extra bytes per point at most).
    std::vector<float> sorted(n);
    for (std::vector<float>* axis : {&x_, &y_, &z_}) {
        for (std::size_t i = 0; i < n; ++i) sorted[i] = (*axis)[original_[i]];
        axis->swap(sorted);
    }
    sorted = {};
    unassignedKey_ = static_cast<float>(influence2_) * kKeyUp;
    key_.assign(n, unassignedKey_);
    owner_.assign(n, kUnassigned);
    next_.assign(n, -1);
    prev_.assign(n, -1);
    alive_ = n;
    // Float squared distances (for distances up to d_i, coordinates up to m) are off by less
    // than this; see the error analysis in docs/colonize.md ("Speed").
    const double m = grid_.maxAbsCoordinate() + influenceRadius;
    const double e1 = 0x1p-22 * (m + influenceRadius);
    floatMargin_ =
        static_cast<float>(0x1p-20 * influence2_ + 4.0 * e1 * influenceRadius + 4.0 * e1 * e1);
    cellBound_.assign(grid_.cellCount(), kDeadKey);
    std::uint32_t largestCell = 0;
    for (std::size_t c = 0; c < grid_.cellCount(); ++c) {
        const std::uint32_t count = grid_.cellEnd(c) - grid_.cellBegin(c);
        if (count > 0) cellBound_[c] = unassignedKey_ * kSlack;
        largestCell = std::max(largestCell, count);
    }
    candidates_.resize(largestCell);
}

void AttractorStore::release() {
    grid_ = SpatialGrid();
    x_ = {}, y_ = {}, z_ = {}, key_ = {};
    owner_ = {}, next_ = {}, prev_ = {}, head_ = {};
    original_ = {};
    cellBound_ = {};
    candidates_ = {};
}

void AttractorStore::attach(std::uint32_t i, NodeId node, double d2) {
    owner_[i] = node;
    key_[i] = static_cast<float>(d2) * kKeyUp;
    prev_[i] = -1;
    next_[i] = head_[static_cast<std::size_t>(node)];
    if (next_[i] != -1) prev_[static_cast<std::size_t>(next_[i])] = static_cast<std::int32_t>(i);
    head_[static_cast<std::size_t>(node)] = static_cast<std::int32_t>(i);
    ++assigned_;
}

void AttractorStore::detach(std::uint32_t i) {
    const NodeId node = owner_[i];
    if (prev_[i] != -1) {
        next_[static_cast<std::size_t>(prev_[i])] = next_[i];
    } else {
        head_[static_cast<std::size_t>(node)] = next_[i];
    }
    if (next_[i] != -1) prev_[static_cast<std::size_t>(next_[i])] = prev_[i];
    owner_[i] = kUnassigned;
    key_[i] = unassignedKey_;
    --assigned_;
}

void AttractorStore::moveTo(std::uint32_t i, NodeId node, double d2) {
    if (owner_[i] >= 0) detach(i);
    if (node >= 0) attach(i, node, d2);
    // The key may have grown (owner farther or gone): raise the cell's bound.
    const auto cell = static_cast<std::size_t>(grid_.cellOf(position(i).cast<double>()));
    cellBound_[cell] = std::max(cellBound_[cell], key_[i] * kSlack);
}

void AttractorStore::refreshBound(std::size_t cell) {
    float bound = kDeadKey;
    for (std::uint32_t i = grid_.cellBegin(cell); i < grid_.cellEnd(cell); ++i) {
        bound = std::max(bound, key_[i]);
    }
    cellBound_[cell] = bound * kSlack;
}

// Pass 1 of removeAndClaimNear, branch-free: stores in candidates_ the points of [first, last)
// whose float squared distance to (cx, cy, cz) may be below max(key·slack, kill threshold);
// dead points (key -inf) never qualify. Four points at a time where vector extensions exist.
std::uint32_t AttractorStore::preselect(std::uint32_t first, std::uint32_t last, float cx, float cy,
                                        float cz, float killThreshold) {
    const float* xs = x_.data();
    const float* ys = y_.data();
    const float* zs = z_.data();
    const float* keys = key_.data();
    std::uint32_t* out = candidates_.data();
    const float margin = floatMargin_;
    std::uint32_t count = 0;
    std::uint32_t i = first;
#if defined(__GNUC__)
    using V4f = float __attribute__((vector_size(16)));
    const V4f vx = {cx, cx, cx, cx}, vy = {cy, cy, cy, cy}, vz = {cz, cz, cz, cz};
    const V4f slack = {kSlack, kSlack, kSlack, kSlack};
    const V4f kill = {killThreshold, killThreshold, killThreshold, killThreshold};
    const V4f vmargin = {margin, margin, margin, margin};
    const V4f zero = {0.0f, 0.0f, 0.0f, 0.0f};
    for (; i + 4 <= last; i += 4) {
        V4f x, y, z, key;
        std::memcpy(&x, xs + i, sizeof x);
        std::memcpy(&y, ys + i, sizeof y);
        std::memcpy(&z, zs + i, sizeof z);
        std::memcpy(&key, keys + i, sizeof key);
        const V4f dx = x - vx, dy = y - vy, dz = z - vz;
        const V4f scaled = key * slack;
        V4f limit = scaled > kill ? scaled : kill;
        limit = key < zero ? key : limit;
        const auto pass = (dx * dx + dy * dy + dz * dz) < (limit + vmargin);
        if (!(pass[0] | pass[1] | pass[2] | pass[3])) continue;
        for (std::uint32_t lane = 0; lane < 4; ++lane) {
            out[count] = i + lane;
            count += pass[lane] ? 1u : 0u;
        }
    }
#endif
    for (; i < last; ++i) {
        const float dx = xs[i] - cx, dy = ys[i] - cy, dz = zs[i] - cz;
        const float key = keys[i];
        const float limit = key < 0.0f ? key : std::max(key * kSlack, killThreshold);
        out[count] = i;
        count += (dx * dx + dy * dy + dz * dz < limit + margin) ? 1u : 0u;
    }
    return count;
}

void AttractorStore::removeAndClaimNear(NodeId node, const Vec3& c,
                                        std::span<const Vec3> nodePositions,
                                        std::vector<NodeId>& changedNodes) {
    const float cx = static_cast<float>(c.x()), cy = static_cast<float>(c.y()),
                cz = static_cast<float>(c.z());
    const float killThreshold = static_cast<float>(kill2_) * kSlack;
    bool claimed = false;
    grid_.forEachCellWithGap(c, std::sqrt(influence2_), [&](std::size_t cell, double gap2) {
        const float bound = cellBound_[cell];
        if (bound < 0.0f || (gap2 >= kill2_ && (gap2 >= influence2_ || gap2 >= bound))) return;
        // Pass 1, branch-free: points whose float distance may be below their key (claim) or
        // the kill radius (removal); dead points have key -inf and never pass.
        const std::uint32_t count =
            preselect(grid_.cellBegin(cell), grid_.cellEnd(cell), cx, cy, cz, killThreshold);
        if (count == 0) return;
        // Pass 2, exact: remove within d_k; else claim when strictly nearer than the owner
        // (a tie keeps the older node).
        bool changed = false;
        for (std::uint32_t k = 0; k < count; ++k) {
            const std::uint32_t i = candidates_[k];
            const double d2 = squaredDistance(position(i), c);
            const NodeId current = owner_[i];
            if (d2 < kill2_) {
                if (current >= 0) {
                    changedNodes.push_back(current);
                    detach(i);
                }
                owner_[i] = kDead;
                key_[i] = kDeadKey;
                --alive_;
                changed = true;
                continue;
            }
            if (!(d2 < influence2_)) continue;
            if (current >= 0) {
                const Vec3& owner = nodePositions[static_cast<std::size_t>(current)];
                if (d2 >= squaredDistance(position(i), owner)) continue;
                changedNodes.push_back(current);
                detach(i);
            }
            attach(i, node, d2);
            changed = claimed = true;
        }
        if (changed) refreshBound(cell);
    });
    if (claimed) changedNodes.push_back(node);
}

bool AttractorStore::hasPointWithin(const Vec3& c, double radius) const {
    bool found = false;
    grid_.forEachCellWithGap(c, radius, [&](std::size_t cell, double gap2) {
        if (found || cellBound_[cell] < 0.0f || gap2 >= radius * radius) return;
        for (std::uint32_t i = grid_.cellBegin(cell); i < grid_.cellEnd(cell) && !found; ++i) {
            found = owner_[i] != kDead && squaredDistance(position(i), c) < radius * radius;
        }
    });
    return found;
}

std::int64_t AttractorStore::nearestAlive(const Vec3& c) const {
    std::int64_t best = -1;
    double bestD2 = 0.0;
    for (std::uint32_t i = 0; i < owner_.size(); ++i) {
        if (owner_[i] == kDead) continue;
        const double d2 = squaredDistance(position(i), c);
        if (best < 0 || d2 < bestD2 ||
            (d2 == bestD2 && original_[i] < original_[static_cast<std::size_t>(best)])) {
            best = i;
            bestD2 = d2;
        }
    }
    return best;
}

}  // namespace ramus::colonize_detail
