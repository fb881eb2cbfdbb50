// SPDX-License-Identifier: GPL-3.0-or-later
// Broad phase: which axis-aligned boxes meet, without testing all pairs.
//
// Every pairwise check of the plan (joins, overlaps, blocked openings) first narrows the pairs
// to those whose bounding boxes meet, so the cost grows like n log n + k, not n^2.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "core/box.h"

namespace roomcad {

/// A closed box in space, in metres: a box in plan and a height range (the extent of a wall or
/// a slab). A wall meets those of the storeys above and below it in plan alone.
struct SpaceBox {
  Box2 plan;  ///< its index is the caller's object index
  double min_z = 0.0;
  double max_z = 0.0;
};

using IndexPairs = std::vector<std::pair<std::size_t, std::size_t>>;

/// Finds every pair of boxes that meet (boundaries included: closed boxes). Below 2048 boxes
/// (a home's walls) a sweep along the axis where they overlap least, testing each box against
/// those still open there: O(n log n + n m + k) for m open at a time, at most n^2 / 2 tests
/// (bench/broad_phase_bench: 2.1-2.7x faster than the segment tree on arif-putra-pertama-1's
/// 304 walls, 1.4x slower on the tower's 504 in space, whose rooms overlap along every axis).
/// From 2048 on, CGAL's box_intersection_d segment tree.
/// @param[in] boxes  finite boxes with min <= max; indices need not be dense but must be unique.
/// @return pairs (first < second) of the boxes' indices, sorted, each pair once.
///         O(n log^2 n + k) for n boxes and k pairs from 2048 boxes on.
[[nodiscard]] IndexPairs find_meeting_boxes(const std::vector<Box2>& boxes);

/// Finds every pair (a, b) with a from `left` and b from `right` whose boxes meet (a sweep below
/// 2048 boxes in all, each box tested against the other side's open ones).
/// @return pairs (left index, right index), sorted. O((n + m) log^2 (n + m) + k) from 2048 on.
[[nodiscard]] IndexPairs find_meeting_boxes(const std::vector<Box2>& left,
                                            const std::vector<Box2>& right);

/// Finds every pair of boxes that meet in space (boundaries included), as the overloads for
/// Box2 do in plan. O(n log^3 n + k).
[[nodiscard]] IndexPairs find_meeting_boxes(const std::vector<SpaceBox>& boxes);
[[nodiscard]] IndexPairs find_meeting_boxes(const std::vector<SpaceBox>& left,
                                            const std::vector<SpaceBox>& right);

/// @return the box of segment a-b grown by `margin` on every side (rounded outward, so
///         that every point within `margin` of the segment lies inside). Index 0.
[[nodiscard]] Box2 grown_segment_box(double ax, double ay, double bx, double by, double margin);

/// @return the plan box with the closed height range spanning z0 and z1 (either order),
///         rounded outward by a step, so that it holds every height between them; the whole
///         line where either is not finite.
[[nodiscard]] SpaceBox space_box(const Box2& plan, double z0, double z1);

}  // namespace roomcad
