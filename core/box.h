// SPDX-License-Identifier: GPL-3.0-or-later
// Axis-aligned boxes, the one pair of box types every module shares: Box2 in the plane (plan
// boxes, a picture's boxes, a plane's view) and Box3 in space. Both are closed. A bound that
// is NaN (the bounds of an exact point's interval may be) makes a box meet every box:
// candidates are never lost, only tested.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

namespace roomcad {

/// A closed box in the plane, tagged with the caller's index (reported by the broad phase and
/// the box grid). Empty when a min is above its max (empty_box2()).
struct Box2 {
  double min_x = 0.0;
  double min_y = 0.0;
  double max_x = 0.0;
  double max_y = 0.0;
  std::size_t index = 0;  ///< the caller's object index
};

/// @return the box that holds nothing, which add_point grows. O(1).
[[nodiscard]] inline Box2 empty_box2() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {inf, inf, -inf, -inf, 0};
}

/// @return whether the box holds no point (a min above its max). O(1).
[[nodiscard]] inline bool is_empty(const Box2& b) { return b.min_x > b.max_x || b.min_y > b.max_y; }

/// Grows `b` to hold (x, y). O(1).
inline void add_point(Box2& b, double x, double y) {
  b.min_x = std::min(b.min_x, x), b.min_y = std::min(b.min_y, y);
  b.max_x = std::max(b.max_x, x), b.max_y = std::max(b.max_y, y);
}

/// @return the smallest box holding both (an empty one adds nothing); a's index. O(1).
[[nodiscard]] inline Box2 merged(Box2 a, const Box2& b) {
  if (is_empty(b)) return a;
  add_point(a, b.min_x, b.min_y);
  add_point(a, b.max_x, b.max_y);
  return a;
}

/// @return whether closed boxes a and b share a point; true where a bound is NaN. O(1).
[[nodiscard]] inline bool boxes_meet(const Box2& a, const Box2& b) {
  return !(a.max_x < b.min_x || b.max_x < a.min_x || a.max_y < b.min_y || b.max_y < a.min_y);
}

/// A closed box in space: low and high corners.
struct Box3 {
  std::array<double, 3> low{}, high{};
};

/// @return the box that holds nothing, which add_point grows. O(1).
[[nodiscard]] inline Box3 empty_box3() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {{inf, inf, inf}, {-inf, -inf, -inf}};
}

/// @return whether the box holds no point (a low above its high). O(1).
[[nodiscard]] inline bool is_empty(const Box3& b) {
  return b.low[0] > b.high[0] || b.low[1] > b.high[1] || b.low[2] > b.high[2];
}

/// Grows `b` to hold (x, y, z). O(1).
inline void add_point(Box3& b, double x, double y, double z) {
  const std::array<double, 3> p{x, y, z};
  for (std::size_t k = 0; k < 3; ++k)
    b.low[k] = std::min(b.low[k], p[k]), b.high[k] = std::max(b.high[k], p[k]);
}

/// @return whether closed boxes a and b share a point; true where a bound is NaN. O(1).
[[nodiscard]] inline bool boxes_meet(const Box3& a, const Box3& b) {
  for (std::size_t k = 0; k < 3; ++k)
    if (a.high[k] < b.low[k] || b.high[k] < a.low[k]) return false;
  return true;
}

}  // namespace roomcad
