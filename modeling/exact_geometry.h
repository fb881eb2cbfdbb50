// SPDX-License-Identifier: GPL-3.0-or-later
// Exact plane geometry for plan verdicts: filtered evaluation in any number type.
//
// A predicate is written once as a generic lambda over a number type NT and evaluated first
// in interval arithmetic; only when the intervals cannot decide (the shapes touch or nearly
// touch) is it evaluated again in 128-bit intervals (precise_interval.h), in which sums and
// products of doubles are exact, and only when those cannot either (a square root of an exact
// zero) in Radical (radical.h), which is exact for + - * / and the square roots of rationals
// and decides signs in a bounded number of rational operations. That last stage is lazy
// (lazy_radical.h): only the comparisons its double intervals cannot decide (the ties)
// evaluate their two sides in Radical.
// So wall corners, which involve the square root of a wall's squared length, are compared
// exactly for the coordinates as read at the cost of double arithmetic in all but touching
// cases, and never for long (CORE::Expr, used before, took minutes near degenerate shapes).
// Public for the modules that judge shapes (validation). This header includes CGAL: include it
// only from the few .cpp files that need it.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <CGAL/Interval_nt.h>

#include "modeling/detail/lazy_radical.h"
#include "modeling/detail/precise_interval.h"
#include "modeling/detail/radical.h"
#include "modeling/joins.h"
#include "modeling/plan.h"

namespace roomcad::exact {

using Approx = CGAL::Interval_nt<false>;  ///< needs upward rounding: see decide()
using Precise = PreciseInterval;          ///< 128-bit intervals (MPFR), any rounding mode
using Exact = Radical;
using LazyExact = LazyRadical;  ///< decide()'s last stage: Exact where intervals cannot tell

template <class NT>
struct Pt {
  NT x;
  NT y;
};

template <class NT>
Pt<NT> to_pt(const Point2& p) {
  return {NT(p.x), NT(p.y)};
}
template <class NT>
Pt<NT> operator+(const Pt<NT>& a, const Pt<NT>& b) {
  return {a.x + b.x, a.y + b.y};
}
template <class NT>
Pt<NT> operator-(const Pt<NT>& a, const Pt<NT>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class NT>
Pt<NT> operator*(const NT& s, const Pt<NT>& a) {
  return {s * a.x, s * a.y};
}
template <class NT>
NT dot(const Pt<NT>& a, const Pt<NT>& b) {
  return a.x * b.x + a.y * b.y;
}
template <class NT>
NT cross(const Pt<NT>& a, const Pt<NT>& b) {
  return a.x * b.y - a.y * b.x;
}

/// @return sqrt(x) in any of the number types here (CGAL's for doubles and intervals).
template <class NT>
NT root(const NT& x) {
  using CGAL::sqrt;
  return sqrt(x);
}

/// Evaluates `predicate(NT{})` exactly: in double intervals first, then in 128-bit ones, in
/// Radical (lazily: LazyExact) if neither can decide.
/// @param predicate  generic callable taking a number-type tag and returning a truth value
///                   (bool, or CGAL::Uncertain<bool> for intervals).
/// @return the exact verdict. Cost: a few double operations unless the case is degenerate;
///         then rational arithmetic bounded by the number of distinct roots (see radical.h).
template <class Predicate>
bool decide(Predicate&& predicate) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    try {
      return static_cast<bool>(predicate(Approx{}));
    } catch (const CGAL::Uncertain_conversion_exception&) {
      // The intervals straddle the decision: fall through to finer ones.
    }
  }
  try {
    return static_cast<bool>(predicate(Precise{}));
  } catch (const UndecidedComparison&) {
    // Still straddled (a root of an exact zero, or a tie): fall through to exact arithmetic.
  }
  const LazyExact::Scope scope;
  return static_cast<bool>(predicate(LazyExact{}));
}

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
Pt<NT> mitre_corner(const WallLine<NT>& mine, WallEnd end, const WallLine<NT>& other, WallEnd other_end,
                    int side) {
  // Travelling into the joint along `mine` reverses it at its from-end; leaving along
  // `other` reverses it at its to-end. Each reversal swaps left and right.
  const int other_side = side * (end == WallEnd::from ? -1 : 1) * (other_end == WallEnd::to ? -1 : 1);
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
    return {mitre_corner(line, end, other, other_end, -1), mitre_corner(line, end, other, other_end, 1)};
  };
  const std::array<Pt<NT>, 2> from = end_corners(WallEnd::from), to = end_corners(WallEnd::to);
  return {from[0], to[0], to[1], from[1]};
}

}  // namespace roomcad::exact
