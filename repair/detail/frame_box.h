// SPDX-License-Identifier: GPL-3.0-or-later
// A straight wall with a flat top as a box in the frame of a reference wall: s along the
// reference's centre line from its `from` end, n across it (to its left), z absolute. Two
// parallel walls drawn over one another are two such boxes; what one edit of one of them
// keeps of the union is read off the boxes (repair/detail/parallel_walls.h).
//
// Coordinates are doubles: s and n are rounded projections, exact for walls along the axes
// (a difference of coordinates, monotone in them). Where an edit claims to keep the union,
// repair_plan checks the claim on the exact analytic volume.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "plan/plan.h"

namespace roomcad::detail {

struct Extent {
  double lo = 0.0;
  double hi = 0.0;
  [[nodiscard]] bool contains(const Extent& e) const { return lo <= e.lo && e.hi <= hi; }
  [[nodiscard]] bool overlaps(const Extent& e) const { return lo < e.hi && e.lo < hi; }
  /// How far `e` reaches out of this extent, on either side (0 inside).
  [[nodiscard]] double excess(const Extent& e) const {
    return std::max({lo - e.lo, e.hi - hi, 0.0});
  }
};

/// A reference wall's centre line as an origin and a unit direction.
struct LineFrame {
  Point2 origin;
  Point2 unit;
  [[nodiscard]] double s(Point2 p) const {
    return (p.x - origin.x) * unit.x + (p.y - origin.y) * unit.y;
  }
  [[nodiscard]] double n(Point2 p) const {
    return (p.y - origin.y) * unit.x - (p.x - origin.x) * unit.y;
  }
  [[nodiscard]] Point2 at(double s) const { return {origin.x + s * unit.x, origin.y + s * unit.y}; }
};

struct FrameBox {
  Extent s, n, z;
  /// How far this box reaches out of `outer`: the length of the per-axis excesses.
  [[nodiscard]] double excess_over(const FrameBox& outer) const {
    return std::hypot(outer.s.excess(s), outer.n.excess(n), outer.z.excess(z));
  }
};

/// @return the frame of wall `w`'s centre line. @pre w has positive length.
[[nodiscard]] LineFrame line_frame(const Wall& w);

/// @return whether repairs may edit this wall as a box: straight, flat-topped, positive length
///         and thickness, finite.
[[nodiscard]] bool is_plain_wall(const Wall& w);

/// @return wall `w` as a box in `frame`: its centre line's extent along and across the frame,
///         widened by half its thickness across; z from base_z.
/// @pre is_plain_wall(w), and w parallel to the frame (else the box is not the wall's).
[[nodiscard]] FrameBox frame_box(const Plan& plan, const LineFrame& frame, const Wall& w);

/// @return whether the two walls' centre lines lie on one line. Exact.
[[nodiscard]] bool on_one_line(const Wall& a, const Wall& b);

/// @return the length of wall `w`'s centre line.
[[nodiscard]] double wall_length(const Wall& w);

}  // namespace roomcad::detail
