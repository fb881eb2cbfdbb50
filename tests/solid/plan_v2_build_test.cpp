// SPDX-License-Identifier: GPL-3.0-or-later
// Version 2 plans built (docs/plan-format.md "Version 2"): levels resolved (plan_levels.h, its
// own tests in plan_levels_test.cpp),
// arc walls as their chord polylines (arc_chords.h) with openings across chords, on every
// path against Nef and the analytic volume; sloped tops and shaped openings built closed, with
// the analytic volume (analytic_volume_test.cpp checks that volume itself).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "plan/arc_chords.h"
#include "plan/plan_chords.h"
#include "plan/plan_levels.h"
#include "solid/analytic_volume.h"
#include "support/model_support.h"
#include "testing/tower_plan.h"

namespace roomcad {
namespace {

using test::add_opening;
using test::add_room;
using test::add_wall;
using test::empty_plan;
using test::expect_paths_agree;

Plan two_storeys() {
  Plan plan = empty_plan();
  plan.levels = {{"ground", 0.0, 2.8, {}}, {"first", 3.0, 2.6, {}}};
  add_room(plan, "g", 0, 0, 4, 3);
  add_room(plan, "f", 0, 0, 4, 3);
  for (Wall& w : plan.walls) w.level = w.id[0] == 'g' ? "ground" : "first";
  plan.walls[4].base = 0.1;  // measured from the first level's elevation
  return plan;
}

double lowest_z(const SolidMesh& mesh) {
  double z = INFINITY;
  for (const auto v : mesh.vertices()) z = std::min(z, mesh.point(v)[2]);
  return z;
}

TEST(PlanV2Build, EachStoreyStandsOnItsLevel) {
  const Plan plan = two_storeys();
  // Both rooms: walls 0.2 thick on a 4 x 3 centre-line rectangle, mitred: area 0.2 x 14.
  expect_paths_agree(plan, 2, 0.2 * 14 * 2.5 * 2);
  const Model first = build_model(plan_of_level(plan, "first"));
  EXPECT_EQ(lowest_z(first.walls), 3.0);  // the level's elevation (the 0.1 base is one wall's)
  EXPECT_EQ(lowest_z(build_model(plan_of_level(plan, "ground")).walls), 0.0);
}

TEST(PlanV2Build, TheCountIsTheSmallestWithinTheTolerance) {
  for (const double extent : {10.0, 60.0, -90.0, 180.0, 270.0, 359.0}) {
    for (const double tolerance : {0.1, 0.001, 1e-5}) {
      const double span = 6.0, theta = std::abs(extent) * std::numbers::pi / 180.0;
      const double radius = span / (2.0 * std::sin(theta / 2.0));
      const std::size_t n = chord_count(span, extent, tolerance);
      auto sagitta = [&](std::size_t k) {
        return radius * (1.0 - std::cos(theta / (2.0 * double(k))));
      };
      if (n > kMaxChords) {  // 359 degrees within 1e-5 m: refused by chord_polyline
        EXPECT_GT(sagitta(kMaxChords), tolerance) << extent << " " << tolerance;
        continue;
      }
      EXPECT_LE(sagitta(n), tolerance) << extent << " " << tolerance;
      if (n > 1) {
        EXPECT_GT(sagitta(n - 1), tolerance) << extent << " " << tolerance;
      }
    }
  }
}

TEST(PlanV2Build, ThePolylineRunsOnTheCircleFromFromToTo) {
  Wall w;
  w.id = "bow", w.from = {11, 1}, w.to = {11, 7}, w.arc_extent = 60.0;
  const std::vector<Point2> line = chord_polyline(w, 0.001);
  ASSERT_GT(line.size(), 3u);
  EXPECT_EQ(line.front(), w.from);
  EXPECT_EQ(line.back(), w.to);
  // 60 degrees over a 6 m chord: radius 6, the centre to the left of from -> to (x = 11 - 6 cos
  // 30).
  const Point2 centre{11.0 - 6.0 * std::cos(std::numbers::pi / 6.0), 4.0};
  for (const Point2& p : line) EXPECT_NEAR(std::hypot(p.x - centre.x, p.y - centre.y), 6.0, 1e-12);
  for (const Point2& p : line) EXPECT_GE(p.x, 11.0);  // away from the centre
  w.arc_extent = -60.0;  // clockwise: the centre on the right, the bulge on the left
  for (const Point2& p : chord_polyline(w, 0.001)) EXPECT_LE(p.x, 11.0);
  w.arc_extent.reset();
  EXPECT_EQ(chord_polyline(w, 0.001).size(), 2u);
}

TEST(PlanV2Build, TooManyChordsAreRefusedNamingTheWall) {
  Wall w;
  w.id = "bow", w.from = {0, 0}, w.to = {1e6, 0}, w.arc_extent = 180.0;
  try {
    (void)chord_polyline(w, 1e-9);
    FAIL() << "no refusal";
  } catch (const PreconditionError& e) {
    EXPECT_EQ(e.code(), Code::too_large);
    EXPECT_NE(std::string(e.what()).find("'bow'"), std::string::npos) << e.what();
  }
}

// A bow wall of 60 degrees closing a room, with a window across several of its chords.
Plan bow_room() {
  Plan plan = empty_plan();
  plan.site.chord_tolerance = 0.01;
  add_wall(plan, "s", {5, 1}, {11, 1});
  add_wall(plan, "bow", {11, 1}, {11, 7}).arc_extent = 60.0;
  add_wall(plan, "n", {11, 7}, {5, 7});
  add_wall(plan, "w", {5, 7}, {5, 1});
  return plan;
}

TEST(PlanV2Build, AnArcWallIsItsMitredChordPolylineOnEveryPath) {
  Plan plan = bow_room();
  const double bow = polyline_length(chord_polyline(plan.walls[1], 0.01));
  // Mitred all round, every wall's plan area is thickness x centre-line length.
  const double volume = 0.2 * (6 + bow + 6 + 6) * 2.5;
  expect_paths_agree(plan, 1, volume);
}

TEST(PlanV2Build, AnOpeningAcrossChordsIsOneHoleThroughTheirMitres) {
  Plan plan = bow_room();
  const double bow = polyline_length(chord_polyline(plan.walls[1], 0.01));
  // A window of 2 m along the polyline over three chord corners (10 chords of 0.628 m): its
  // hole is 0.2 x 2 x 1, the mitres' wedges included, and one tunnel (genus 2).
  add_opening(plan, "win", OpeningType::window, "bow", 2.0, 2.0, 1.0, 1.0);
  ASSERT_EQ(chord_count(6.0, 60.0, 0.01), 10u);
  const double volume = 0.2 * (6 + bow + 6 + 6) * 2.5 - 0.2 * 2.0 * 1.0;
  // Nef merges the sill across the chords into one face that no single chord's hole holds,
  // so its face labels are not compared here; the solids are.
  const SolidCheck nef = test::expect_valid_walls(plan, BooleanPath::nef, 2, volume);
  for (const BooleanPath path : {BooleanPath::automatic, BooleanPath::general}) {
    const SolidCheck c = test::expect_valid_walls(plan, path, 2, volume);
    EXPECT_NEAR(c.volume, nef.volume, 1e-12 * volume);
  }
}

TEST(PlanV2Build, AShapedOpeningAcrossChordsIsRefusedNamingItNotCutApart) {
  Plan plan = bow_room();
  add_opening(plan, "gable", OpeningType::window, "bow", 2.0, 2.0, 1.0, 1.0).shape = {
      {0, 0}, {1, 0}, {0.5, 1}};
  test::expect_build_refused(plan, {}, Code::not_buildable,
                             "opening 'gable' has a shape and spans corners");
  // Within one chord (10 chords of 0.628 m) it is cut: a triangle of 0.4 x 0.5 through 0.2.
  plan.openings[0].offset = 0.1, plan.openings[0].width = 0.4, plan.openings[0].height = 0.5;
  const double bow = polyline_length(chord_polyline(plan.walls[1], 0.01));
  test::expect_valid_walls(plan, BooleanPath::automatic, 2,
                           0.2 * (6 + bow + 6 + 6) * 2.5 - 0.2 * 0.1);
}

TEST(PlanV2Build, FacesNameThePlansWallsAndOpenings) {
  Plan plan = bow_room();
  add_opening(plan, "win", OpeningType::window, "bow", 2.0, 2.0, 1.0, 1.0);
  for (const BooleanPath path : {BooleanPath::automatic, BooleanPath::nef}) {
    const Model model = build_model(plan, test::options_for(path));
    ASSERT_EQ(model.objects.size(), 5u);
    const FacePropertyHandles props = face_property_handles(model.walls);
    std::set<int> named;
    for (const auto f : model.walls.faces()) named.insert(model.walls.property(props.object, f));
    EXPECT_EQ(named, (std::set<int>{0, 1, 2, 3, 4}));  // the four walls and the window
  }
}

TEST(PlanV2Build, SlopedTopsAndShapedOpeningsBuildClosedWithTheAnalyticVolume) {
  Plan plan = bow_room();
  plan.walls[0].height_at_end = 1.0;
  add_opening(plan, "arch", OpeningType::window, "s", 1, 1, 1, 1).shape = {
      {0, 0}, {1, 0}, {0.5, 1}};
  const Model model = build_model(plan);
  const SolidCheck check = check_solid(model.walls);
  EXPECT_TRUE(check.is_closed());
  EXPECT_TRUE(check.is_manifold());
  EXPECT_TRUE(check.is_valid());
  const double analytic = analytic_wall_volume(plan);
  EXPECT_NEAR(check.volume, analytic, 1e-9 * analytic);
}

TEST(PlanV2Build, AGeneratedTowerOfStoreysAndFloorsIsOneClosedSolid) {
  // 3 storeys of the 2 x 2 grid (bench/build_bench.cpp builds 6 of 6 x 6), each on its floor.
  // Walls per storey: plan area 12 x 4 x 0.2 less what the 4 tees (0.2^2 / 2 each) and the
  // cross (0.2^2) count twice = 9.48 m^2, 2.8 high, less 4 doors 0.9 x 2.1 and 24 windows
  // 0.8 x 1.2 through 0.2: 20.424 m^3. Floors: 8.2 x 8.2 x 0.2, above the ground storey less
  // a stair well 1 x 2.6. The walls stand on their floor and reach the next one: no overlap.
  samples::TowerSpec spec;
  spec.storey.n = 2;
  spec.storeys = 3;
  const Plan plan = samples::make_tower_plan(spec);
  ASSERT_EQ(plan.walls.size(), 36u);
  const double expected = 3 * 20.424 + 0.2 * (3 * 67.24 - 2 * 2.6);
  for (const BooleanPath path : {BooleanPath::automatic, BooleanPath::general}) {
    const Model model = build_model(plan, test::options_for(path));
    const SolidCheck check = check_solid(model.walls);
    EXPECT_TRUE(check.is_closed());
    EXPECT_TRUE(check.is_manifold());
    EXPECT_TRUE(check.is_valid());
    EXPECT_NEAR(check.volume, expected, 1e-9 * expected);
    EXPECT_NEAR(analytic_wall_volume(plan), expected, 1e-9 * expected);
  }
}

}  // namespace
}  // namespace roomcad
