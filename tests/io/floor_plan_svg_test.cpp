// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/floor_plan_svg.h"

#include <gtest/gtest.h>

namespace roomcad {
namespace {

FloorPlanDrawing small_drawing() {
  FloorPlanDrawing d;
  d.width = 100;
  d.height = 80;
  d.cut_walls.push_back({{10, 10}, {50, 10}, {50, 15}, {10, 15}});
  d.windows.push_back({{20, 10}, {30, 10}});
  d.door_leaves.push_back({{60, 15}, {60, 35}});
  // A quarter turn from straight below the centre to its right: on paper (y down) that turns
  // towards negative angles, so SVG's sweep flag is 0.
  d.door_swings.push_back({{60, 15}, {60, 35}, {80, 15}, 20});
  d.dimension_texts.push_back({{30, 5}, "4.00", 2.5, -90.0, TextAnchor::middle});
  return d;
}

TEST(FloorPlanSvg, GroupsElementsAndTurnsArcsTheRightWay) {
  const std::string svg = make_floor_plan_svg(small_drawing(), "plan").to_string();
  const auto has = [&](const std::string& s) { return svg.find(s) != std::string::npos; };
  EXPECT_TRUE(has("width=\"100mm\" height=\"80mm\" viewBox=\"0 0 100 80\""));
  EXPECT_TRUE(
      has("<g id=\"cut-walls\" class=\"cut-walls\" fill=\"#1a1a1a\">\n"
          "<polygon points=\"10,10 50,10 50,15 10,15\"/>"));
  EXPECT_TRUE(has("<g id=\"windows\""));
  EXPECT_TRUE(has("<path d=\"M60,35 A20,20 0 0 0 80,15\" fill=\"none\"/>")) << svg;
  EXPECT_TRUE(has("transform=\"rotate(-90 30 5)\">4.00</text>"));
  EXPECT_EQ(svg, make_floor_plan_svg(small_drawing(), "plan").to_string());
}

TEST(FloorPlanSvg, ClockwiseSwingSetsTheSweepFlag) {
  FloorPlanDrawing d = small_drawing();
  std::swap(d.door_swings[0].from, d.door_swings[0].to);
  const std::string svg = make_floor_plan_svg(d, "").to_string();
  EXPECT_NE(svg.find("<path d=\"M80,15 A20,20 0 0 1 60,35\""), std::string::npos) << svg;
}

}  // namespace
}  // namespace roomcad
