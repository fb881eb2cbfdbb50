// SPDX-License-Identifier: GPL-3.0-or-later
// Arc walls as their chord polylines (docs/plan-format.md, "arc_extent"): the fewest equal
// chords within the chord tolerance, turning the way the extent's sign says; and a plan with
// its arcs replaced by their chords (plan_chords.h), openings cut along them.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "plan/arc_chords.h"
#include "plan/plan_chords.h"

namespace roomcad {
namespace {

Wall arc_wall(Point2 from, Point2 to, double extent) {
  Wall w;
  w.id = "bow";
  w.from = from;
  w.to = to;
  w.arc_extent = extent;
  return w;
}

TEST(PlanChords, ChordsAreEqualWithinToleranceAndTheFewestThatAre) {
  const Point2 a{6.4976215, -9.1945013}, b{0.041, -10.419019};
  const double span = std::hypot(b.x - a.x, b.y - a.y);
  const double theta = 40 * std::numbers::pi / 180;
  const double radius = span / (2 * std::sin(theta / 2));
  for (const double tolerance : {0.05, 0.01, 0.001, 1e-5}) {
    const std::vector<Point2> p = chord_polyline(arc_wall(a, b, 40), tolerance);
    ASSERT_GE(p.size(), 3u);
    EXPECT_EQ(p.front(), a);
    EXPECT_EQ(p.back(), b);
    const double n = static_cast<double>(p.size() - 1);
    EXPECT_LE(radius * (1 - std::cos(theta / (2 * n))), tolerance);
    EXPECT_GT(radius * (1 - std::cos(theta / (2 * (n - 1)))), tolerance);  // the fewest
    for (std::size_t k = 1; k < p.size(); ++k) {
      const double chord = std::hypot(p[k].x - p[k - 1].x, p[k].y - p[k - 1].y);
      EXPECT_LE(radius - std::sqrt(radius * radius - chord * chord / 4), tolerance * (1 + 1e-6));
    }
  }
}

TEST(PlanChords, PositiveExtentTurnsCounterClockwiseBulgingRight) {
  // From (0,0) to (2,0) turning +90 degrees: the centre (1, 1) is to the left, the arc passes
  // below the chord, through (1, 1 - sqrt 2).
  for (const double sign : {1.0, -1.0}) {
    const std::vector<Point2> p = chord_polyline(arc_wall({0, 0}, {2, 0}, sign * 90), 1e-4);
    double lowest = 0, highest = 0;
    for (const Point2& q : p) {
      lowest = std::min(lowest, q.y);
      highest = std::max(highest, q.y);
      EXPECT_NEAR(std::hypot(q.x - 1, q.y - sign), std::sqrt(2.0), 1e-12);
    }
    EXPECT_NEAR(sign > 0 ? lowest : -highest, 1 - std::sqrt(2.0), 1e-4);
  }
}

TEST(PlanChords, ArcsThatCannotBeBuiltAreSaidSo) {
  EXPECT_TRUE(is_buildable_arc(arc_wall({0, 0}, {4, 0}, 90), 0.001));
  EXPECT_FALSE(is_buildable_arc(arc_wall({0, 0}, {4, 0}, 360), 0.001));
  EXPECT_FALSE(is_buildable_arc(arc_wall({0, 0}, {0, 0}, 90), 0.001));
  EXPECT_FALSE(is_buildable_arc(arc_wall({0, 0}, {1e9, 0}, 57.3), 1e-12));  // too many chords
  Wall straight;
  straight.from = {1, 2};
  straight.to = {3, 4};
  EXPECT_FALSE(is_buildable_arc(straight, 0.001));
  EXPECT_DOUBLE_EQ(polyline_length({{0, 0}, {3, 4}, {3, 5}}), 6.0);
}

TEST(PlanChords, ArcWallsBecomeTheirChordsAndTheirOpeningsPiecesAlongThem) {
  Plan p;
  p.walls = {arc_wall({0, 0}, {4, 0}, 90)};
  p.walls[0].height = 1;
  p.walls[0].height_at_end = 3;  // sloped: the chords share the slope along the polyline
  Wall straight;
  straight.id = "s";
  straight.from = {4, 0};
  straight.to = {4, 3};
  p.walls.push_back(straight);
  Opening o;
  o.id = "w";
  o.wall = "bow";
  o.offset = 1;
  o.width = 2;
  o.sill = 0.5;
  o.height = 0.5;
  o.shape = {{0, 0}, {1, 0}, {0.5, 1}};
  p.openings = {o};
  o.id = "d";
  o.wall = "s";
  o.shape.clear();
  p.openings.push_back(o);
  const ChordPlan c = with_arcs_as_chords(p);
  const std::vector<Point2> line = chord_polyline(p.walls[0], chord_tolerance_of(p.site));
  ASSERT_EQ(c.plan.walls.size(), line.size());  // the chords, then the straight wall
  double along = 0;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const Wall& chord = c.plan.walls[k];
    EXPECT_EQ(chord.id, "bow");
    EXPECT_FALSE(chord.arc_extent.has_value());
    EXPECT_EQ(chord.from, line[k]);
    EXPECT_EQ(chord.to, line[k + 1]);
    EXPECT_EQ(c.source_wall[k], 0u);
    EXPECT_NEAR(chord.height, 1 + 2 * along / polyline_length(line), 1e-12);
    along += std::hypot(chord.to.x - chord.from.x, chord.to.y - chord.from.y);
  }
  EXPECT_EQ(c.plan.walls.back().id, "s");
  // The window's pieces cover [1, 3] along the polyline, one per chord crossed, each on its
  // chord; the door of the straight wall is copied whole.
  double width = 0;
  for (std::size_t j = 0; j < c.plan.openings.size(); ++j) {
    const Opening& piece = c.plan.openings[j];
    if (piece.id == "d") {
      EXPECT_EQ(c.chord[j], kNoChord);
      EXPECT_EQ(piece, p.openings[1]);
      continue;
    }
    ASSERT_NE(c.chord[j], kNoChord);
    EXPECT_EQ(c.source_opening[j], 0u);
    EXPECT_TRUE(piece.shape.empty());
    EXPECT_EQ(piece.sill, 0.5);
    EXPECT_EQ(piece.height, 0.5);
    width += piece.width;
  }
  EXPECT_NEAR(width, 2.0, 1e-12);
}

}  // namespace
}  // namespace roomcad
