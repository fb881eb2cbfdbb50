// SPDX-License-Identifier: GPL-3.0-or-later
// FlatIndex: a hash table from keys to 32-bit indices, for "which point (or corner, or object)
// had this key first" questions: open addressing with linear probing in two flat arrays.
// std::unordered_map allocates a node per entry; on tables of tens of thousands of points and
// corners per build (the general path), or of a large plan's ids (validation), those
// allocations and their scattered nodes were most of the tables' cost. Entries are never
// removed, and the table is never iterated, so nothing depends on its slot order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

#include "core/assert.h"

namespace roomcad {

/// @return x's bits mixed so that every input bit moves about half the output bits
///         (splitmix64's finaliser): linear probing needs well spread low bits.
[[nodiscard]] constexpr std::uint64_t mix_bits(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// Hash of a 64-bit key or an array of them, for FlatIndex.
struct BitsHash {
  [[nodiscard]] std::size_t operator()(std::uint64_t key) const {
    return std::size_t(mix_bits(key));
  }
  template <std::size_t N>
  [[nodiscard]] std::size_t operator()(const std::array<std::uint64_t, N>& key) const {
    std::uint64_t h = 0;
    for (const std::uint64_t k : key) h = mix_bits(h ^ k);
    return std::size_t(h);
  }
};

/// Key equality, word by word for arrays (std::array's == calls memcmp, which cost more than
/// the rest of a lookup).
template <class Key>
[[nodiscard]] bool same_key(const Key& a, const Key& b) {
  return a == b;
}
template <std::size_t N>
[[nodiscard]] bool same_key(const std::array<std::uint64_t, N>& a,
                            const std::array<std::uint64_t, N>& b) {
  bool same = true;
  for (std::size_t k = 0; k < N; ++k) same = same && a[k] == b[k];
  return same;
}

template <class Key, class Hash = BitsHash>
class FlatIndex {
 public:
  static constexpr std::uint32_t kNone = UINT32_MAX;

  /// An empty table with room for `expected` keys before it grows.
  explicit FlatIndex(std::size_t expected = 0) { grow(expected); }

  /// Stores `index` for `key` unless the key has one. @pre index != kNone.
  /// @return {the key's index, whether it was stored now}. O(1) expected.
  std::pair<std::uint32_t, bool> try_emplace(const Key& key, std::uint32_t index) {
    RC_ASSERT(index != kNone, "kNone marks an empty slot, never a stored index");
    if (2 * (size_ + 1) > values_.size()) grow(2 * (size_ + 1));
    std::size_t at = slot_of(key);
    for (; values_[at] != kNone; at = (at + 1) & mask_)
      if (same_key(keys_[at], key)) return {values_[at], false};
    keys_[at] = key;
    values_[at] = index;
    ++size_;
    return {index, true};
  }

  /// @return the key's index, or kNone. O(1) expected.
  [[nodiscard]] std::uint32_t find(const Key& key) const {
    for (std::size_t at = slot_of(key); values_[at] != kNone; at = (at + 1) & mask_)
      if (same_key(keys_[at], key)) return values_[at];
    return kNone;
  }

 private:
  [[nodiscard]] std::size_t slot_of(const Key& key) const { return Hash{}(key)&mask_; }

  // At least twice as many slots as `expected` keys (a power of two), so probes stay short;
  // the keys stored so far are filed again.
  void grow(std::size_t expected) {
    std::size_t slots = 16;
    while (slots < 2 * expected) slots *= 2;
    std::vector<Key> keys(slots);
    std::vector<std::uint32_t> values(slots, kNone);
    mask_ = slots - 1;
    for (std::size_t k = 0; k < values_.size(); ++k) {
      if (values_[k] == kNone) continue;
      std::size_t at = slot_of(keys_[k]);
      while (values[at] != kNone) at = (at + 1) & mask_;
      keys[at] = keys_[k];
      values[at] = values_[k];
    }
    keys_.swap(keys);
    values_.swap(values);
  }

  std::vector<Key> keys_;
  std::vector<std::uint32_t> values_;  // kNone: an empty slot
  std::size_t mask_ = 0, size_ = 0;
};

/// Object indices by id: which object had the id first. Its keys view the objects' ids.
using IdIndex = FlatIndex<std::string_view, std::hash<std::string_view>>;

/// @param[in] objects  anything with an `id` (a plan's walls, openings, ...); must outlive the
///                     index, whose keys view their ids
/// @return each id's index among `objects`, the first where several share it. O(n) expected.
template <class Objects>
[[nodiscard]] IdIndex index_by_id(const Objects& objects) {
  IdIndex index(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i)
    index.try_emplace(objects[i].id, std::uint32_t(i));
  return index;
}

}  // namespace roomcad
