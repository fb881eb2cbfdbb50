#include "render/floor_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace roomcad {
namespace {

// One straight wall, 4 m along x, 0.2 m thick, with a window (sill 0.9, top 2.2) at u = 1..2
// and a door at u = 2.5..3.3. At 1:50 a metre is 20 mm; the page margin is 30 mm and the plan's
// top edge (y = 0.1) is at paper y = 30, so plan (u, across) is paper (30 + 20u, 32 - 20 across).
Plan one_wall_plan() {
  Plan plan;
  Wall wall;
  wall.id = "w";
  wall.from = {0, 0};
  wall.to = {4, 0};
  wall.thickness = 0.2;
  plan.walls.push_back(wall);
  Opening window;
  window.id = "win";
  window.type = OpeningType::window;
  window.wall = "w";
  window.offset = 1.0;
  window.width = 1.0;
  window.sill = 0.9;
  window.height = 1.3;
  Opening door;
  door.id = "door";
  door.wall = "w";
  door.offset = 2.5;
  door.width = 0.8;
  plan.openings = {door, window};  // out of order on purpose: drawing sorts along the wall
  return plan;
}

Point2 paper(double u, double across) { return {30.0 + 20.0 * u, 32.0 - 20.0 * across}; }

void expect_near(Point2 got, Point2 want) {
  EXPECT_NEAR(got.x, want.x, 1e-9);
  EXPECT_NEAR(got.y, want.y, 1e-9);
}

/// @return the [min, max] paper x of a polygon.
std::pair<double, double> x_span(const PaperPolygon& polygon) {
  const auto [lo, hi] = std::minmax_element(polygon.begin(), polygon.end(),
                                            [](Point2 a, Point2 b) { return a.x < b.x; });
  return {lo->x, hi->x};
}

TEST(FloorPlan, CutsTheWallAtTheOpeningsTheSectionPasses) {
  const FloorPlanDrawing d = draw_floor_plan(one_wall_plan(), {});
  ASSERT_EQ(d.cut_walls.size(), 3u);
  const double want[3][2] = {{0.0, 1.0}, {2.0, 2.5}, {3.3, 4.0}};
  for (int i = 0; i < 3; ++i) {
    const auto [lo, hi] = x_span(d.cut_walls[i]);
    EXPECT_NEAR(lo, paper(want[i][0], 0).x, 1e-9) << i;
    EXPECT_NEAR(hi, paper(want[i][1], 0).x, 1e-9) << i;
  }
  // The window symbol: three lines along the wall, on both faces and the centre line.
  ASSERT_EQ(d.windows.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const double across = -0.1 + 0.1 * i;
    expect_near(d.windows[i].a, paper(1.0, across));
    expect_near(d.windows[i].b, paper(2.0, across));
  }
  EXPECT_DOUBLE_EQ(d.width, 4 * 20 + 60.0);
  EXPECT_DOUBLE_EQ(d.height, 0.2 * 20 + 60.0 + 25.0);
}

TEST(FloorPlan, DrawsTheDoorLeafAndSwingPerHingeAndSwing) {
  Plan plan = one_wall_plan();
  FloorPlanDrawing d = draw_floor_plan(plan, {});
  // hinge left, swing in: turns about u = 2.5 on the left face, opens towards +y.
  ASSERT_EQ(d.door_leaves.size(), 1u);
  ASSERT_EQ(d.door_swings.size(), 1u);
  expect_near(d.door_leaves[0].a, paper(2.5, 0.1));
  expect_near(d.door_leaves[0].b, paper(2.5, 0.9));
  expect_near(d.door_swings[0].centre, paper(2.5, 0.1));
  expect_near(d.door_swings[0].from, paper(2.5, 0.9));
  expect_near(d.door_swings[0].to, paper(3.3, 0.1));
  EXPECT_DOUBLE_EQ(d.door_swings[0].radius, 16.0);
  // hinge right, swing out: turns about u = 3.3 on the right face, opens towards -y.
  plan.openings[0].hinge = Hinge::right;
  plan.openings[0].swing = Swing::out;
  d = draw_floor_plan(plan, {});
  expect_near(d.door_leaves[0].a, paper(3.3, -0.1));
  expect_near(d.door_leaves[0].b, paper(3.3, -0.9));
  expect_near(d.door_swings[0].to, paper(2.5, -0.1));
}

TEST(FloorPlan, WindowOutsideTheCutLeavesTheWallWhole) {
  const FloorPlanDrawing d = draw_floor_plan(one_wall_plan(), {.cut_height = 2.5});
  EXPECT_TRUE(d.windows.empty());
  EXPECT_EQ(d.cut_walls.size(), 2u);  // only the door is cut
  EXPECT_EQ(d.door_leaves.size(), 1u);
}

TEST(FloorPlan, WallsBelowAndAboveTheCutAreSeenNotCut) {
  Plan plan = one_wall_plan();
  plan.walls[0].height = 0.8;
  FloorPlanDrawing d = draw_floor_plan(plan, {});
  EXPECT_TRUE(d.cut_walls.empty());
  EXPECT_EQ(d.walls_below.size(), 1u);
  EXPECT_TRUE(d.door_leaves.empty());
  plan.walls[0].height = 2.8;
  plan.walls[0].base = 1.5;
  d = draw_floor_plan(plan, {});
  EXPECT_EQ(d.walls_above.size(), 1u);
  EXPECT_TRUE(d.walls_below.empty());
}

TEST(FloorPlan, DimensionsScaleBarAndTitle) {
  const FloorPlanDrawing d = draw_floor_plan(one_wall_plan(), {.scale = 50});
  std::vector<std::string> texts;
  for (const PaperText& t : d.dimension_texts) texts.push_back(t.text);
  // The wall's own length, then the overall width and depth of the plan.
  EXPECT_EQ(texts, (std::vector<std::string>{"4.00", "4.00", "0.20"}));
  EXPECT_DOUBLE_EQ(d.dimension_texts[2].rotate_deg, -90.0);  // read from the right
  EXPECT_EQ(d.scale_bar_black.size() + d.scale_bar_white.size(), 5u);
  ASSERT_GE(d.labels.size(), 3u);
  EXPECT_EQ(d.labels[1].text, "2 m");  // the longest round length fitting 40 mm at 1:50
  EXPECT_NE(d.labels.back().text.find("section at 1.00 m, scale 1:50"), std::string::npos);
}

TEST(FloorPlan, RejectsBadOptions) {
  EXPECT_NE(check_floor_plan_options({.scale = 0}).find("scale"), std::string::npos);
  EXPECT_NE(check_floor_plan_options({.cut_height = -1}).find("cut height"), std::string::npos);
  EXPECT_THROW((void)draw_floor_plan(one_wall_plan(), {.scale = NAN}), std::invalid_argument);
  EXPECT_TRUE(check_floor_plan_options({}).empty());
}

}  // namespace
}  // namespace roomcad
