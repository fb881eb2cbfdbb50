// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/flat_index.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <map>
#include <random>

#include <gtest/gtest.h>

namespace roomcad {
namespace {

// Every key's slot is 0: each probe runs through all the keys stored before it.
struct CollidingHash {
  std::size_t operator()(std::uint64_t) const { return 0; }
};

TEST(FlatIndex, KeepsTheFirstIndexOfEachKeyThroughGrowth) {
  // Started with room for 1 key, so it grows many times on the way; compared with std::map.
  FlatIndex<std::array<std::uint64_t, 3>> index(1);
  std::map<std::array<std::uint64_t, 3>, std::uint32_t> reference;
  std::mt19937_64 random(7);
  for (std::uint32_t k = 0; k < 20000; ++k) {
    const std::array<std::uint64_t, 3> key{random() % 64, random() % 64, random() % 8};
    const auto [first, stored] = index.try_emplace(key, k);
    const auto [it, fresh] = reference.try_emplace(key, k);
    ASSERT_EQ(stored, fresh) << "at " << k;
    ASSERT_EQ(first, it->second) << "at " << k;
  }
  for (const auto& [key, first] : reference) EXPECT_EQ(index.find(key), first);
  EXPECT_EQ(index.find({64, 0, 0}), (FlatIndex<std::array<std::uint64_t, 3>>::kNone));
}

TEST(FlatIndex, KeysThatAllCollideAreStillToldApart) {
  FlatIndex<std::uint64_t, CollidingHash> index;
  for (std::uint64_t key = 0; key < 100; ++key)
    EXPECT_TRUE(index.try_emplace(key * 3, std::uint32_t(key)).second);
  for (std::uint64_t key = 0; key < 100; ++key) {
    EXPECT_EQ(index.find(key * 3), std::uint32_t(key));
    EXPECT_EQ(index.find(key * 3 + 1), (FlatIndex<std::uint64_t, CollidingHash>::kNone));
    EXPECT_FALSE(index.try_emplace(key * 3, 999).second);
  }
}

TEST(FlatIndex, MixedBitsSpreadNeighbouringKeys) {
  // Doubles of a grid (0.25, 0.5, 0.75, ...) differ in their high bits only; mixed, their low
  // bits (the table's slots) must differ: no slot takes more than a few of them.
  std::array<int, 256> used{};
  for (int k = 1; k <= 256; ++k) ++used[mix_bits(std::bit_cast<std::uint64_t>(0.25 * k)) & 255];
  int most = 0;
  for (const int n : used) most = std::max(most, n);
  EXPECT_LE(most, 8);
}

}  // namespace
}  // namespace roomcad
