// The hash table of indices (src/mesh/index_hash_table.hpp): equal items found, others added,
// and growing keeps what was stored.
#include "mesh/index_hash_table.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "mesh/fixed_hash.hpp"

namespace ramus {
namespace {

using detail::IndexHashTable;

// Items with many repeats, hashed badly on purpose (every item of a value in one slot run, and
// values colliding in pairs) so that probing past other items is exercised.
std::uint64_t poorHash(std::uint32_t value) { return value / 2; }

TEST(IndexHashTable, FindsTheFirstEqualItemAndAddsNewOnes) {
    std::vector<std::uint32_t> items;
    for (std::uint32_t i = 0; i < 300; ++i) items.push_back((i * 7) % 50);
    IndexHashTable table(items.size());
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        const std::uint32_t first = table.findOrAdd(
            poorHash(items[i]), i, [&](std::uint32_t j) { return items[j] == items[i]; });
        std::uint32_t expected = i;
        for (std::uint32_t j = 0; j < i; ++j) {
            if (items[j] == items[i]) {
                expected = j;
                break;
            }
        }
        EXPECT_EQ(first, expected) << "item " << i;
    }
    // Looked up again, every value finds its first item (the index offered is never stored).
    const auto absent = static_cast<std::uint32_t>(items.size());
    for (std::uint32_t value = 0; value < 50; ++value) {
        const std::uint32_t found = table.findOrAdd(
            poorHash(value), absent, [&](std::uint32_t j) { return items[j] == value; });
        std::uint32_t first = 0;
        while (items[first] != value) ++first;
        EXPECT_EQ(found, first) << "value " << value;
    }
}

TEST(IndexHashTable, GrowingKeepsTheStoredIndices) {
    std::vector<std::uint64_t> keys;
    IndexHashTable table(4);
    auto hashOf = [&](std::uint32_t j) { return detail::splitMixFinal(keys[j]); };
    for (std::uint64_t k = 0; k < 1000; ++k) {
        const auto next = static_cast<std::uint32_t>(keys.size());
        if (next == table.capacity()) table.grow(2 * next, hashOf);
        keys.push_back(k * k + 1);
        ASSERT_EQ(table.findOrAdd(hashOf(next), next,
                                  [&](std::uint32_t j) { return keys[j] == keys[next]; }),
                  next);
    }
    EXPECT_GE(table.capacity(), keys.size());
    const auto absent = static_cast<std::uint32_t>(keys.size());  // offered, never stored
    for (std::uint32_t j = 0; j < keys.size(); ++j) {
        EXPECT_EQ(
            table.findOrAdd(hashOf(j), absent, [&](std::uint32_t i) { return keys[i] == keys[j]; }),
            j);
    }
}

}  // namespace
}  // namespace ramus
