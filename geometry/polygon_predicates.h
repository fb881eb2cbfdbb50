// SPDX-License-Identifier: GPL-3.0-or-later
// Exact verdicts on polygons given by double coordinates (slab areas, opening outlines): CGAL's
// exact rationals, and its Boolean set operations through detail::ExactPolygonSet; and the
// one construction repairs need, an area's difference, rounded once to doubles.
#pragma once

#include <vector>

#include "plan/plan.h"

namespace roomcad {

/// @return whether `polygon` is simple (no edge meets another except its neighbours at their
///         shared corner) and has at least 3 corners. Exact. O(n log n).
[[nodiscard]] bool is_simple_polygon(const Polygon& polygon);

/// @return whether `inner` lies strictly inside `outer` (no common point of their boundaries).
/// @pre both simple. Exact. O(n m).
[[nodiscard]] bool is_strictly_inside(const Polygon& inner, const Polygon& outer);

/// @return whether two simple polygons share no point (boundaries included). Exact. O(n m).
[[nodiscard]] bool are_disjoint(const Polygon& a, const Polygon& b);

/// @return whether the areas `a` (outline minus holes) and `b` share interior area (touching
/// is not sharing). @pre outlines and holes simple, holes strictly inside and disjoint.
/// Exact. O((n + m) log (n + m)) plus the size of the intersection.
[[nodiscard]] bool areas_overlap(const Polygon& a, const std::vector<Polygon>& a_holes,
                                 const Polygon& b, const std::vector<Polygon>& b_holes);

/// @return whether the outlines of two openings of one wall (their `shape`, or their
/// rectangle, in the wall's (u, v) frame) share interior area. Exact. @pre shapes simple.
[[nodiscard]] bool outlines_overlap(const Opening& a, const Opening& b);

/// An area of the plane: an outline (counter-clockwise) minus its holes (clockwise).
struct Area {
  Polygon outline;
  std::vector<Polygon> holes;
};

/// @return the pieces of area `a` outside area `b`, computed exactly, each corner then rounded
///         to the nearest double. @pre as areas_overlap. O((n + m) log (n + m) + k).
[[nodiscard]] std::vector<Area> area_difference(const Polygon& a,
                                                const std::vector<Polygon>& a_holes,
                                                const Polygon& b,
                                                const std::vector<Polygon>& b_holes);

}  // namespace roomcad
