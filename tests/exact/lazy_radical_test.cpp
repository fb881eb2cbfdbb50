// SPDX-License-Identifier: GPL-3.0-or-later
// exact::LazyRadical: the same signs as Radical, with Radical evaluated only for the
// comparisons that double intervals cannot decide.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "exact/lazy_radical.h"
#include "support/invariant.h"

namespace roomcad::exact {
namespace {

TEST(LazyRadical, ComparisonsTheIntervalsDecideEvaluateNothing) {
  const LazyRadical::Scope scope;
  const LazyRadical a = sqrt(LazyRadical(2)) * LazyRadical(3);
  const LazyRadical b = sqrt(LazyRadical(3)) + LazyRadical(2.5);
  EXPECT_GT(a, b);  // 4.24264 against 4.23205
  EXPECT_GT(a - b, LazyRadical(0.0105));
  EXPECT_LT(a - b, LazyRadical(0.0106));
  EXPECT_EQ(sign(-a), -1);
  EXPECT_FALSE(a.is_evaluated());
  EXPECT_FALSE(b.is_evaluated());
}

TEST(LazyRadical, TiesAreDecidedExactly) {
  const LazyRadical::Scope scope;
  const LazyRadical r2 = sqrt(LazyRadical(2)), r3 = sqrt(LazyRadical(3));
  const LazyRadical product = r2 * r3, r6 = sqrt(LazyRadical(6));
  EXPECT_EQ(product, r6);  // the intervals overlap: both sides are evaluated
  EXPECT_TRUE(product.is_evaluated());
  EXPECT_TRUE(r6.is_evaluated());
  EXPECT_EQ(sign(product - r6), 0);
  const LazyRadical third = LazyRadical(1) / LazyRadical(3);
  EXPECT_EQ(third * LazyRadical(3), LazyRadical(1));  // 1/3 is no double: only Radical says equal
  EXPECT_LE(third * LazyRadical(3), LazyRadical(1));
  EXPECT_FALSE(third * LazyRadical(3) < LazyRadical(1));
  // A difference that cancels below the intervals' width, not to zero.
  const double x = 1e15;
  const LazyRadical s = sqrt(LazyRadical(x) * LazyRadical(x) + LazyRadical(1));
  EXPECT_GT(s, LazyRadical(x));
  EXPECT_LT(s - LazyRadical(x), LazyRadical(1e-15));
}

TEST(LazyRadical, ABadDivisionBreaksAnInvariantWhenEvaluated) {
  const LazyRadical::Scope scope;
  const LazyRadical q =
      LazyRadical(1) / (sqrt(LazyRadical(2)) * sqrt(LazyRadical(2)) - LazyRadical(2));
  EXPECT_INVARIANT_BROKEN((void)sign(q));
}

/// A random expression built in both number types at once.
struct Both {
  LazyRadical lazy;
  Radical exact;
};

Both random_value(std::mt19937_64& rng, int depth) {
  std::uniform_int_distribution<int> pick(0, 5);
  std::uniform_int_distribution<int> small(-4, 4);
  const int op = depth == 0 ? 0 : pick(rng);
  if (op == 0) {
    const double x = small(rng) * 0.25;
    return {LazyRadical(x), Radical(x)};
  }
  if (op == 1) {  // the root of a small rational: ties between products of roots are common
    const double x = std::abs(small(rng)) * 0.5;
    return {sqrt(LazyRadical(x)), sqrt(Radical(x))};
  }
  const Both a = random_value(rng, depth - 1), b = random_value(rng, depth - 1);
  switch (op) {
    case 2: return {a.lazy + b.lazy, a.exact + b.exact};
    case 3: return {a.lazy - b.lazy, a.exact - b.exact};
    case 4: return {a.lazy * b.lazy, a.exact * b.exact};
    default:
      if (sign(b.exact) == 0) return a;
      return {a.lazy / b.lazy, a.exact / b.exact};
  }
}

TEST(LazyRadical, SignsOfRandomExpressionsAreRadicals) {
  std::mt19937_64 rng(7);
  int ties = 0, evaluated = 0;
  for (int i = 0; i < 400; ++i) {
    const LazyRadical::Scope scope;
    const Both a = random_value(rng, 3), c = random_value(rng, 2);
    // Every other pair is a and a rewritten: (a * c) / c + c - c, equal to it by a path
    // whose intervals grow.
    Both b = random_value(rng, 3);
    if (i % 2 == 1 && sign(c.exact) != 0)
      b = {(a.lazy * c.lazy) / c.lazy + c.lazy - c.lazy,
           (a.exact * c.exact) / c.exact + c.exact - c.exact};
    SCOPED_TRACE(i);
    ASSERT_EQ(compare(a.lazy, b.lazy), sign(a.exact - b.exact));
    ASSERT_EQ(sign(a.lazy - b.lazy), sign(a.exact - b.exact));
    ties += sign(a.exact - b.exact) == 0;
    evaluated += a.lazy.is_evaluated();
  }
  EXPECT_GT(ties, 100);              // the cases that need Radical came up
  EXPECT_LT(evaluated, 400 - ties);  // and the others mostly did not
}

}  // namespace
}  // namespace roomcad::exact
