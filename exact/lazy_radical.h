// SPDX-License-Identifier: GPL-3.0-or-later
// A Radical computed only when a comparison needs it: each value carries a double interval
// and the expression that made it; a sign or comparison that its interval decides costs an
// interval operation, and one that it cannot decide (an exact tie, or values within the
// interval's width of each other) evaluates the expressions of its two sides in Radical,
// once per value (the result is kept).
//
// Why: exact::decide reaches its exact stage when two shapes touch, and then one comparison
// or two of the predicate are exact ties; the dozens of others (which corner of a quad is
// the lowest along an axis, say) are far apart. Evaluating all of them in Radical made
// `validate --rules all` on a 304-wall real home spend most of its time in rational
// arithmetic for comparisons that double intervals decide (validation/detail/shapes.h).
//
// Values are handles to expression nodes that live in a per-thread arena until the
// LazyRadical::Scope they were made in ends (no reference counts: a predicate makes hundreds
// of values and drops them all at once). Preconditions as Radical's (a non-zero divisor, the
// root of a rational); a violation throws std::domain_error when the value is evaluated, not
// when it is made.
#pragma once

#include <compare>
#include <cstddef>

#include "exact/radical.h"

namespace roomcad::exact {

class LazyRadical {
 public:
  /// Frees on exit the values made since entry (and the radicands their evaluation
  /// registered): values must not outlive it, and are made only inside one. Scopes nest.
  class Scope {
   public:
    Scope();
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    Radical::Scope radicands_;
    std::size_t entry_size_;
  };

  LazyRadical() : LazyRadical(0.0) {}
  LazyRadical(double x);  // NOLINT(google-explicit-constructor): a number type, like double

  friend LazyRadical operator+(const LazyRadical& a, const LazyRadical& b);
  friend LazyRadical operator-(const LazyRadical& a, const LazyRadical& b);
  friend LazyRadical operator*(const LazyRadical& a, const LazyRadical& b);
  friend LazyRadical operator/(const LazyRadical& a, const LazyRadical& b);
  LazyRadical operator-() const;
  friend LazyRadical sqrt(const LazyRadical& x);

  /// @return -1, 0 or +1, exactly. Cost: an interval test; evaluation when it cannot tell.
  friend int sign(const LazyRadical& x);
  /// @return the sign of a - b, exactly, without making a - b unless the intervals overlap.
  friend int compare(const LazyRadical& a, const LazyRadical& b);

  /// @return the value in Radical, evaluated now if it was not before. Cost: one Radical
  ///         operation per sub-expression not yet evaluated.
  [[nodiscard]] const Radical& exact() const;
  /// @return whether exact() has been evaluated (for tests of the laziness).
  [[nodiscard]] bool is_evaluated() const;

  struct Node;         ///< an expression node (lazy_radical.cpp)
  struct FromNode {};  ///< a tag, so that NT(0) does not read as a null node
  LazyRadical(FromNode, const Node* node) : node_(node) {}

 private:
  const Node* node_;  ///< in the arena of the innermost Scope
};

/// Every comparison operator, from compare().
inline std::strong_ordering operator<=>(const LazyRadical& a, const LazyRadical& b) {
  return compare(a, b) <=> 0;
}
inline bool operator==(const LazyRadical& a, const LazyRadical& b) { return compare(a, b) == 0; }

}  // namespace roomcad::exact
