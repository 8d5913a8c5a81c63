// The hash table of indices (src/mesh/index_hash_table.hpp): equal items found, others added,
// missing ones reported, and growing keeps what was stored.
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
    for (std::uint32_t value = 0; value < 60; ++value) {
        const std::uint32_t found =
            table.find(poorHash(value), [&](std::uint32_t j) { return items[j] == value; });
        if (value < 50) {
            ASSERT_NE(found, IndexHashTable::kNone);
            EXPECT_EQ(items[found], value);
        } else {
            EXPECT_EQ(found, IndexHashTable::kNone);
        }
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
    for (std::uint32_t j = 0; j < keys.size(); ++j) {
        EXPECT_EQ(table.find(hashOf(j), [&](std::uint32_t i) { return keys[i] == keys[j]; }), j);
    }
    EXPECT_EQ(table.find(detail::splitMixFinal(3), [&](std::uint32_t i) { return keys[i] == 3; }),
              IndexHashTable::kNone);  // 3 is no k² + 1
}

}  // namespace
}  // namespace ramus
