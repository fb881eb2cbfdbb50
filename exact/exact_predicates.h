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
// Public for the modules that judge shapes (geometry, validation, solid). This header includes
// CGAL: include it only from the few .cpp files that need it.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <CGAL/Interval_nt.h>

#include "exact/lazy_radical.h"
#include "exact/precise_interval.h"
#include "exact/radical.h"

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

/// Any point with members x and y (a plan's Point2) in NT.
template <class NT, class Point>
Pt<NT> to_pt(const Point& p) {
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

}  // namespace roomcad::exact
