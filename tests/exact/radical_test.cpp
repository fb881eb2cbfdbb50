// SPDX-License-Identifier: GPL-3.0-or-later
// exact::Radical: signs, equalities and inverses of sums of products of square roots, decided
// exactly (no refinement), and rounding to the nearest double.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "exact/radical.h"
#include "support/invariant.h"

namespace roomcad::exact {
namespace {

TEST(Radical, ProductsOfRootsAreRecognisedAsTheRootOfTheProduct) {
  const Radical::Scope scope;
  const Radical r2 = sqrt(Radical(2)), r3 = sqrt(Radical(3)), r6 = sqrt(Radical(6));
  EXPECT_EQ(sign(r2 * r3 - r6), 0);
  EXPECT_EQ(sign(sqrt(Radical(8)) - Radical(2) * r2), 0);  // 8 = 4 * 2: a rewritten root
  EXPECT_EQ(sign(sqrt(Radical(2.25)) - Radical(1.5)), 0);  // a rational square
  EXPECT_EQ(sign(r2 * r2 - Radical(2)), 0);
}

TEST(Radical, SignsOfNearlyCancellingSumsAreExact) {
  const Radical::Scope scope;
  const Radical r2 = sqrt(Radical(2)), r3 = sqrt(Radical(3)), r10 = sqrt(Radical(10));
  EXPECT_LT(r2 + r3, r10);                      // 3.1462... < 3.1623...
  EXPECT_GT(r2 + r3 - r10, Radical(-0.01602));  // -0.0160133...
  EXPECT_LT(r2 + r3 - r10, Radical(-0.01601));
  // (1 + 1e-30)-style closeness in doubles: sqrt(x^2 + 1) - x > 0 for a huge x.
  const double x = 1e15;
  const Radical s = sqrt(Radical(x) * Radical(x) + Radical(1));
  EXPECT_GT(s, Radical(x));
  EXPECT_LT(s - Radical(x), Radical(1e-15));
  EXPECT_GT(s - Radical(x), Radical(4.9e-16));
}

TEST(Radical, DivisionMultipliesByTheConjugate) {
  const Radical::Scope scope;
  const Radical r2 = sqrt(Radical(2)), r3 = sqrt(Radical(3)), r5 = sqrt(Radical(5));
  EXPECT_EQ(Radical(1) / (r2 + r3), r3 - r2);
  const Radical a = r2 + r3 * r5 - Radical(7);
  EXPECT_EQ((a / (r2 - r5)) * (r2 - r5), a);
  EXPECT_INVARIANT_BROKEN((void)(a / Radical(0)));
  EXPECT_INVARIANT_BROKEN((void)sqrt(Radical(-1)));
}

TEST(Radical, RoundsToTheNearestDouble) {
  const Radical::Scope scope;
  EXPECT_EQ(round_to_nearest(sqrt(Radical(2))), std::sqrt(2.0));
  EXPECT_EQ(round_to_nearest(sqrt(Radical(1e12 + 7)) * Radical(-3)), -std::sqrt(9e12 + 63));
  EXPECT_EQ(round_to_nearest(Radical(0.1)), 0.1);
  EXPECT_EQ(round_to_nearest(Radical(0)), 0.0);
  // Halfway between 1 and the next double: ties go to the lower.
  const double up = std::nextafter(1.0, 2.0);
  EXPECT_EQ(round_to_nearest((Radical(1) + Radical(up)) / Radical(2)), 1.0);
}

TEST(Radical, RoundsAValueWhoseTermsOverflowDoubles) {
  // sqrt(2) + 1e300 * 1e300 / 1e300 / 1e300: terms of 1e600 (as a mitre of walls a denormal
  // off straight divides by 1e-323), the value in range. Its interval is unbounded.
  const Radical::Scope scope;
  const Radical big(1e300);
  const Radical x = sqrt(Radical(2)) * (big * big) / big / big;
  EXPECT_EQ(round_to_nearest(x), std::sqrt(2.0));
  EXPECT_EQ(round_to_nearest(-x), -std::sqrt(2.0));
  EXPECT_EQ(round_to_nearest(x * big * big), std::numeric_limits<double>::max());  // saturates
}

}  // namespace
}  // namespace roomcad::exact
