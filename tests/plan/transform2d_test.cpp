// SPDX-License-Identifier: GPL-3.0-or-later
// Homogeneous 2D transforms (row-vector convention) and their decimal-exact guarantees.
#include "plan/transform2d.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace roomcad {
namespace {

/// Bitwise equality: EXPECT_EQ on doubles would accept -0 == 0.
void expect_same_bits(Point2 a, Point2 b) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.x), std::bit_cast<std::uint64_t>(b.x))
      << a.x << " vs " << b.x;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.y), std::bit_cast<std::uint64_t>(b.y))
      << a.y << " vs " << b.y;
}

/// Decimal points of up to 15 significant digits, as plans are typed.
std::vector<Point2> decimal_points() {
  return {{0.1, 0.2}, {1.1, 2.3},          {-3.7, 0.35},   {12.345, -6.789}, {1e-3, 7.25e2},
          {0.0, 1.0}, {123456.789, 0.001}, {2.675, 1.005}, {99.99, -0.07},   {1e10, 3e-5}};
}

TEST(Transform2d, RowVectorTranslationSitsInTheBottomRow) {
  const Transform2d t = translate(3.0, 2.0);
  EXPECT_EQ(t.m[2][0], 3.0);
  EXPECT_EQ(t.m[2][1], 2.0);
  EXPECT_EQ(apply(t, {2.0, 3.0}), (Point2{5.0, 5.0}));  // the seed's example, figure 1
}

TEST(Transform2d, ScaleAndRotateFollowTheSeedFormulas) {
  EXPECT_EQ(apply(scale(2.0), {2.0, 3.0}), (Point2{4.0, 6.0}));
  // Counter-clockwise: x1 = x cos - y sin, y1 = x sin + y cos.
  EXPECT_EQ(apply(rotate(90.0), {2.0, 3.0}), (Point2{-3.0, 2.0}));
  const Point2 p = apply(rotate(30.0), {1.0, 0.0});
  EXPECT_NEAR(p.x, std::sqrt(3.0) / 2.0, 1e-15);
  EXPECT_NEAR(p.y, 0.5, 1e-15);
}

TEST(Transform2d, ComposeAppliesFirstThenSecond) {
  const Transform2d t = compose(translate(1.0, 0.0), rotate(90.0));
  EXPECT_EQ(apply(t, {1.0, 0.0}), (Point2{0.0, 2.0}));  // (2, 0) turned to (0, 2)
  const Transform2d u = compose(rotate(90.0), translate(1.0, 0.0));
  EXPECT_EQ(apply(u, {1.0, 0.0}), (Point2{1.0, 1.0}));  // (0, 1) moved to (1, 1)
}

TEST(Transform2d, ResultsAreCorrectlyRoundedDecimals) {
  EXPECT_NE(0.1 + 0.2, 0.3);  // what plain doubles do
  EXPECT_EQ(apply(translate(0.2, 0.0), {0.1, 0.0}).x, 0.3);
  EXPECT_EQ(exact_add(1.1, 2.2), 3.3);
  EXPECT_EQ(apply(scale(3.0), {0.1, 0.0}).x, 0.3);
}

TEST(Transform2d, MoveThenMoveBackIsIdentityForDecimals) {
  const std::vector<Point2> shifts{{0.1, -0.2}, {1.234, 5.6789}, {-1e-4, 300.5}, {0.7, 0.7}};
  for (const Point2& p : decimal_points()) {
    for (const Point2& d : shifts) {
      const Point2 there = apply(translate(d.x, d.y), p);
      expect_same_bits(apply(translate(-d.x, -d.y), there), p);
    }
  }
}

TEST(Transform2d, FourQuarterTurnsAboutAnyDecimalPointAreIdentity) {
  const std::vector<Point2> centres{{0.0, 0.0}, {0.1, 0.7}, {3.3, -1.9}, {1234.567, 0.0123}};
  for (const Point2& c : centres) {
    for (const double deg : {90.0, -90.0, 270.0, 450.0}) {
      const Transform2d quarter = rotate(deg, c);
      for (const Point2& p : decimal_points()) {
        Point2 q = p;
        for (int i = 0; i < 4; ++i) q = apply(quarter, q);
        expect_same_bits(q, p);
      }
    }
  }
}

TEST(Transform2d, PlainDoublesWouldNotGiveTheQuarterTurnsBack) {
  // Why the decimal arithmetic: the same turns in plain doubles drift for this point/centre.
  const Point2 c{0.1, 0.7};
  Point2 q;
  int drifted = 0;
  for (const Point2& p : decimal_points()) {
    q = p;
    for (int i = 0; i < 4; ++i) q = {c.x - (q.y - c.y), c.y + (q.x - c.x)};
    drifted += (q != p);
  }
  EXPECT_GT(drifted, 0);
}

TEST(Transform2d, ScaleThenInverseScaleIsIdentityForDecimals) {
  const Point2 c{0.3, -1.1};
  for (const Point2& p : decimal_points()) {
    const Point2 there = apply(scale(2.0, c), p);
    expect_same_bits(apply(scale(0.5, c), there), p);
    expect_same_bits(apply(scale(0.1, c), apply(scale(10.0, c), p)), p);
  }
}

TEST(Transform2d, QuarterTurnMatricesHaveExactEntries) {
  const Transform2d r = rotate(270.0, {0.1, 0.2});
  EXPECT_EQ(r.m[0][0], 0.0);
  EXPECT_EQ(r.m[0][1], -1.0);
  EXPECT_EQ(r.m[1][0], 1.0);
  EXPECT_EQ(r.m[2][0], -0.1);  // cx - cy, exactly the decimal
  EXPECT_EQ(r.m[2][1], 0.3);   // cx + cy
  EXPECT_TRUE(is_quarter_turn(-450.0));
  EXPECT_FALSE(is_quarter_turn(45.0));
}

TEST(Transform2d, DirectionsIgnoreTranslation) {
  const Transform2d t = compose(rotate(90.0), translate(5.0, 5.0));
  EXPECT_EQ(apply_to_direction(t, {1.0, 0.0}), (Point2{0.0, 1.0}));
}

TEST(Transform2d, GeneralAnglesRoundTripWithinAnUlpOrTwo) {
  // Not exact (cos 30 is irrational), but each result is rounded once: document the drift.
  const Point2 p{3.3, 1.7};
  const Point2 q = apply(rotate(-30.0), apply(rotate(30.0), p));
  EXPECT_NEAR(q.x, p.x, 4e-15);
  EXPECT_NEAR(q.y, p.y, 4e-15);
}

TEST(Transform2d, AnExactChainKeepsTheCentreOfAnyTurn) {
  const Point2 c{5.9, 3.85};
  for (const double deg : {30.0, -17.5, 123.4}) {
    const auto chain = about_point(rotate(deg), c);
    expect_same_bits(apply_exactly(chain, c), c);
    const Point2 p = apply_exactly(chain, {1.1, 2.3});
    const Point2 q = apply(rotate(deg, c), {1.1, 2.3});  // composed entries: within an ulp or so
    EXPECT_NEAR(p.x, q.x, 4e-15);
    EXPECT_NEAR(p.y, q.y, 4e-15);
  }
  const auto quarter = about_point(rotate(90.0), c);
  for (const Point2& p : decimal_points())
    expect_same_bits(apply_exactly(quarter, p), apply(rotate(90.0, c), p));
}

TEST(Transform2d, NonFiniteValuesPropagate) {
  EXPECT_TRUE(std::isnan(apply(translate(1.0, 0.0), {std::nan(""), 0.0}).x));
  EXPECT_TRUE(std::isinf(apply(translate(1.0, 0.0), {INFINITY, 0.0}).x));
  EXPECT_TRUE(std::isnan(apply_exactly(about_point(rotate(30.0), {1, 1}), {std::nan(""), 0.0}).y));
}

TEST(Transform2d, ExactZeroHasNoSign) {
  const Point2 p = apply(translate(-1.5, 1.5), {1.5, -1.5});
  EXPECT_FALSE(std::signbit(p.x));
  EXPECT_FALSE(std::signbit(p.y));
}

}  // namespace
}  // namespace roomcad
