// A hash table of indices into an array kept by the caller, who hashes and compares the items:
// open addressing with linear probing over twice as many slots as items, no allocation per
// item. For finding equal items among hundreds of thousands (the solid union's welds by
// position and vertex maps, the refinement's vertices), where sorting them had cost a comparison
// of whole keys per step. Internal to src/mesh.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace ramus::detail {

class IndexHashTable {
public:
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

    /// Room for `items` indices.
    explicit IndexHashTable(std::size_t items)
        : slots_(std::bit_ceil(2 * items + 2), kNone), mask_(slots_.size() - 1) {}

    /// The first index stored with hash `hash` for which same(index) holds; where there is none,
    /// stores `index` and returns it.
    template <class Same>
    std::uint32_t findOrAdd(std::uint64_t hash, std::uint32_t index, Same same) {
        for (std::size_t s = hash & mask_;; s = (s + 1) & mask_) {
            if (slots_[s] == kNone) return slots_[s] = index;
            if (same(slots_[s])) return slots_[s];
        }
    }

    /// How many indices it has room for.
    std::size_t capacity() const { return slots_.size() / 2 - 1; }

    /// Makes room for `items` indices, moving the stored ones (hashOf(index): their hashes).
    template <class HashOf>
    void grow(std::size_t items, HashOf hashOf) {
        IndexHashTable grown(items);
        for (const std::uint32_t index : slots_) {
            if (index == kNone) continue;
            std::size_t s = hashOf(index) & grown.mask_;
            while (grown.slots_[s] != kNone) s = (s + 1) & grown.mask_;
            grown.slots_[s] = index;
        }
        *this = std::move(grown);
    }

private:
    std::vector<std::uint32_t> slots_;
    std::size_t mask_;
};

}  // namespace ramus::detail
