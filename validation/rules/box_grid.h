// SPDX-License-Identifier: GPL-3.0-or-later
// A uniform grid of boxes for one-at-a-time queries ("which walls are near this door?") while
// searching for fixes; batches of queries use find_meeting_boxes (geometry/broad_phase.h).
#pragma once

#include <cstddef>
#include <unordered_map>
#include <vector>

#include "geometry/broad_phase.h"

namespace roomcad::rules {

class BoxGrid {
 public:
  BoxGrid() = default;
  /// Indexes boxes (Box2::index is reported by queries) in square cells of about the mean
  /// box size. O(n) for boxes of about that size.
  explicit BoxGrid(std::vector<Box2> boxes);

  /// @return the indices of the boxes that meet `query` (closed), sorted, each once.
  ///         O(cells covered + boxes found).
  [[nodiscard]] std::vector<std::size_t> find(const Box2& query) const;

 private:
  [[nodiscard]] long long cell_of(double v) const;
  [[nodiscard]] static long long key_of(long long cx, long long cy) { return cx * 2654435761LL ^ cy; }

  std::vector<Box2> boxes_;
  double cell_ = 1.0;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;  ///< cell -> positions in boxes_
  std::vector<std::size_t> big_;  ///< boxes over too many cells, checked by every query
};

}  // namespace roomcad::rules
