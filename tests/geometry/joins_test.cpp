// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/joins.h"

#include <cmath>

#include <gtest/gtest.h>

#include "testing/plan_builders.h"

namespace roomcad {
namespace {

using samples::make_wall;

Plan plan_of(std::vector<Wall> walls) {
  Plan p;
  p.walls = std::move(walls);
  return p;
}

TEST(Joins, LCornerIsMitredWithCornersOnTheBisector) {
  const Plan p =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {0, 0}, {0, 3}, 0.2)});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 1u);
  EXPECT_EQ(j.pairs[0].kind, JoinKind::mitre);
  EXPECT_EQ(j.pairs[0].point, (Point2{0, 0}));
  EXPECT_EQ(j.mitre[0][0], std::optional<std::size_t>(1));
  EXPECT_EQ(j.mitre[1][0], std::optional<std::size_t>(0));
  EXPECT_FALSE(j.mitre[0][1].has_value());
  const auto fa = wall_footprint(p, j, 0);
  // {from-right, to-right, to-left, from-left}: outer corner (-0.1,-0.1), inner (0.1, 0.1).
  EXPECT_EQ(fa[0], (Point2{-0.1, -0.1}));
  EXPECT_EQ(fa[1], (Point2{4, -0.1}));
  EXPECT_EQ(fa[2], (Point2{4, 0.1}));
  EXPECT_EQ(fa[3], (Point2{0.1, 0.1}));
  const auto fb = wall_footprint(p, j, 1);
  EXPECT_EQ(fb[0], (Point2{0.1, 0.1}));    // b's right side is x = +0.1 (inner)
  EXPECT_EQ(fb[3], (Point2{-0.1, -0.1}));  // b's left side is x = -0.1 (outer)
}

TEST(Joins, WallsOnTheStoreyAboveDoNotJoinOrBreakAMitre) {
  Wall above = make_wall("c", {0, 0}, {0, 3}, 0.2);
  above.base = 2.8;  // exactly on top of the ground floor's 2.8 m walls
  const Plan p =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {0, 0}, {0, 3}, 0.2), above});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 1u);
  EXPECT_EQ(j.pairs[0].kind, JoinKind::mitre) << "the wall above is not a third wall at the corner";
  EXPECT_FALSE(j.are_joined(0, 2));
  EXPECT_FALSE(j.are_joined(1, 2));
}

TEST(Joins, MitreOfDifferentThicknessesPassesThroughSideLineCrossings) {
  const Plan p =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {0, 3}, {0, 0}, 0.4)});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 1u);
  ASSERT_EQ(j.pairs[0].kind, JoinKind::mitre);
  const auto fa = wall_footprint(p, j, 0);
  EXPECT_EQ(fa[0], (Point2{-0.2, -0.1}));
  EXPECT_EQ(fa[3], (Point2{0.2, 0.1}));
  const auto fb = wall_footprint(p, j, 1);
  // b runs south: its right side is x = -0.2, left x = +0.2; its to-end is the corner.
  EXPECT_EQ(fb[1], (Point2{-0.2, -0.1}));
  EXPECT_EQ(fb[2], (Point2{0.2, 0.1}));
}

TEST(Joins, RotatedMitreCornersAreBitIdenticalForBothWalls) {
  const double c = std::cos(71.3 * M_PI / 180), s = std::sin(71.3 * M_PI / 180);
  const Point2 o{1048576.3, -1048576.7};
  const Plan p = plan_of({make_wall("a", o, {o.x + 3 * c, o.y + 3 * s}, 0.25),
                          make_wall("b", {o.x - 2 * s, o.y + 2 * c}, o, 0.3)});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 1u);
  ASSERT_EQ(j.pairs[0].kind, JoinKind::mitre);
  const auto fa = wall_footprint(p, j, 0);
  const auto fb = wall_footprint(p, j, 1);
  // a's from-end meets b's to-end: a's from-right is b's to-right, a's from-left b's to-left.
  EXPECT_EQ(fa[0], fb[1]);
  EXPECT_EQ(fa[3], fb[2]);
  EXPECT_NE(fa[0], fa[3]);
}

TEST(Joins, CollinearContinuationIsMitredWithSquareEnds) {
  const Plan p =
      plan_of({make_wall("a", {0, 0}, {2, 0}, 0.2), make_wall("b", {2, 0}, {5, 0}, 0.2)});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 1u);
  EXPECT_EQ(j.pairs[0].kind, JoinKind::mitre);
  const auto fa = wall_footprint(p, j, 0);
  EXPECT_EQ(fa[1], (Point2{2, -0.1}));
  EXPECT_EQ(fa[2], (Point2{2, 0.1}));
}

TEST(Joins, CollinearOverlapUnitesAndIsNotAMitre) {
  const Plan p =
      plan_of({make_wall("a", {0, 0}, {3, 0}, 0.2), make_wall("b", {0, 0}, {2, 0}, 0.2)});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 1u);
  EXPECT_EQ(j.pairs[0].kind, JoinKind::unite);
}

TEST(Joins, CornerSharperThanTheMitreReachUnitesAndKeepsSquareEnds) {
  // Walls 0.2 thick leaving the shared end at 14 and 15 degrees: the outer corner of their
  // mitre lies 0.1 / sin(angle / 2) from the end, 0.82 and 0.77 m; the reach is 4 x 0.2 m.
  const auto corner = [](double degrees) {
    const double r = degrees * M_PI / 180;
    return plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2),
                    make_wall("b", {0, 0}, {4 * std::cos(r), 4 * std::sin(r)}, 0.2)});
  };
  EXPECT_EQ(find_joins(corner(15)).pairs.at(0).kind, JoinKind::mitre);
  const Plan sharp = corner(14);
  const Joins j = find_joins(sharp);
  ASSERT_EQ(j.pairs.size(), 1u);
  EXPECT_EQ(j.pairs[0].kind, JoinKind::unite);
  EXPECT_FALSE(j.mitre[0][0].has_value());
  const auto fa = wall_footprint(sharp, j, 0);
  EXPECT_EQ(fa[0], (Point2{0, -0.1}));
  EXPECT_EQ(fa[3], (Point2{0, 0.1}));
}

TEST(Joins, StraightRunToAnotherThicknessWithAKinkUnitesUnlessTheMitreIsNear) {
  // A 0.2 m wall running on as a 0.1 m wall, bent by 1 degree: the side lines cross 2.9 m
  // away. Bent by 10 degrees they cross 0.29 m away, within the reach of 0.8 m.
  const auto run = [](double degrees, double thickness) {
    const double r = degrees * M_PI / 180;
    return plan_of({make_wall("a", {0, 0}, {3, 0}, 0.2),
                    make_wall("b", {3, 0}, {3 + 2 * std::cos(r), 2 * std::sin(r)}, thickness)});
  };
  EXPECT_EQ(find_joins(run(1, 0.1)).pairs.at(0).kind, JoinKind::unite);
  EXPECT_EQ(find_joins(run(10, 0.1)).pairs.at(0).kind, JoinKind::mitre);
  EXPECT_EQ(find_joins(run(1, 0.2)).pairs.at(0).kind, JoinKind::mitre);  // equal: on the bisector
  EXPECT_EQ(find_joins(run(0, 0.1)).pairs.at(0).kind, JoinKind::mitre);  // straight: square ends
}

TEST(Joins, HairpinOfWallsDrawnOverEachOtherStaysWithinItsWalls) {
  // Found by fuzz_build: two walls ending at one point, one doubling back along the other
  // with a tilt of 2e-16 rad; the mitre put a corner 7.7e18 m away.
  const Plan p = plan_of(
      {make_wall("a", {-1150000, -1150000}, {-1150000.0000000002, -1060000}, 20000),
       make_wall("b", {-1150000.0000000002, -1120000}, {-1150000.0000000002, -1060000}, 20000)});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 1u);
  EXPECT_EQ(j.pairs[0].kind, JoinKind::unite);
  for (std::size_t w = 0; w < 2; ++w)
    for (const Point2& c : wall_footprint(p, j, w)) {
      EXPECT_LE(std::abs(c.x + 1150000), 10000.001);
      EXPECT_LE(std::abs(c.y + 1105000), 45000.001);
    }
}

TEST(Joins, TAndXAndThreeWayMeetingsUnite) {
  const Plan t =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {2, 0}, {2, 3}, 0.2)});
  const Joins jt = find_joins(t);
  ASSERT_EQ(jt.pairs.size(), 1u);
  EXPECT_EQ(jt.pairs[0].kind, JoinKind::unite);
  EXPECT_EQ(jt.pairs[0].point, (Point2{2, 0}));

  const Plan x =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {2, -2}, {2, 3}, 0.2)});
  const Joins jx = find_joins(x);
  ASSERT_EQ(jx.pairs.size(), 1u);
  EXPECT_EQ(jx.pairs[0].kind, JoinKind::unite);
  EXPECT_EQ(jx.pairs[0].point, (Point2{2, 0}));

  const Plan three =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {0, 0}, {0, 3}, 0.2),
               make_wall("c", {0, 0}, {-2, -2}, 0.2)});
  const Joins j3 = find_joins(three);
  ASSERT_EQ(j3.pairs.size(), 3u);
  for (const Join& join : j3.pairs) EXPECT_EQ(join.kind, JoinKind::unite);
  EXPECT_FALSE(j3.mitre[0][0].has_value());
  // United ends stay square.
  EXPECT_EQ(wall_footprint(three, j3, 0)[0], (Point2{0, -0.1}));
}

TEST(Joins, EndWithinToleranceJoinsAndBeyondDoesNot) {
  // The tolerance is 1e-6 m; at 2^20 m from the origin the gaps are still exact doubles.
  const double x0 = 1048576.0;
  const Plan near = plan_of({make_wall("a", {x0, 0}, {x0 + 4, 0}, 0.2),
                             make_wall("b", {x0 + 2, 0.5e-6}, {x0 + 2, 3}, 0.2)});
  EXPECT_TRUE(find_joins(near).are_joined(0, 1));
  // Exactly at the tolerance (2^-20 m, an exact double) still joins; one ulp more does not.
  Plan edge =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {2, 0x1p-20}, {2, 3}, 0.2)});
  edge.site.tolerance = 0x1p-20;
  EXPECT_TRUE(find_joins(edge).are_joined(1, 0));
  edge.walls[1].from.y = std::nextafter(0x1p-20, 1.0);
  EXPECT_FALSE(find_joins(edge).are_joined(1, 0));
  const Plan far = plan_of({make_wall("a", {x0, 0}, {x0 + 4, 0}, 0.2),
                            make_wall("b", {x0 + 2, 2e-6}, {x0 + 2, 3}, 0.2)});
  EXPECT_FALSE(find_joins(far).are_joined(0, 1));
  EXPECT_EQ(find_joins(far).find(0, 1), nullptr);
}

TEST(Joins, EndPointsWithinToleranceAreMitred) {
  Plan p =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {0.5e-6, 0.5e-6}, {0, 3}, 0.2)});
  const Joins j = find_joins(p);
  ASSERT_TRUE(j.are_joined(0, 1));
  EXPECT_EQ(j.find(1, 0)->kind, JoinKind::mitre);
  p.site.tolerance = 1e-7;
  EXPECT_FALSE(find_joins(p).are_joined(0, 1));
}

TEST(Joins, ChainOfEndsWithinToleranceUnitesAll) {
  // Ends at x = 0, 0.8e-6 and 1.6e-6: neighbours are within 1e-6, the outer two are not.
  const Plan p =
      plan_of({make_wall("a", {0, 0}, {0, -3}, 0.2), make_wall("b", {0.8e-6, 0}, {3, 3}, 0.2),
               make_wall("c", {1.6e-6, 0}, {3, -3}, 0.2)});
  const Joins j = find_joins(p);
  for (const Join& join : j.pairs) EXPECT_EQ(join.kind, JoinKind::unite);
  for (const auto& m : j.mitre) {
    EXPECT_FALSE(m[0].has_value());
    EXPECT_FALSE(m[1].has_value());
  }
}

TEST(Joins, WallsApartAndDegenerateWallsJoinNothing) {
  const Plan p =
      plan_of({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {0, 1}, {4, 1}, 0.2),
               make_wall("z", {2, 0}, {2, 0}, 0.2), make_wall("n", {NAN, 0}, {2, 0}, 0.2)});
  const Joins j = find_joins(p);
  EXPECT_TRUE(j.pairs.empty());
  EXPECT_EQ(j.mitre.size(), 4u);
}

TEST(Joins, ClosedRingOfFourWallsIsFourMitres) {
  const Plan p =
      plan_of({make_wall("s", {0, 0}, {4, 0}, 0.2), make_wall("e", {4, 0}, {4, 3}, 0.2),
               make_wall("n", {4, 3}, {0, 3}, 0.2), make_wall("w", {0, 3}, {0, 0}, 0.2)});
  const Joins j = find_joins(p);
  ASSERT_EQ(j.pairs.size(), 4u);
  for (const Join& join : j.pairs) EXPECT_EQ(join.kind, JoinKind::mitre);
  for (std::size_t w = 0; w < 4; ++w) {
    const auto f = wall_footprint(p, j, w);
    const std::size_t next = (w + 1) % 4;
    // This wall's to-end is the next wall's from-end: the outer (right) corners coincide.
    EXPECT_EQ(f[1], wall_footprint(p, j, next)[0]);
    EXPECT_EQ(f[2], wall_footprint(p, j, next)[3]);
  }
}

}  // namespace
}  // namespace roomcad
