// SPDX-License-Identifier: GPL-3.0-or-later
// analytic_wall_volume (mesh/mesh_check.h) on what is not a stack of flat slabs: sloped
// tops, shaped holes, slabs. Each expected volume is worked out by hand in its comment; the
// sloped and shaped cases are also checked against the built mesh's volume (check_solid).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plan/signed_area.h"
#include "solid/analytic_volume.h"
#include "support/model_support.h"

namespace roomcad {
namespace {

using test::add_opening;
using test::add_wall;
using test::empty_plan;

constexpr double kRelative = 1e-12;  // the analytic volume is exact, rounded once

void expect_volume(const Plan& plan, double expected) {
  EXPECT_NEAR(analytic_wall_volume(plan), expected, kRelative * expected);
}

// The built solid is valid and its volume is the analytic one to 1e-9 relative.
void expect_mesh_agrees(const Plan& plan) {
  const double analytic = analytic_wall_volume(plan);
  const Model model = build_model(plan);
  const SolidCheck check = check_solid(model.walls);
  EXPECT_TRUE(check.is_closed());
  EXPECT_TRUE(check.is_manifold());
  EXPECT_TRUE(check.is_valid());
  EXPECT_NEAR(check.volume, analytic, 1e-9 * analytic);
}

Slab& add_slab(Plan& plan, const std::string& id, Polygon outline, double top, double thickness) {
  Slab& s = plan.slabs.emplace_back();
  s.id = id, s.outline = std::move(outline), s.top = top, s.thickness = thickness;
  return s;
}

// A door-like arch: the unit square's lower part, then a half circle of `n` segments on top.
Polygon arch(int n) {
  Polygon p{{0.0, 0.0}, {1.0, 0.0}};
  for (int k = 0; k <= n; ++k) {
    const double a = std::numbers::pi * k / n;
    p.push_back({0.5 + 0.5 * std::cos(a), 0.5 + 0.5 * std::sin(a)});
  }
  return p;
}

TEST(AnalyticVolume, ALoneSlopedWallIsItsTrapezoidSide) {
  Plan plan = empty_plan();
  add_wall(plan, "s", {0, 0}, {4, 0}).height = 2.0;
  plan.walls[0].height_at_end = 3.0;
  // Square caps: length 4 x thickness 0.2 x mean height (2 + 3) / 2 = 2.0.
  expect_volume(plan, 4 * 0.2 * 2.5);
  expect_mesh_agrees(plan);
}

TEST(AnalyticVolume, ASlopedWallMitredToATallerFlatWall) {
  Plan plan = empty_plan();
  add_wall(plan, "s", {0, 0}, {4, 0}).height = 2.0;
  plan.walls[0].height_at_end = 3.0;  // top z = 2 + x / 4
  add_wall(plan, "f", {4, 0}, {4, 3}).height = 3.5;
  // s: the rectangle [0, 3.9] x [-0.1, 0.1] (area 0.78, mean top at x = 1.95) plus the mitre's
  // triangle (3.9, -0.1), (4.1, -0.1), (3.9, 0.1) (area 0.02, centroid x = 11.9 / 3).
  // f: centre-line length 3 x 0.2 (the mitre's triangles cancel) x 3.5.
  const double s = 0.78 * (2 + 1.95 / 4) + 0.02 * (2 + 11.9 / 3 / 4);
  expect_volume(plan, s + 0.6 * 3.5);
  expect_mesh_agrees(plan);
}

TEST(AnalyticVolume, ATopCrossingAnotherWallsCornerInsideAnIntervalIsAnEvent) {
  Plan plan = empty_plan();
  add_wall(plan, "s", {0, 0}, {4, 0}).height = 1.0;
  plan.walls[0].height_at_end = 3.0;  // top z = 1 + x / 2
  add_wall(plan, "t", {3, -1}, {3, 1}).height = 3.0;
  // s: 4 x 0.2 x 2 = 1.6; t: 2 x 0.2 x 3 = 1.2; both: the square [2.9, 3.1] x [-0.1, 0.1]
  // under s's top (mean 2.5 at x = 3): 0.04 x 2.5 = 0.1. Union 2.7.
  // Only the corners' heights (0, 1, 3) as events: Simpson over [1, 3] with A(1) = 1.16,
  // A(2) = 0.76, A(3) = 0.4 gives 1.5333 instead of 1.54 (the top passes t's corners at
  // z = 2.45 and 2.55): 2.6933, wrong.
  expect_volume(plan, 2.7);
}

TEST(AnalyticVolume, ATriangularOpeningRemovesItsPrism) {
  Plan plan = empty_plan();
  add_wall(plan, "w", {0, 0}, {4, 0});
  add_opening(plan, "tri", OpeningType::window, "w", 1, 1.2, 1, 0.9).shape = {
      {0, 0}, {1, 0}, {0.5, 1}};
  // 4 x 0.2 x 2.5 = 2, minus the triangle 1.2 x 0.9 / 2 = 0.54 through 0.2: 0.108.
  expect_volume(plan, 2.0 - 0.108);
  expect_mesh_agrees(plan);
}

TEST(AnalyticVolume, ANonConvexOpeningRemovesItsPrism) {
  Plan plan = empty_plan();
  add_wall(plan, "w", {0, 0}, {4, 0});
  add_opening(plan, "l", OpeningType::window, "w", 1, 1, 0.5, 1.5).shape = {
      {0, 0}, {1, 0}, {1, 0.4}, {0.4, 0.4}, {0.4, 1}, {0, 1}};
  // The L covers 1 - 0.6 x 0.6 = 0.64 of its 1 x 1.5 rectangle: 0.96 m^2, x 0.2 = 0.192.
  expect_volume(plan, 2.0 - 0.192);
  expect_mesh_agrees(plan);
}

TEST(AnalyticVolume, AnArchedDoorRemovesItsPrism) {
  Plan plan = empty_plan();
  add_wall(plan, "w", {0, 0}, {4, 1});  // not along an axis
  const Polygon shape = arch(24);
  add_opening(plan, "arch", OpeningType::door, "w", 1, 0.9, 0, 2.2).shape = shape;
  // Length sqrt(17) x 0.2 x 2.5, minus the arch's area (shoelace) x 0.9 x 2.2 x 0.2.
  expect_volume(plan, std::sqrt(17.0) * 0.2 * 2.5 - signed_area(shape) * 0.9 * 2.2 * 0.2);
  expect_mesh_agrees(plan);
}

TEST(AnalyticVolume, AnArchUnderASlopedTopCutsWhatIsThere) {
  Plan plan = empty_plan();
  add_wall(plan, "s", {0, 0}, {4, 0}).height = 2.0;
  plan.walls[0].height_at_end = 3.0;
  add_wall(plan, "f", {4, 0}, {4, 3}).height = 3.5;
  // Its top z = 2.7 stands above the wall's top there (2.375 to 2.625).
  add_opening(plan, "arch", OpeningType::window, "s", 1.5, 1, 1.2, 1.5).shape = arch(16);
  add_opening(plan, "tri", OpeningType::window, "f", 1, 1, 1, 1).shape = {{0, 0}, {1, 0}, {0.5, 1}};
  expect_mesh_agrees(plan);
}

TEST(AnalyticVolume, ASlabIsItsOutlineMinusItsHoles) {
  Plan plan = empty_plan();
  add_slab(plan, "floor", {{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 3.0, 0.2).holes = {
      {{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
  // (4 x 3 - 1 x 1) x 0.2.
  expect_volume(plan, 11 * 0.2);
}

TEST(AnalyticVolume, AWallThroughASlabIsNotCountedTwice) {
  Plan plan = empty_plan();
  add_wall(plan, "w", {0, 0}, {4, 0}).height = 3.0;
  add_slab(plan, "floor", {{-1, -1}, {5, -1}, {5, 1}, {-1, 1}}, 2.0, 0.2);
  // Wall 4 x 0.2 x 3 = 2.4, slab 6 x 2 x 0.2 = 2.4, both: 4 x 0.2 x 0.2 = 0.16.
  expect_volume(plan, 2.4 + 2.4 - 0.16);
}

TEST(AnalyticVolume, AHoleMeetingASlabCutsItToo) {
  Plan plan = empty_plan();
  add_wall(plan, "w", {0, 0}, {4, 0}).height = 3.0;
  add_slab(plan, "floor", {{-1, -1}, {5, -1}, {5, 1}, {-1, 1}}, 2.0, 0.2);
  add_opening(plan, "d", OpeningType::door, "w", 1, 1, 0, 2.1);
  // As above, minus the door's box 1 x 0.2 x 2.1 = 0.42, the slab's part in it included
  // (keeping the slab there would leave 1 x 0.2 x 0.2 = 0.04 more).
  expect_volume(plan, 4.64 - 0.42);
}

}  // namespace
}  // namespace roomcad
