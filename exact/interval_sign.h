// SPDX-License-Identifier: GPL-3.0-or-later
// The sign a double interval proves, for the filters in front of exact arithmetic
// (exact_planes.cpp's predicates, lazy_radical.cpp's comparisons).
#pragma once

namespace roomcad::detail {

/// What interval_sign returns when the interval holds numbers of both signs.
inline constexpr int kUnknownSign = 2;

/// @param[in] x  an interval that holds the value (CGAL::Interval_nt, either protection)
/// @return -1, 0 or +1 when the interval proves it (a point interval at zero proves zero),
///         kUnknownSign when it holds 0 but is not 0. O(1).
template <class IntervalT>
int interval_sign(const IntervalT& x) {
  if (x.inf() > 0.0) return 1;
  if (x.sup() < 0.0) return -1;
  if (x.inf() == 0.0 && x.sup() == 0.0) return 0;
  return kUnknownSign;
}

}  // namespace roomcad::detail
