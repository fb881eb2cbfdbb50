// SPDX-License-Identifier: GPL-3.0-or-later
// exact::PreciseInterval: 128-bit bounds rounded outward, comparisons that refuse to guess,
// and the nearest double told only when no midpoint between doubles is within reach.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "exact/precise_interval.h"

namespace roomcad::exact {
namespace {

TEST(PreciseInterval, RootsRoundToTheCorrectlyRoundedDouble) {
  // IEEE sqrt is correctly rounded: the interval must agree with it.
  for (const double x : {2.0, 3.0, 5.0, 0.1, 1e-300, 12345.678, 1e300}) {
    const std::optional<double> nearest = sqrt(PreciseInterval(x)).nearest_double();
    ASSERT_TRUE(nearest.has_value()) << x;
    EXPECT_EQ(*nearest, std::sqrt(x)) << x;
  }
  // (1 / 3) * 3 is 1 exactly; its interval is a few 2^-128 wide around 1: still clear.
  EXPECT_EQ((PreciseInterval(1) / PreciseInterval(3) * PreciseInterval(3)).nearest_double(), 1.0);
}

TEST(PreciseInterval, ATieBetweenTwoDoublesIsLeftToExactArithmetic) {
  // 1 + 2^-53 lies halfway between 1 and the next double: exact at 128 bits, yet no nearest.
  const PreciseInterval tie = PreciseInterval(1) + PreciseInterval(std::ldexp(1.0, -53));
  EXPECT_FALSE(tie.nearest_double().has_value());
  // A hair above it is clear again, and rounds up.
  const PreciseInterval above = tie + PreciseInterval(std::ldexp(1.0, -100));
  EXPECT_EQ(above.nearest_double(), std::nextafter(1.0, 2.0));
  // Beyond the largest double there is no nearest double.
  const double most = std::numeric_limits<double>::max();
  EXPECT_FALSE((PreciseInterval(most) + PreciseInterval(most)).nearest_double().has_value());
}

TEST(PreciseInterval, ComparisonsItCannotDecideThrow) {
  const PreciseInterval third = PreciseInterval(1) / PreciseInterval(3);
  EXPECT_TRUE(PreciseInterval(0.5) == PreciseInterval(0.5));
  EXPECT_FALSE(third == PreciseInterval(0.5));
  EXPECT_THROW((void)(third * PreciseInterval(3) == PreciseInterval(1)), UndecidedComparison);
  EXPECT_THROW((void)(PreciseInterval(1) / (third * PreciseInterval(3) - PreciseInterval(1))),
               UndecidedComparison);
  EXPECT_THROW((void)sqrt(PreciseInterval(-1)), UndecidedComparison);
}

TEST(PreciseInterval, SumsOfDoublesAreExactSoTouchingIsDecided) {
  // 0.1 + 0.2 - 0.1 is 0.2 exactly in real numbers; double intervals straddle it, 128 bits
  // hold it as one number: the comparisons a touch needs are decided, not thrown.
  const PreciseInterval sum = PreciseInterval(0.1) + PreciseInterval(0.2) - PreciseInterval(0.1);
  EXPECT_TRUE(sum == PreciseInterval(0.2));
  EXPECT_TRUE(sum <= PreciseInterval(0.2));
  EXPECT_FALSE(sum < PreciseInterval(0.2));
  // The doubles 0.1 and 0.2 add to a little more than the double 0.3.
  EXPECT_TRUE(PreciseInterval(0.1) + PreciseInterval(0.2) > PreciseInterval(0.3));
  EXPECT_TRUE(PreciseInterval(0.3) < PreciseInterval(0.1) + PreciseInterval(0.2));
  // A root of 2 squared is 2 in real numbers, not in 128 bits: left to exact arithmetic.
  const PreciseInterval two = sqrt(PreciseInterval(2)) * sqrt(PreciseInterval(2));
  EXPECT_THROW((void)(two < PreciseInterval(2)), UndecidedComparison);
  EXPECT_THROW((void)(two >= PreciseInterval(2)), UndecidedComparison);
  EXPECT_TRUE(two < PreciseInterval(2.0000001));
}

TEST(PreciseInterval, SignsAndProductsKeepTheNumberInside) {
  // Products of intervals of mixed signs take the extreme corners.
  const PreciseInterval a = PreciseInterval(-2) / PreciseInterval(3);    // about -0.667
  const PreciseInterval b = -(PreciseInterval(5) / PreciseInterval(7));  // about -0.714
  EXPECT_EQ((a * b).nearest_double(), 10.0 / 21.0);  // IEEE division rounds correctly
  EXPECT_EQ((a - b).nearest_double(), 1.0 / 21.0);
}

TEST(PreciseInterval, ProductsAndQuotientsHoldTheNumberWhateverTheSignsOfTheBounds) {
  // Intervals about 2/3, about -2/3, and two holding 0 inside (a tiny and a wider one): each
  // product and quotient takes its bounds from the corners its signs call for, and must still
  // hold the exact result.
  const PreciseInterval pos = PreciseInterval(2) / PreciseInterval(3), neg = -pos;
  const PreciseInterval zero =
      PreciseInterval(1) / PreciseInterval(3) * PreciseInterval(3) - PreciseInterval(1);
  const PreciseInterval wide_zero = zero * PreciseInterval(1e30);
  const auto holds_zero = [](const PreciseInterval& x) {
    EXPECT_THROW((void)(x < PreciseInterval(0)), UndecidedComparison);
    EXPECT_THROW((void)(x > PreciseInterval(0)), UndecidedComparison);
    EXPECT_TRUE(x < PreciseInterval(1e-6) && x > PreciseInterval(-1e-6));
  };
  EXPECT_EQ((pos * pos).nearest_double(), 4.0 / 9.0);
  EXPECT_EQ((pos * neg).nearest_double(), -4.0 / 9.0);
  EXPECT_EQ((neg * pos).nearest_double(), -4.0 / 9.0);
  EXPECT_EQ((neg * neg).nearest_double(), 4.0 / 9.0);
  for (const PreciseInterval* z : {&zero, &wide_zero}) {
    for (const PreciseInterval* x : {&pos, &neg, &zero, &wide_zero}) {
      holds_zero(*z * *x);
      holds_zero(*x * *z);
    }
    holds_zero(*z / pos);
    holds_zero(*z / neg);
    EXPECT_THROW((void)(pos / *z), UndecidedComparison);
  }
  EXPECT_EQ((pos / pos).nearest_double(), 1.0);
  EXPECT_EQ((pos / neg).nearest_double(), -1.0);
  EXPECT_EQ((neg / pos).nearest_double(), -1.0);
  EXPECT_EQ((neg / neg).nearest_double(), 1.0);
  EXPECT_EQ((PreciseInterval(1) / pos).nearest_double(), 1.5);
  EXPECT_EQ((PreciseInterval(-1) / neg).nearest_double(), 1.5);
}

}  // namespace
}  // namespace roomcad::exact
