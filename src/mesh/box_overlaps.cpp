// Overlapping boxes by a hierarchy of uniform grids (box_overlaps.hpp).
#include "box_overlaps.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "box_tree.hpp"
#include "fixed_hash.hpp"
#include "on_cores.hpp"

namespace ramus::detail {
namespace {

// Level 0's cells are this many times as wide as the median box's largest side; a level takes
// the boxes up to kLevelSpan of its cells wide.
constexpr double kCellScale = 2.0;
constexpr double kLevelSpan = 2.0;
// Cell coordinates take 19 bits per axis and the level 5 in a cell's key.
constexpr int kAxisBits = 19;
constexpr int kLevelBits = 5;
constexpr std::int64_t kAxisCells = std::int64_t{1} << kAxisBits;
constexpr int kLevels = 1 << kLevelBits;
// Buckets of the hash table handled by one task, boxes by one task of the cross-level search.
constexpr std::size_t kBucketsPerTask = 4096;
constexpr std::size_t kBoxesPerTask = 1024;

using Cell = std::array<std::int64_t, 3>;

// Whether every coordinate of b is a finite number (a box with another is left out).
bool finiteBox(const Box3& b) {
    for (int d = 0; d < 3; ++d) {
        if (!std::isfinite(b.lo[d]) || !std::isfinite(b.hi[d])) return false;
    }
    return true;
}

// A box entered in a cell: the cell's key, the box and on which axes the cell is the first the
// box meets (bit d: axis d). Of the cells that two overlapping boxes both meet, the one holding
// the lowest corner of their intersection reports them: as the cells are numbered along each
// axis by a monotone function, that corner's cell is on each axis the later of the two boxes'
// first cells, so the cell reports the pair where on every axis it is the first cell of one of
// them: (mask of one | mask of the other) == 7, without computing the corner's cell (three
// divisions per pair had been a third of the search).
struct Entry {
    std::uint64_t key;
    std::uint32_t box;
    std::uint32_t firstOn;  // the axes on which this is the box's first cell
    bool operator<(const Entry& e) const { return key != e.key ? key < e.key : box < e.box; }
};
constexpr std::uint32_t kFirstOnEveryAxis = 7;

// Grids over the boxes, one per level. Level 0's cells are twice as wide as the median box's
// largest side and it takes the boxes up to kLevelSpan cells wide (nearly all of a mesh's
// triangles, each meeting a few cells); the next level does the same with the boxes left, and
// so on: a level's median box is wider than kLevelSpan cells of every level below, so its cells
// are wider than twice any box of those, which meets at most 8 of them. Each level takes at
// least half of the boxes left, so there are few (tree_3d, ABOP 1.24a 2; ABOP 2.8c 5).
class BoxHierarchy {
public:
    // Over the non-empty `boxes`; none: not valid.
    explicit BoxHierarchy(const std::vector<Box3>& boxes) : level_(boxes.size(), -1) {
        std::array<double, 3> top{};
        origin_.fill(std::numeric_limits<double>::infinity());
        top.fill(-std::numeric_limits<double>::infinity());
        std::vector<std::uint32_t> left;  // boxes without a level yet
        for (std::uint32_t i = 0; i < boxes.size(); ++i) {
            if (boxes[i].empty() || !finiteBox(boxes[i])) continue;
            for (int d = 0; d < 3; ++d) {
                origin_[d] = std::min(origin_[d], boxes[i].lo[d]);
                top[d] = std::max(top[d], boxes[i].hi[d]);
            }
            left.push_back(i);
        }
        double extent = 0.0;
        for (int d = 0; d < 3; ++d) extent = std::max(extent, top[d] - origin_[d]);
        std::vector<double> sides;
        for (int k = 0; k < kLevels && !left.empty(); ++k) {
            sides.clear();
            for (const std::uint32_t i : left) sides.push_back(largestSide(boxes[i]));
            auto middle = sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2);
            std::nth_element(sides.begin(), middle, sides.end());
            double width =
                std::max(kCellScale * *middle, extent / static_cast<double>(kAxisCells - 1));
            if (!(width > 0.0)) width = 1.0;  // every box a point, all at one place
            width_[static_cast<std::size_t>(k)] = width;
            std::erase_if(left, [&](std::uint32_t i) {
                if (k + 1 < kLevels && largestSide(boxes[i]) > kLevelSpan * width) return false;
                level_[i] = k;
                return true;
            });
        }
    }

    bool valid() const { return width_[0] > 0.0; }
    // The level of box i; -1 where it is empty or not finite.
    int level(std::size_t i) const { return level_[i]; }

    Cell cellOf(const std::array<double, 3>& p, int level) const {
        Cell c;
        for (int d = 0; d < 3; ++d) {
            const double x =
                std::floor((p[d] - origin_[d]) / width_[static_cast<std::size_t>(level)]);
            c[d] = std::clamp(static_cast<std::int64_t>(x), std::int64_t{0}, kAxisCells - 1);
        }
        return c;
    }
    static std::uint64_t keyOf(const Cell& c, int level) {
        return static_cast<std::uint64_t>(level) << (3 * kAxisBits) |
               static_cast<std::uint64_t>(c[0]) << (2 * kAxisBits) |
               static_cast<std::uint64_t>(c[1]) << kAxisBits | static_cast<std::uint64_t>(c[2]);
    }
    // Calls visit(key, firstOn) for every cell of `level` that box b meets, firstOn the axes on
    // which it is b's first cell (Entry).
    template <class Visit>
    void forCells(const Box3& b, int level, Visit visit) const {
        const Cell lo = cellOf(b.lo, level), hi = cellOf(b.hi, level);
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
                for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
                    visit(keyOf({x, y, z}, level), static_cast<std::uint32_t>(x == lo[0]) |
                                                       static_cast<std::uint32_t>(y == lo[1]) << 1 |
                                                       static_cast<std::uint32_t>(z == lo[2]) << 2);
                }
            }
        }
    }

private:
    static double largestSide(const Box3& b) {
        return std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
    }

    std::array<double, 3> origin_{};
    std::array<double, kLevels> width_{};  // of the cells of each level
    std::vector<int> level_;
};

// The cells of all levels that the boxes i with include(i) meet on their level, hashed into
// buckets: the entries (cell key, box) sorted by bucket and within a bucket by key.
class CellTable {
public:
    template <class Include>
    CellTable(const std::vector<Box3>& boxes, const BoxHierarchy& levels, Include include) {
        // The entries in box order, each cell's in one pass (the cells' bounds take divisions),
        // then a counting sort by bucket.
        std::vector<Entry> made;
        made.reserve(boxes.size());
        for (std::uint32_t i = 0; i < boxes.size(); ++i) {
            if (levels.level(i) < 0 || !include(i)) continue;
            used_[static_cast<std::size_t>(levels.level(i))] = true;
            levels.forCells(boxes[i], levels.level(i),
                            [&](std::uint64_t key, std::uint32_t firstOn) {
                                made.push_back(Entry{key, i, firstOn});
                            });
        }
        buckets_ = 1;
        while (buckets_ < made.size()) buckets_ *= 2;
        first_.assign(buckets_ + 1, 0);
        std::vector<std::uint32_t> bucketOfEntry(made.size());
        for (std::size_t k = 0; k < made.size(); ++k) {
            bucketOfEntry[k] = static_cast<std::uint32_t>(bucketOf(made[k].key));
            ++first_[bucketOfEntry[k] + 1];
        }
        for (std::size_t b = 0; b < buckets_; ++b) first_[b + 1] += first_[b];
        entries_.resize(made.size());
        std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
        for (std::size_t k = 0; k < made.size(); ++k) entries_[next[bucketOfEntry[k]]++] = made[k];
        // In box order already: only buckets that several cells share need sorting (buckets are
        // as many as entries, and cells hold tens of entries each).
        for (std::size_t b = 0; b < buckets_; ++b) {
            const auto from = entries_.begin() + first_[b], to = entries_.begin() + first_[b + 1];
            if (!std::is_sorted(from, to)) std::sort(from, to);
        }
    }

    std::size_t buckets() const { return buckets_; }
    // Whether a box of `level` has entries.
    bool has(int level) const { return used_[static_cast<std::size_t>(level)]; }
    // The entries of bucket b.
    std::pair<const Entry*, const Entry*> bucket(std::size_t b) const {
        return {entries_.data() + first_[b], entries_.data() + first_[b + 1]};
    }
    // The entries of the cell `key`.
    std::pair<const Entry*, const Entry*> cell(std::uint64_t key) const {
        const auto [begin, end] = bucket(bucketOf(key));
        const Entry* from = std::lower_bound(begin, end, Entry{key, 0, 0});
        const Entry* to = from;
        while (to != end && to->key == key) ++to;
        return {from, to};
    }

private:
    std::size_t bucketOf(std::uint64_t key) const { return splitMixFinal(key) & (buckets_ - 1); }

    std::size_t buckets_ = 1;
    std::array<bool, kLevels> used_{};
    std::vector<std::uint32_t> first_;
    std::vector<Entry> entries_;
};

// Appends to `out` the pair of box i with every box j of `table` in the cells of `level` that i
// meets, where wanted(j), the two overlap and the cell reports them.
template <class Wanted>
void addPairsMet(std::uint32_t i, int level, const std::vector<Box3>& boxes,
                 const BoxHierarchy& levels, const CellTable& table, Wanted wanted,
                 const PairFilter& keep, std::vector<BoxPair>& out) {
    levels.forCells(boxes[i], level, [&](std::uint64_t key, std::uint32_t firstOn) {
        const auto [from, to] = table.cell(key);
        for (const Entry* e = from; e != to; ++e) {
            const std::uint32_t j = e->box;
            if ((firstOn | e->firstOn) == kFirstOnEveryAxis && wanted(j) &&
                boxes[i].overlaps(boxes[j]) && keep(std::min(i, j), std::max(i, j))) {
                out.emplace_back(std::min(i, j), std::max(i, j));
            }
        }
    });
}

// Whether the search is to stop (overlappingBoxes' `stop`).
bool stopped(const std::atomic<bool>* stop) {
    return stop != nullptr && stop->load(std::memory_order_relaxed);
}

// Boxes looked at between two looks at `stop`.
constexpr std::size_t kBoxesBetweenStops = 64;

// The pairs in tasks of kBoxesPerTask boxes: task(first, end, out) for the boxes first..end-1
// (kBoxesBetweenStops at a time), out getting its pairs, until `stop` is set; concatenated in
// order.
template <class Task>
std::vector<BoxPair> pairsByBoxes(std::size_t n, Task task, const std::atomic<bool>* stop,
                                  std::vector<std::vector<BoxPair>> found = {}) {
    const std::size_t tasks = (n + kBoxesPerTask - 1) / kBoxesPerTask;
    const std::size_t before = found.size();
    found.resize(before + tasks);
    forEachCoarseOnCores(tasks, [&](std::size_t t) {
        const std::size_t end = std::min(n, (t + 1) * kBoxesPerTask);
        for (std::size_t first = t * kBoxesPerTask; first < end && !stopped(stop);
             first += kBoxesBetweenStops) {
            task(static_cast<std::uint32_t>(first),
                 static_cast<std::uint32_t>(std::min(end, first + kBoxesBetweenStops)),
                 found[before + t]);
        }
    });
    std::size_t total = 0;
    for (const auto& f : found) total += f.size();
    std::vector<BoxPair> pairs;
    pairs.reserve(total);
    for (const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
    return pairs;
}

// Every pair of overlapping boxes: the pairs within each cell of each level, then each box
// with the boxes of the levels above its own in the cells of theirs it meets.
std::vector<BoxPair> allOverlapping(const std::vector<Box3>& boxes, const BoxHierarchy& levels,
                                    const PairFilter& keep, const std::atomic<bool>* stop) {
    const CellTable table(boxes, levels, [](std::uint32_t) { return true; });
    const std::size_t bucketTasks = (table.buckets() + kBucketsPerTask - 1) / kBucketsPerTask;
    std::vector<std::vector<BoxPair>> found(bucketTasks);
    forEachCoarseOnCores(bucketTasks, [&](std::size_t task) {
        if (stopped(stop)) return;
        std::vector<Box3> local;  // the boxes of one cell, side by side
        const std::size_t end = std::min(table.buckets(), (task + 1) * kBucketsPerTask);
        for (std::size_t b = task * kBucketsPerTask; b < end && !stopped(stop); ++b) {
            const auto [begin, bucketEnd] = table.bucket(b);
            for (const Entry* s = begin; s != bucketEnd;) {  // a bucket may hold several cells
                const Entry* e = s + 1;
                while (e != bucketEnd && e->key == s->key) ++e;
                local.clear();
                for (const Entry* a = s; a != e; ++a) local.push_back(boxes[a->box]);
                for (std::size_t a = 0; a < local.size(); ++a) {
                    for (std::size_t c = a + 1; c < local.size(); ++c) {
                        if ((s[a].firstOn | s[c].firstOn) == kFirstOnEveryAxis &&
                            local[a].overlaps(local[c]) && keep(s[a].box, s[c].box)) {
                            found[task].emplace_back(s[a].box, s[c].box);  // sorted
                        }
                    }
                }
                s = e;
            }
        }
    });
    return pairsByBoxes(
        boxes.size(),
        [&](std::uint32_t first, std::uint32_t end, std::vector<BoxPair>& out) {
            for (std::uint32_t i = first; i < end; ++i) {
                for (int level = levels.level(i) + 1; levels.level(i) >= 0 && level < kLevels;
                     ++level) {
                    if (!table.has(level)) continue;
                    addPairsMet(
                        i, level, boxes, levels, table, [](std::uint32_t) { return true; }, keep,
                        out);
                }
            }
        },
        stop, std::move(found));
}

// The pairs of overlapping boxes with a suspect among them, by looking up: every box looks up
// the suspects of its own level and those above in a table of the suspects alone, and every
// suspect the other boxes of the levels above its own. Where there are few suspects (the
// crossing search after moving a few corners) no table of all boxes is built.
std::vector<BoxPair> overlappingSuspects(const std::vector<Box3>& boxes,
                                         const std::vector<char>& suspect,
                                         const BoxHierarchy& levels, const PairFilter& keep,
                                         const std::atomic<bool>* stop) {
    int lowest = kLevels;  // the lowest level of a suspect
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        if (suspect[i] && levels.level(i) >= 0) lowest = std::min(lowest, levels.level(i));
    }
    const CellTable suspects(boxes, levels, [&](std::uint32_t i) { return suspect[i] != 0; });
    const CellTable above(boxes, levels, [&](std::uint32_t i) {
        return suspect[i] == 0 && levels.level(i) > lowest;
    });
    return pairsByBoxes(
        boxes.size(),
        [&](std::uint32_t first, std::uint32_t end, std::vector<BoxPair>& out) {
            for (std::uint32_t i = first; i < end; ++i) {
                const int own = levels.level(i);
                if (own < 0) continue;
                // Two suspects of one level find each other: reported by the first.
                auto wanted = [&](std::uint32_t j) {
                    return j != i && !(suspect[i] && levels.level(j) == own && j < i);
                };
                for (int level = own; level < kLevels; ++level) {
                    if (suspects.has(level)) {
                        addPairsMet(i, level, boxes, levels, suspects, wanted, keep, out);
                    }
                    if (suspect[i] && level > own && above.has(level)) {
                        addPairsMet(i, level, boxes, levels, above, wanted, keep, out);
                    }
                }
            }
        },
        stop);
}

// With more than one suspect in this many boxes (the crossing count after a union: ABOP 1.24a
// 134 k of 167 k triangles), every overlapping pair is found as without suspects and those
// without one dropped: every box looking up the suspects' table cost more.
constexpr std::size_t kManySuspects = 2;

// With at most one suspect in this many boxes, the suspects go into a box tree and every box
// looks them up there: the grids' tables and every box's cells cost more than the few pairs
// (the crossing count after the repair's moves: ABOP 1.24a 25 ms a count over 167 k triangles
// with 300–1300 suspects).
constexpr std::size_t kFewSuspects = 32;

// The pairs of overlapping boxes with a suspect among them, where the suspects are few: every
// box looks up a tree of the suspects' boxes.
std::vector<BoxPair> overlappingFewSuspects(const std::vector<Box3>& boxes,
                                            const std::vector<char>& suspect,
                                            const PairFilter& keep, const std::atomic<bool>* stop) {
    std::vector<std::uint32_t> suspects;
    std::vector<Box3> suspectBoxes;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        if (!suspect[i] || boxes[i].empty() || !finiteBox(boxes[i])) continue;
        suspects.push_back(i);
        suspectBoxes.push_back(boxes[i]);
    }
    const BoxTree tree(suspectBoxes);
    return pairsByBoxes(
        boxes.size(),
        [&](std::uint32_t first, std::uint32_t end, std::vector<BoxPair>& out) {
            for (std::uint32_t i = first; i < end; ++i) {
                if (boxes[i].empty() || !finiteBox(boxes[i])) continue;
                tree.forEachOverlapping(boxes[i], [&](std::uint32_t k) {
                    const std::uint32_t j = suspects[k];
                    // Two suspects find each other: reported by the first.
                    if (j == i || (suspect[i] && j < i) || !boxes[i].overlaps(boxes[j])) return;
                    if (keep(std::min(i, j), std::max(i, j))) {
                        out.emplace_back(std::min(i, j), std::max(i, j));
                    }
                });
            }
        },
        stop);
}

}  // namespace

std::vector<BoxPair> overlappingBoxes(const std::vector<Box3>& boxes,
                                      const std::vector<char>& suspect, const PairFilter& keep,
                                      const std::atomic<bool>* stop) {
    const PairFilter all = [](std::uint32_t, std::uint32_t) { return true; };
    const PairFilter& filter = keep ? keep : all;
    const auto suspects = static_cast<std::size_t>(
        std::count_if(suspect.begin(), suspect.end(), [](char s) { return s != 0; }));
    if (!suspect.empty() && suspects * kFewSuspects <= boxes.size()) {
        return overlappingFewSuspects(boxes, suspect, filter, stop);
    }
    const BoxHierarchy levels(boxes);
    if (!levels.valid()) return {};
    if (suspect.empty()) return allOverlapping(boxes, levels, filter, stop);
    if (suspects * kManySuspects > boxes.size()) {
        return allOverlapping(
            boxes, levels,
            [&](std::uint32_t i, std::uint32_t j) {
                return (suspect[i] || suspect[j]) && filter(i, j);
            },
            stop);
    }
    return overlappingSuspects(boxes, suspect, levels, filter, stop);
}

}  // namespace ramus::detail
