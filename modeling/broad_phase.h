// SPDX-License-Identifier: GPL-3.0-or-later
// Broad phase: which axis-aligned boxes meet, without testing all pairs.
//
// Every pairwise check of the plan (joins, overlaps, blocked openings) first narrows the pairs
// to those whose bounding boxes meet, so the cost grows like n log n + k, not n^2.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace roomcad {

/// A closed axis-aligned box in the plane, in metres, tagged with the caller's index.
struct Box2 {
  double min_x = 0.0;
  double min_y = 0.0;
  double max_x = 0.0;
  double max_y = 0.0;
  std::size_t index = 0;  ///< the caller's object index, reported in the pairs
};

using IndexPairs = std::vector<std::pair<std::size_t, std::size_t>>;

/// Finds every pair of boxes that meet (boundaries included: closed boxes).
/// @param[in] boxes  finite boxes with min <= max; indices need not be dense but must be unique.
/// @return pairs (first < second) of the boxes' indices, sorted, each pair once.
///         O(n log^2 n + k) for n boxes and k pairs (CGAL box_intersection_d segment tree).
[[nodiscard]] IndexPairs find_meeting_boxes(const std::vector<Box2>& boxes);

/// Finds every pair (a, b) with a from `left` and b from `right` whose boxes meet.
/// @return pairs (left index, right index), sorted. O((n + m) log^2 (n + m) + k).
[[nodiscard]] IndexPairs find_meeting_boxes(const std::vector<Box2>& left,
                                            const std::vector<Box2>& right);

/// @return the box of segment a-b grown by `margin` on every side (rounded outward, so
///         that every point within `margin` of the segment lies inside). Index 0.
[[nodiscard]] Box2 grown_segment_box(double ax, double ay, double bx, double by, double margin);

}  // namespace roomcad
