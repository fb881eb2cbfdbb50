// SPDX-License-Identifier: GPL-3.0-or-later
// 2D homogeneous transforms of a plan (lab 1 of the Tomsk State University manual "Laboratory works
// in computer graphics"), in the manual's ROW-VECTOR convention: a point is the row [x y 1] and
// maps to [x' y' 1] = [x y 1] * M, so the translation sits in the bottom row (m[2][0], m[2][1]) and
// `compose(a, b)` = a * b means "first a, then b".
//
// Decimal-exact arithmetic. Plans are written and typed as decimals ("1.1", "-0.35"), and the
// file stores each number as the shortest decimal that reads back to its double. So this type
// reads every double (point coordinates and matrix entries alike) AS THAT SHORTEST DECIMAL,
// computes each result exactly, and rounds it once to the nearest double. Consequences, each
// tested in tests/plan/transform2d_test.cpp:
//  - Results are correctly rounded: moving 0.1 by 0.2 gives 0.3 (double addition gives
//    0.30000000000000004).
//  - Exactly invertible edits: when every value involved (coordinates, entries, results) has at
//    most 15 significant digits, the exact decimal result reads back from its double unchanged
//    (15 = DBL_DIG), so a move then the opposite move, a scale by 2 then by 0.5, and four
//    quarter turns about ANY such point give back the same doubles, bit for bit. Beyond 15
//    digits the round trip may be off by one unit in the last place; nothing else is promised.
//  - Rotations by a multiple of 90 degrees use the exact cos/sin 0 and +-1, so they only move
//    and negate decimals: exact under the 15-digit condition above.
//  - Composed matrices round each entry; apply_exactly() evaluates a chain such as
//    T(-c) * R * T(c) without rounding between factors, so the centre of a turn stays put bit for
//    bit at any angle. Plan edits (plan/plan_edit.h) use chains.
//  - A zero result is +0 (decimal zero has no sign). NaN and infinities propagate as in double
//    arithmetic (the plan validator reports them).
#pragma once

#include <array>
#include <span>

#include "plan/plan.h"

namespace roomcad {

/// A 3x3 homogeneous 2D transform, row-vector convention (see the file comment).
struct Transform2d {
  std::array<std::array<double, 3>, 3> m{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
  friend bool operator==(const Transform2d&, const Transform2d&) = default;
};

/// @return the identity transform.
[[nodiscard]] Transform2d identity_transform();

/// @param[in] dx,dy shift in metres.
/// @return the translation [[1 0 0] [0 1 0] [dx dy 1]]. O(1).
[[nodiscard]] Transform2d translate(double dx, double dy);

/// Counter-clockwise rotation (x toward y) by `degrees` about `about`.
/// @param[in] degrees any finite angle; multiples of 90 use exact cos/sin in {0, 1, -1}.
/// @param[in] about   centre of rotation, metres.
/// @return T(-about) * R * T(about), entries rounded once each. O(1).
[[nodiscard]] Transform2d rotate(double degrees, Point2 about = {});

/// Uniform scale by `factor` about `about` (the seed scales about the origin; this composes
/// T(-about) * S * T(about)).
/// @return the scale transform. O(1). A factor of 0 or less is allowed here (callers refuse it
///         where it makes no sense).
[[nodiscard]] Transform2d scale(double factor, Point2 about = {});

/// @return a * b: apply `first`, then `then`. Each entry is the exact decimal dot product,
///         rounded once. O(1).
[[nodiscard]] Transform2d compose(const Transform2d& first, const Transform2d& then);

/// @return [p.x p.y 1] * t, each coordinate exact then rounded once. O(1).
[[nodiscard]] Point2 apply(const Transform2d& t, Point2 p);

/// @return [p.x p.y 1] * chain[0] * chain[1] * ..., computed exactly and rounded once at the
///         end. Unlike apply(compose(...)), whose composed entries are each rounded, a chain
///         keeps what the exact transform keeps: turning about c leaves c where it is, bit for
///         bit, at any angle. O(chain length), about a microsecond a matrix.
[[nodiscard]] Point2 apply_exactly(std::span<const Transform2d> chain, Point2 p);

/// @return {T(-about), linear, T(about)}: `linear` (which fixes the origin) acting about
///         `about`, as a chain for apply_exactly (rotate() and scale() compose it).
[[nodiscard]] std::array<Transform2d, 3> about_point(const Transform2d& linear, Point2 about);

/// @return [v.x v.y 0] * t: a direction, which translations do not move. O(1).
[[nodiscard]] Point2 apply_to_direction(const Transform2d& t, Point2 v);

/// @return the exact decimal value of a*b + c*d + ..., i.e. sum of a[i]*b[i], each double read
///         as its shortest decimal, rounded once to the nearest double. The primitive all the
///         functions above are built on, exposed for lengths along a wall (offset + du).
/// @pre a.size() == b.size(). Cost O(d^2) per term for d-digit numbers: about a microsecond.
[[nodiscard]] double exact_dot(std::span<const double> a, std::span<const double> b);

/// @return a + b, exactly in decimal, rounded once (see exact_dot).
[[nodiscard]] double exact_add(double a, double b);

/// @return true if `degrees` is a whole multiple of 90 (then rotate() is exact).
[[nodiscard]] bool is_quarter_turn(double degrees);

}  // namespace roomcad
