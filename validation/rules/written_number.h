// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers as written in the plan, for the exact verdicts of the rule sets.
//
// A plan's numbers are read to the nearest double. The base checks decide on those doubles;
// the rules decide on the numbers as a person or a tool wrote them, so that a passage drawn
// exactly 0.90 m wide is not 3e-17 m narrower than a 0.90 m threshold, and a door leaf that
// exactly reaches a wall face touches it rather than hitting it:
//  - a double that is a multiple of 2^-30 (integers, halves, and every number an importer
//    puts on a binary grid) is taken as that binary value;
//  - any other double is taken as its shortest decimal (0.1 is one tenth), the text that
//    reads back to it.
// WrittenApprox holds an interval around that value (the double, widened by one ulp when the
// value is a decimal), WrittenExact the value itself as an exact::Radical. decide_written
// evaluates a predicate in the first and, if the intervals cannot decide, in the second: the
// verdict is exact for the written numbers. Includes CGAL: for the rule sources only.
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>

#include <CGAL/Interval_nt.h>

#include "geometry/exact_wall_lines.h"

namespace roomcad::rules {

/// @return true if x is a multiple of 2^-30 (taken as its binary value). O(1).
[[nodiscard]] bool is_binary_grid(double x);

/// An interval holding a written number. Arithmetic is interval arithmetic (needs upward
/// rounding: see decide_written); comparisons give CGAL::Uncertain<bool>.
class WrittenApprox {
 public:
  WrittenApprox() = default;
  WrittenApprox(double x);                          // NOLINT: a number type, like double
  WrittenApprox(const exact::Approx& v) : v_(v) {}  // NOLINT: results of arithmetic
  [[nodiscard]] const exact::Approx& value() const { return v_; }

  friend WrittenApprox operator+(const WrittenApprox& a, const WrittenApprox& b) {
    return a.v_ + b.v_;
  }
  friend WrittenApprox operator-(const WrittenApprox& a, const WrittenApprox& b) {
    return a.v_ - b.v_;
  }
  friend WrittenApprox operator*(const WrittenApprox& a, const WrittenApprox& b) {
    return a.v_ * b.v_;
  }
  friend WrittenApprox operator/(const WrittenApprox& a, const WrittenApprox& b) {
    return a.v_ / b.v_;
  }
  WrittenApprox operator-() const { return -v_; }
  friend auto operator<(const WrittenApprox& a, const WrittenApprox& b) { return a.v_ < b.v_; }
  friend auto operator>(const WrittenApprox& a, const WrittenApprox& b) { return a.v_ > b.v_; }
  friend auto operator<=(const WrittenApprox& a, const WrittenApprox& b) { return a.v_ <= b.v_; }
  friend auto operator>=(const WrittenApprox& a, const WrittenApprox& b) { return a.v_ >= b.v_; }
  friend auto operator==(const WrittenApprox& a, const WrittenApprox& b) { return a.v_ == b.v_; }
  friend auto operator!=(const WrittenApprox& a, const WrittenApprox& b) { return a.v_ != b.v_; }
  friend WrittenApprox sqrt(const WrittenApprox& a) { return CGAL::sqrt(a.v_); }
  /// @return the interval hull of a and b (no decision needed).
  friend WrittenApprox lesser(const WrittenApprox& a, const WrittenApprox& b) {
    return CGAL::min(a.v_, b.v_);
  }
  friend WrittenApprox greater(const WrittenApprox& a, const WrittenApprox& b) {
    return CGAL::max(a.v_, b.v_);
  }

 private:
  exact::Approx v_;
};

/// A written number, exactly. Values must not outlive the exact::Radical::Scope they were
/// made in (decide_written opens one).
class WrittenExact {
 public:
  WrittenExact() = default;
  WrittenExact(double x);                           // NOLINT: a number type, like double
  WrittenExact(const exact::Radical& v) : v_(v) {}  // NOLINT: results of arithmetic
  [[nodiscard]] const exact::Radical& value() const { return v_; }

  friend WrittenExact operator+(const WrittenExact& a, const WrittenExact& b) {
    return a.v_ + b.v_;
  }
  friend WrittenExact operator-(const WrittenExact& a, const WrittenExact& b) {
    return a.v_ - b.v_;
  }
  friend WrittenExact operator*(const WrittenExact& a, const WrittenExact& b) {
    return a.v_ * b.v_;
  }
  friend WrittenExact operator/(const WrittenExact& a, const WrittenExact& b) {
    return a.v_ / b.v_;
  }
  WrittenExact operator-() const { return -v_; }
  friend bool operator<(const WrittenExact& a, const WrittenExact& b) { return a.v_ < b.v_; }
  friend bool operator>(const WrittenExact& a, const WrittenExact& b) { return a.v_ > b.v_; }
  friend bool operator<=(const WrittenExact& a, const WrittenExact& b) { return a.v_ <= b.v_; }
  friend bool operator>=(const WrittenExact& a, const WrittenExact& b) { return a.v_ >= b.v_; }
  friend bool operator==(const WrittenExact& a, const WrittenExact& b) { return a.v_ == b.v_; }
  friend bool operator!=(const WrittenExact& a, const WrittenExact& b) { return a.v_ != b.v_; }
  friend WrittenExact sqrt(const WrittenExact& a) { return sqrt(a.v_); }
  friend WrittenExact lesser(const WrittenExact& a, const WrittenExact& b) { return a < b ? a : b; }
  friend WrittenExact greater(const WrittenExact& a, const WrittenExact& b) {
    return a < b ? b : a;
  }

 private:
  exact::Radical v_;
};

/// Extremes of doubles, for the approximate pass of fix searches (evaluate below).
inline double lesser(double a, double b) { return a < b ? a : b; }
inline double greater(double a, double b) { return a < b ? b : a; }

/// The truth of a comparison in NT: CGAL::Uncertain<bool> for intervals, bool when exact.
/// Combine truths with | and & (not || and &&, which would force a decision on each).
template <class NT>
using Truth = decltype(std::declval<NT>() < std::declval<NT>());

/// @return true if t is certainly true (an uncertain truth is not).
template <class T>
bool is_surely(const T& t) {
  return CGAL::is_certain(t) && CGAL::get_certain(t);
}

/// @return the double x itself (not a written number) in NT: for points the rules compute,
///         such as a candidate centre of a free circle.
template <class NT>
NT computed(double x) {
  if constexpr (std::is_same_v<NT, double>) return x;
  else if constexpr (std::is_same_v<NT, WrittenApprox>) return NT(exact::Approx(x));
  else return NT(exact::Radical(x));
}

/// Evaluates `predicate(NT{})` for the written numbers: in WrittenApprox, then in
/// WrittenExact if the intervals cannot decide (see exact::decide).
/// @return the exact verdict. Cost: a few interval operations unless the case is degenerate.
template <class Predicate>
bool decide_written(Predicate&& predicate) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    try {
      return static_cast<bool>(predicate(WrittenApprox{}));
    } catch (const CGAL::Uncertain_conversion_exception&) {
      // The intervals straddle the decision: fall through to exact arithmetic.
    }
  }
  const exact::Radical::Scope scope;
  return static_cast<bool>(predicate(WrittenExact{}));
}

/// How a predicate is evaluated: exactly (decide_written), or in plain doubles, to sort out
/// candidates quickly in searches whose pick is then verified exactly.
enum class Precision : std::uint8_t { approximate, exact };

/// @return predicate(double{}) or decide_written(predicate), as asked.
template <class Predicate>
bool evaluate(Precision precision, Predicate&& predicate) {
  if (precision == Precision::approximate) return static_cast<bool>(predicate(0.0));
  return decide_written(std::forward<Predicate>(predicate));
}

}  // namespace roomcad::rules
