// SPDX-License-Identifier: GPL-3.0-or-later
// PreciseInterval: an interval of 128-bit binary floats (MPFR, every bound rounded outward)
// that holds an exact real number, a number type for the templates of exact_predicates.h: the
// middle filter of exact::decide, between double intervals and exact Radical numbers.
//
// Why: a wall corner that is not a double (a skewed wall's mitre: square roots of the walls'
// squared lengths) must be rounded to its nearest double exactly. Exact arithmetic (Radical,
// radical.h) does that at the cost of rational numbers and their gcds, tens of microseconds a
// wall; 128 bits hold the corner to about 2^-120 of itself, so its nearest double is known
// at once unless the corner lies that close to a midpoint between two doubles (ties, which
// are exact numbers: then Radical decides). Likewise a predicate on shapes that touch: sums and
// products of a plan's doubles are exact at 128 bits, so "exactly zero" is a single number
// here, where double intervals straddle it. A comparison the interval cannot decide throws
// UndecidedComparison, so a template takes no branch the exact numbers would not take.
//
// Cost: two MPFR operations per operation (no allocation: the bounds' limbs live inside the
// value), about 0.1 us.
#pragma once

#include <gmp.h>
#include <mpfr.h>

#include <optional>
#include <stdexcept>

namespace roomcad::exact {

/// Thrown when an interval comparison cannot be decided (the intervals overlap), or a
/// division by or a root of an interval holding 0 or negative numbers is asked for.
class UndecidedComparison : public std::runtime_error {
 public:
  UndecidedComparison() : std::runtime_error("PreciseInterval: undecided") {}
};

class PreciseInterval {
 public:
  static constexpr mpfr_prec_t kBits = 128;

  PreciseInterval();          ///< zero
  PreciseInterval(double x);  // NOLINT(google-explicit-constructor): a number type, like double
  PreciseInterval(const PreciseInterval& other);
  PreciseInterval& operator=(const PreciseInterval& other);

  friend PreciseInterval operator+(const PreciseInterval& a, const PreciseInterval& b);
  friend PreciseInterval operator-(const PreciseInterval& a, const PreciseInterval& b);
  friend PreciseInterval operator*(const PreciseInterval& a, const PreciseInterval& b);
  /// @throws UndecidedComparison if b holds 0.
  friend PreciseInterval operator/(const PreciseInterval& a, const PreciseInterval& b);
  PreciseInterval operator-() const;
  /// @throws UndecidedComparison if x may be negative.
  friend PreciseInterval sqrt(const PreciseInterval& x);

  /// @return whether the numbers are equal. @throws UndecidedComparison unless the intervals
  ///         are apart or are the same single number.
  friend bool operator==(const PreciseInterval& a, const PreciseInterval& b);
  friend bool operator!=(const PreciseInterval& a, const PreciseInterval& b) { return !(a == b); }
  /// @return whether a < b. @throws UndecidedComparison unless the intervals are apart, or a
  ///         and b are the same single number.
  friend bool operator<(const PreciseInterval& a, const PreciseInterval& b);
  friend bool operator>(const PreciseInterval& a, const PreciseInterval& b) { return b < a; }
  friend bool operator<=(const PreciseInterval& a, const PreciseInterval& b) { return !(b < a); }
  friend bool operator>=(const PreciseInterval& a, const PreciseInterval& b) { return !(a < b); }

  /// @return the double nearest to the number, when the whole interval lies strictly between
  ///         the midpoints around one finite double; else nothing. O(1).
  [[nodiscard]] std::optional<double> nearest_double() const;

 private:
  static constexpr int kLimbs = (kBits + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS;
  using Operation = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
  void init();
  /// [min, max] of op over the corners of a x b, rounded outward (op: mpfr_mul or mpfr_div).
  static PreciseInterval corner_hull(const PreciseInterval& a, const PreciseInterval& b,
                                     Operation op);
  /// [op(low_x, low_y) rounded down, op(high_x, high_y) rounded up]: the result when the
  /// operands' signs tell which corners bound it.
  static PreciseInterval between_corners(Operation op, mpfr_srcptr low_x, mpfr_srcptr low_y,
                                         mpfr_srcptr high_x, mpfr_srcptr high_y);
  mp_limb_t lo_limbs_[kLimbs];
  mp_limb_t hi_limbs_[kLimbs];
  mpfr_t lo_, hi_;
};

/// @return the double nearest to every number in [lo, hi], when [lo, hi] lies strictly between
///         the midpoints around one finite double (so ties, and numbers within the interval's
///         width of one, are left to exact arithmetic); else nothing. O(1).
[[nodiscard]] std::optional<double> nearest_double_if_clear(mpfr_srcptr lo, mpfr_srcptr hi);

}  // namespace roomcad::exact
