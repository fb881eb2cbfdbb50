// SPDX-License-Identifier: GPL-3.0-or-later
// Exact predicates on centre-line segments, behind a plain header (no CGAL here): what joins,
// validation and the importers decide contacts with.
// All are exact for the doubles given, including the tolerance comparisons (the distance
// is compared with the tolerance exactly, not after rounding).
#pragma once

#include "plan/plan.h"

namespace roomcad {

/// @return true if the closed segments a-b and c-d share a point. Exact. O(1).
[[nodiscard]] bool segments_meet(Point2 a, Point2 b, Point2 c, Point2 d);

/// @return true if the distance from p to the closed segment a-b is at most `tol`. Exact. O(1).
/// @pre a != b, tol >= 0.
[[nodiscard]] bool is_near_segment(Point2 p, Point2 a, Point2 b, double tol);

/// @return true if |p - q| <= tol. Exact. O(1).
[[nodiscard]] bool is_near_point(Point2 p, Point2 q, double tol);

/// @return true if segments a-b and c-d lie on one line and share a piece of positive length.
///         Exact. O(1). @pre a != b, c != d.
[[nodiscard]] bool overlap_collinearly(Point2 a, Point2 b, Point2 c, Point2 d);

/// @return true if the walls' height ranges (base, base + height) share a length: exactly,
///         for the sums as real numbers. Walls stacked on one another (storeys) do not. O(1).
[[nodiscard]] bool share_heights(const Wall& a, const Wall& b);

/// @return true if a-b and c-d are parallel (exactly: cross(b - a, d - c) == 0). O(1).
[[nodiscard]] bool are_parallel(Point2 a, Point2 b, Point2 c, Point2 d);

}  // namespace roomcad
