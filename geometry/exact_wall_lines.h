// SPDX-License-Identifier: GPL-3.0-or-later
// Walls in exact arithmetic: a wall's centre line and half-thickness normal, its side points
// and mitre corners, in any number type of exact/exact_predicates.h, so that validation and
// the solid kernel judge the very same corners. This header includes CGAL: include it only
// from the few .cpp files that need it.
#pragma once

#include <array>
#include <cstddef>

#include "exact/exact_predicates.h"
#include "geometry/joins.h"
#include "plan/plan.h"

namespace roomcad::exact {

/// The left normal of segment a->b scaled to length `half`: perp(b - a) * half / |b - a|.
/// @pre a != b.
template <class NT>
Pt<NT> scaled_left_normal(const Pt<NT>& a, const Pt<NT>& b, const NT& half) {
  const Pt<NT> d = b - a;
  const NT scale = half / root(dot(d, d));
  return {-d.y * scale, d.x * scale};
}

/// A wall's centre line and its half-thickness left normal, in NT.
template <class NT>
struct WallLine {
  Pt<NT> from;
  Pt<NT> to;
  Pt<NT> half_normal;  ///< left of from->to, length thickness / 2
};

template <class NT>
WallLine<NT> wall_line(const Wall& w) {
  const Pt<NT> a = to_pt<NT>(w.from);
  const Pt<NT> b = to_pt<NT>(w.to);
  return {a, b, scaled_left_normal(a, b, NT(w.thickness) / NT(2))};
}

/// Side of a wall: +1 left of from->to, -1 right.
template <class NT>
Pt<NT> side_point(const WallLine<NT>& w, WallEnd end, int side) {
  const Pt<NT>& p = end == WallEnd::from ? w.from : w.to;
  return side > 0 ? p + w.half_normal : p - w.half_normal;
}

/// The corner on `side` (+1 left, -1 right) of wall `mine` at `end`, mitred to wall `other` at
/// `other_end`: where this side line crosses the matching side line of `other`. Walking into
/// the joint along one wall and out along the other, left meets left and right meets right.
/// Parallel partners (a straight continuation) give a square end; see below for what counts
/// as parallel.
template <class NT>
Pt<NT> mitre_corner(const WallLine<NT>& mine, WallEnd end, const WallLine<NT>& other,
                    WallEnd other_end, int side) {
  // Travelling into the joint along `mine` reverses it at its from-end; leaving along
  // `other` reverses it at its to-end. Each reversal swaps left and right.
  const int other_side =
      side * (end == WallEnd::from ? -1 : 1) * (other_end == WallEnd::to ? -1 : 1);
  const Pt<NT> p = side_point(mine, end, side);
  const Pt<NT> q = side_point(other, other_end, other_side);
  const Pt<NT> d1 = mine.to - mine.from;
  const Pt<NT> d2 = other.to - other.from;
  // Parallel partners (a straight continuation) end square. Parallel is decided exactly: an
  // interval holding 0 throws Uncertain_conversion_exception (callers then construct the
  // corner exactly). Walls an ulp from parallel get their true mitre, which lies within an
  // ulp of the square end at equal thicknesses (at unequal ones it is out of kMitreReach,
  // so find_joins unites them). Deciding on the cross product rounded to doubles instead
  // took different branches in intervals (rounding upward) and in exact numbers for walls a
  // denormal apart.
  const NT turn = cross(d1, d2);
  if (turn == NT(0)) return p;
  return p + (cross(q - p, d2) / turn) * d1;
}

/// mitre_corner of walls `a` and `b` as drawn.
template <class NT>
Pt<NT> mitre_corner(const Wall& a, WallEnd end, const Wall& b, WallEnd b_end, int side) {
  return mitre_corner(wall_line<NT>(a), end, wall_line<NT>(b), b_end, side);
}

/// All four corners of wall `w` {from-right, to-right, to-left, from-left} (counter-clockwise),
/// each mitred per `joins` (mitre_corner) or square where its end is not mitred. Each wall's
/// line (a square root in exact types) is made once: the wall's own and one per mitred end.
template <class NT>
std::array<Pt<NT>, 4> wall_corners(const Plan& plan, const Joins& joins, std::size_t w) {
  const WallLine<NT> line = wall_line<NT>(plan.walls[w]);
  const auto end_corners = [&](WallEnd end) -> std::array<Pt<NT>, 2> {  // {right, left}
    const auto partner = joins.mitre[w][static_cast<int>(end)];
    if (!partner) return {side_point(line, end, -1), side_point(line, end, 1)};
    const WallEnd other_end = joins.mitre[*partner][0] == w ? WallEnd::from : WallEnd::to;
    const WallLine<NT> other = wall_line<NT>(plan.walls[*partner]);
    return {mitre_corner(line, end, other, other_end, -1),
            mitre_corner(line, end, other, other_end, 1)};
  };
  const std::array<Pt<NT>, 2> from = end_corners(WallEnd::from), to = end_corners(WallEnd::to);
  return {from[0], to[0], to[1], from[1]};
}

}  // namespace roomcad::exact
