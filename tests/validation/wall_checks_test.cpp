// SPDX-License-Identifier: GPL-3.0-or-later
// Joins excuse walls from wall_overlap (L, T, X, three-way) unless centre lines overlap;
// out_of_bounds on the site rectangle and max_height; messages with concrete fixes.
#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/joins.h"
#include "plan_cases.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;

TEST(Walls, JoinedWallsDoNotOverlapInEveryFrame) {
  const std::vector<std::pair<const char*, Plan>> joined = {
      {"L", plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {0, 0}, {0, 3})})},
      {"L of different thicknesses",
       plan_with({make_wall("a", {0, 0}, {4, 0}, 0.2), make_wall("b", {0, 3}, {0, 0}, 0.45)})},
      {"T", plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, 0}, {2, 3})})},
      {"X", plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, -2}, {2, 3})})},
      {"three-way", plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {0, 0}, {0, 3}),
                               make_wall("c", {0, 0}, {-2, -2})})},
      {"T within tolerance",
       plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, 0.5e-6}, {2, 3})})},
      {"straight continuation",
       plan_with({make_wall("a", {0, 0}, {2, 0}), make_wall("b", {2, 0}, {5, 0})})},
  };
  for (const auto& [name, plan] : joined)
    for (const Frame& f : all_frames()) {
      SCOPED_TRACE(::testing::Message() << name << " at " << f.degrees << " deg");
      EXPECT_EQ(error_codes(validate(f.apply(plan), no_rooms())), Codes{});
    }
}

TEST(Walls, JustOutsideTheToleranceIsNotJoinedAndOverlaps) {
  const Plan p = plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, 2e-6}, {2, 3})});
  for (const Frame& f : all_frames()) {
    SCOPED_TRACE(f.degrees);
    EXPECT_EQ(error_codes(validate(f.apply(p), no_rooms())), Codes{Code::wall_overlap});
  }
}

TEST(Walls, CentreLinesOverlappingAlongALengthOverlapEvenWhenJoined) {
  const Plan p = plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {3, 0}, {6, 0})});
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::wall_overlap});
  EXPECT_EQ(r.items[0].objects, (Ids{"a", "b"}));
  EXPECT_NE(r.items[0].message.find("for 1.00 m"), std::string::npos) << r.items[0].message;
}

TEST(Walls, StoreysStackedOnOneCentreLineDoNotOverlap) {
  // A wall on the storey above stands on the one below: they touch (at the lower wall's top)
  // and share a centre line, but no volume, so they are neither joined nor overlapping.
  const Wall lower = make_wall("a", {0, 0}, {4, 0});
  Wall upper = make_wall("b", {0, 0}, {4, 0});
  upper.base = lower.height;
  const Plan p = plan_with({lower, upper});
  EXPECT_FALSE(find_joins(p).are_joined(0, 1));
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{});
  upper.base = lower.height - 0.1;  // 0.1 m of the two storeys' walls now share a volume
  EXPECT_EQ(error_codes(validate(plan_with({lower, upper}), no_rooms())),
            Codes{Code::wall_overlap});
}

TEST(Walls, OverlapMessageGivesTheDepthAndAFix) {
  const Plan p = plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {0, 0.2}, {4, 0.2})});
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::wall_overlap});
  EXPECT_NE(r.items[0].message.find("overlap by 0.05 m"), std::string::npos) << r.items[0].message;
  EXPECT_NE(r.items[0].fix.find("move b 0.05 m north"), std::string::npos) << r.items[0].fix;
  ASSERT_TRUE(r.items[0].where.has_value());
  EXPECT_TRUE(r.items[0].where->max.has_value());
}

Plan on_site(Wall w) {
  Plan p;
  p.site.origin = {0, 0};
  p.site.cells = {8, 6};
  p.walls = {std::move(w)};
  return p;
}

TEST(Bounds, FootprintTouchingTheSiteEdgeIsInsideAndAMicrometrePastIsOut) {
  const double x0 = 1048576.0;  // dyadic coordinates stay exact this far out
  for (const double shift : {0.0, x0}) {
    SCOPED_TRACE(shift);
    Plan touching = on_site(make_wall("a", {shift, 1}, {shift + 4, 1}));  // square end at x0
    touching.site.origin.x = shift;
    EXPECT_EQ(error_codes(validate(touching, no_rooms())), Codes{});
    Plan out = touching;
    out.walls[0].from.x -= 1e-6;
    const Report r = validate(out, no_rooms());
    ASSERT_EQ(error_codes(r), Codes{Code::out_of_bounds});
    EXPECT_NE(r.items[0].message.find("west edge"), std::string::npos) << r.items[0].message;
  }
}

TEST(Bounds, RotatedWallCornerAgainstTheSiteEdge) {
  // The site edge is placed 1e-6 m beyond (or short of) the wall's lowest corner as rounded
  // from its exact value; the rounding (< 1e-9 m here) cannot flip a 1e-6 m margin.
  for (const double degrees : {30.0, 45.0, 71.3}) {
    SCOPED_TRACE(degrees);
    const Frame f{degrees, {1048576.0, 1048576.0}};
    Plan p = on_site(make_wall("a", f.map({0, 0}), f.map({3, 0})));
    const Joins joins = find_joins(p);
    double lowest = INFINITY;
    for (const Point2& c : wall_footprint(p, joins, 0)) lowest = std::min(lowest, c.y);
    p.site.origin = {1048570.0, lowest - 1e-6};
    p.site.cells = {16, 16};
    EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{});
    p.site.origin.y = lowest + 1e-6;
    EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::out_of_bounds});
  }
}

TEST(Bounds, MitredCornerCountsAndHeightIsExact) {
  // The outer mitre corner reaches (0.875, 0.875); a site starting there holds it exactly.
  Plan p = on_site(make_wall("a", {1, 1}, {4, 1}));
  p.walls.push_back(make_wall("b", {1, 1}, {1, 4}));
  p.site.origin = {0.875, 0.875};
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{});
  p.site.origin = {0.875 + 1e-6, 0};
  EXPECT_EQ(error_codes(validate(p, no_rooms())),
            (Codes{Code::out_of_bounds, Code::out_of_bounds}));

  Plan tall = on_site(make_wall("a", {1, 1}, {4, 1}));
  tall.walls[0].base = 0.1;
  // As read, 0.1 is 0.10000000000000000555 and 5.9 is 5.9000000000000003553: their sum is
  // 6.00000000000000036, above 6, though in doubles 0.1 + 5.9 rounds to exactly 6.
  tall.walls[0].height = 5.9;
  tall.site.max_height = 6.0;
  ASSERT_EQ(0.1 + 5.9, 6.0);
  const Report r = validate(tall, no_rooms());
  EXPECT_EQ(error_codes(r), Codes{Code::out_of_bounds});
  tall.walls[0].height = 5.875;
  EXPECT_EQ(error_codes(validate(tall, no_rooms())), Codes{});
}

TEST(Walls, OnLevelsStandingOnOneAnotherNeitherJoinNorOverlap) {
  // A foundation wall on the level below and the wall above it on the same centre line, as
  // IFC models (duplex.ifc) and storeys drawn one over the other have them; the upper wall's
  // window at the foot of the upper wall. Judged with the levels resolved, they only touch.
  Plan p = plan_with({make_wall("foundation", {1, 1}, {9, 1}), make_wall("wall", {1, 1}, {9, 1})});
  p.levels = {{.id = "base", .elevation = 0.0, .height = 1.25},
              {.id = "ground", .elevation = 1.25, .height = 2.8}};
  p.walls[0].level = "base", p.walls[0].height = 1.25;
  p.walls[1].level = "ground", p.walls[1].height = 2.8;
  p.site.max_height = 6.0;
  p.openings.push_back(make_opening("low", OpeningType::window, "wall", 2, 1.2, 1.0, 0.0));
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{});
  // Let the foundation reach up into the storey above: now the two overlap (one wall drawn
  // twice along that height), and the window is blocked by the wall below.
  p.walls[0].height = 1.75;
  const Codes clash = error_codes(validate(p, no_rooms()));
  EXPECT_EQ(std::count(clash.begin(), clash.end(), Code::wall_overlap), 1);
  EXPECT_EQ(std::count(clash.begin(), clash.end(), Code::opening_blocked), 1);
}

}  // namespace
}  // namespace roomcad
