// SPDX-License-Identifier: GPL-3.0-or-later
// Exact real numbers of the form sum_S c_S * prod_{i in S} sqrt(s_i): rational coefficients
// c_S (GMP) times products of square roots of rational radicands s_i. Wall corners live
// there: a half-thickness normal is perp(d) * t / (2 sqrt(d.d)), and every other operation
// in the plan predicates is + - * or a division by a rational or by such a root.
//
// Why not CORE::Expr: deciding that a CORE expression is zero means refining it to its root
// separation bound, which near degenerate shapes (a window flush with a mitred corner,
// turned and a million metres away) takes minutes. Here the sign of a + b sqrt(s) is decided
// from the signs of a, b and a^2 - b^2 s, recursively over the roots: a bounded amount of
// rational arithmetic (at most 3^k sign evaluations for k distinct roots, k <= 6 or so in a
// plan predicate), with no refinement at all.
//
// Radicands are registered per thread in a table that a Radical::Scope trims on exit: values
// must not outlive their scope. A new radicand whose root is a rational multiple of a
// product of earlier roots is written as that product, so the representation is canonical
// (zero has no terms) and every non-zero value can be inverted.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace roomcad::exact {

class Radical {
 public:
  /// Drops on exit the radicands registered since entry: values made inside a scope must
  /// not outlive it. Scopes nest.
  class Scope {
   public:
    Scope();
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    std::size_t entry_size_;
  };

  Radical() = default;
  Radical(double x);  // NOLINT(google-explicit-constructor): a number type, like double
  /// @pre x is finite.

  friend Radical operator+(const Radical& a, const Radical& b);
  friend Radical operator-(const Radical& a, const Radical& b);
  friend Radical operator*(const Radical& a, const Radical& b);
  /// @pre b != 0 (throws std::domain_error otherwise). Cost: one rational inverse per root.
  friend Radical operator/(const Radical& a, const Radical& b);
  Radical operator-() const;

  /// @return -1, 0 or +1, exactly. Cost: one interval evaluation, and when that cannot tell
  /// (x is zero or very near it) up to 3^k rational products for k roots in x.
  friend int sign(const Radical& x);

  /// @return sqrt(x). @pre x is rational (no roots in it) and x >= 0; throws otherwise.
  friend Radical sqrt(const Radical& x);

  /// @return an interval [lo, hi] of doubles that holds x (a few ulps wide unless the terms
  ///         cancel). Cost: one interval evaluation per term.
  friend std::pair<double, double> to_interval(const Radical& x);

  /// @return the double nearest to x when bounds of x at 192 bits (MPFR, rounded outward)
  ///         lie strictly between the midpoints around one double, else nothing (x within
  ///         2^-190 or so of a midpoint: nearest_double_if_clear, precise_interval.h).
  ///         Cost: a few MPFR operations per term.
  friend std::optional<double> round_if_clear(const Radical& x);

 private:
  using Mask = std::uint64_t;                      ///< bit i: the term has the factor sqrt(s_i)
  std::vector<std::pair<Mask, mpq_class>> terms_;  ///< by increasing mask, no zero coefficient

  static Radical from_terms(std::vector<std::pair<Mask, mpq_class>> terms);
  friend Radical scaled_root(const mpq_class& c, Mask m);
};

inline bool operator<(const Radical& a, const Radical& b) { return sign(a - b) < 0; }
inline bool operator>(const Radical& a, const Radical& b) { return sign(a - b) > 0; }
inline bool operator<=(const Radical& a, const Radical& b) { return sign(a - b) <= 0; }
inline bool operator>=(const Radical& a, const Radical& b) { return sign(a - b) >= 0; }
inline bool operator==(const Radical& a, const Radical& b) { return sign(a - b) == 0; }
inline bool operator!=(const Radical& a, const Radical& b) { return sign(a - b) != 0; }

/// @return the double nearest to x, ties to the lower one. Cost: a few MPFR operations
/// (round_if_clear); about 64 exact comparisons in the rare case that cannot tell.
double round_to_nearest(const Radical& x);

}  // namespace roomcad::exact
