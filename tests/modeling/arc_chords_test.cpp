// SPDX-License-Identifier: GPL-3.0-or-later
// The chord polyline of arc walls (docs/plan-format.md, "arc_extent"): n equal chords, the
// smallest n within the chord tolerance, turning the way the extent's sign says.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "modeling/arc_chords.h"

namespace roomcad {
namespace {

Wall arc_wall(Point2 from, Point2 to, double extent) {
  Wall w;
  w.from = from;
  w.to = to;
  w.arc_extent = extent;
  return w;
}

double sagitta(double radius, double chord) {
  return radius - std::sqrt(radius * radius - chord * chord / 4);
}

TEST(ArcChords, ChordsAreEqualWithinToleranceAndTheFewestThatAre) {
  const Point2 a{6.4976215, -9.1945013}, b{0.041, -10.419019};
  for (const double tolerance : {0.05, 0.01, 0.001, 1e-5}) {
    const Wall w = arc_wall(a, b, 40);
    const std::vector<Point2> p = centre_polyline(w, tolerance);
    ASSERT_GE(p.size(), 3u);
    EXPECT_EQ(p.front(), a);
    EXPECT_EQ(p.back(), b);
    const double radius = arc_radius(a, b, 40);
    const double n = static_cast<double>(p.size() - 1);
    const double theta = 40 * std::numbers::pi / 180;
    EXPECT_LE(radius * (1 - std::cos(theta / (2 * n))), tolerance);
    EXPECT_GT(radius * (1 - std::cos(theta / (2 * (n - 1)))), tolerance);  // fewest
    for (std::size_t k = 1; k < p.size(); ++k) {
      const double chord = std::hypot(p[k].x - p[k - 1].x, p[k].y - p[k - 1].y);
      EXPECT_LE(sagitta(radius, chord), tolerance * (1 + 1e-6));
    }
  }
}

TEST(ArcChords, PositiveExtentTurnsCounterClockwiseBulgingRight) {
  // From (0,0) to (2,0) turning +90 degrees: the centre (1, 1) is to the left, the arc
  // passes below the chord, through (1, 1 - sqrt 2).
  for (const double sign : {1.0, -1.0}) {
    const std::vector<Point2> p = centre_polyline(arc_wall({0, 0}, {2, 0}, sign * 90), 1e-4);
    double lowest = 0, highest = 0;
    for (const Point2& q : p) {
      lowest = std::min(lowest, q.y);
      highest = std::max(highest, q.y);
      EXPECT_NEAR(std::hypot(q.x - 1, q.y - sign), std::sqrt(2.0), 1e-12);
    }
    EXPECT_NEAR(sign > 0 ? lowest : -highest, 1 - std::sqrt(2.0), 1e-4);
  }
}

TEST(ArcChords, StraightWallIsItsTwoEnds) {
  Wall w;
  w.from = {1, 2};
  w.to = {3, 4};
  EXPECT_EQ(centre_polyline(w, 0.001), (std::vector<Point2>{{1, 2}, {3, 4}}));
  EXPECT_DOUBLE_EQ(polyline_length({{0, 0}, {3, 4}, {3, 5}}), 6.0);
}

TEST(ArcChords, ATolerenceBelowRoundingGivesBoundedChords) {
  // 1 - tolerance / radius rounds to 1: the closed form's chord count is infinite.
  const std::vector<Point2> p = centre_polyline(arc_wall({0, 0}, {1e9, 0}, 57.3), 1e-12);
  EXPECT_EQ(p.size(), static_cast<std::size_t>(kMaxArcChords) + 1);
  for (const Point2& q : p) EXPECT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
  EXPECT_EQ(chord_count(1.0, 3.0, 10.0), 1);  // a tolerance above the sagitta: one chord
}

}  // namespace
}  // namespace roomcad
