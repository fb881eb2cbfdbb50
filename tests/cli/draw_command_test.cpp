// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad draw` end to end: the floor plan view, exit statuses and messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/refused_commands.h"
#include "support/run_command.h"

namespace roomcad::test {
namespace {

namespace fs = std::filesystem;

// A 6 x 4 m room drawn counter-clockwise, with an entry door and a window in the south wall.
constexpr const char* kRoomPlan = R"({
  "format": "roomcad-plan", "version": 1, "units": "m",
  "site": { "origin": [0, 0], "cells": [8, 6], "cell_size": 1.0 },
  "walls": [
    { "id": "south", "from": [1, 1], "to": [7, 1] },
    { "id": "east",  "from": [7, 1], "to": [7, 5] },
    { "id": "north", "from": [7, 5], "to": [1, 5] },
    { "id": "west",  "from": [1, 5], "to": [1, 1] }
  ],
  "openings": [
    { "id": "entry", "type": "door", "wall": "south", "offset": 1.0, "width": 0.9 },
    { "id": "win", "type": "window", "wall": "south", "offset": 3.5, "width": 1.4 }
  ]
})";

/// @return the number of <line> elements in the first group that starts with `group`.
std::size_t lines_in(const std::string& svg, const std::string& group) {
  const std::size_t begin = svg.find(group);
  const std::size_t end = svg.find("</g>", begin);
  std::size_t n = 0;
  for (std::size_t p = svg.find("<line", begin); p < end; p = svg.find("<line", p + 1)) ++n;
  return n;
}

CommandResult draw(std::vector<std::string> args) {
  args.insert(args.begin(), "draw");
  return run_roomcad(args);
}

TEST(DrawCommand, DrawsTheFloorPlan) {
  const TempDir dir;
  const std::string plan = (dir / "room.json").string();
  ASSERT_TRUE(write_bytes(plan, kRoomPlan));
  const CommandResult run =
      draw({plan, "--view", "plan", "--scale", "1:50", "-o", (dir / "room.svg").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string svg = read_bytes(dir / "room.svg");
  for (const char* part : {"<g id=\"cut-walls\"", "<g id=\"windows\"", "<g id=\"doors\"", ">6.25<",
                           "section at 1.00 m, scale 1:50", "Room 1", "m²"}) {
    EXPECT_NE(svg.find(part), std::string::npos) << part;
  }
  // The defaults are --view plan --scale 1:50; the output is deterministic.
  ASSERT_EQ(draw({plan, "-o", (dir / "again.svg").string()}).status, 0);
  EXPECT_EQ(read_bytes(dir / "again.svg"), svg);
}

TEST(DrawCommand, PlanErrorsExitOneAndDrawNothing) {
  const TempDir dir;
  std::string bad = kRoomPlan;
  bad.replace(bad.find("\"to\": [7, 1] }"), 14, "\"to\": [7, 1], \"thickness\": -1 }");
  ASSERT_TRUE(write_bytes(dir / "bad.json", bad));
  const CommandResult run = draw({(dir / "bad.json").string(), "-o", (dir / "bad.svg").string()});
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("invalid_value"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "bad.svg"));
}

TEST(DrawCommand, BadOptionsExitTwo) {
  const TempDir dir;
  const std::string plan = (dir / "room.json").string();
  ASSERT_TRUE(write_bytes(plan, kRoomPlan));
  const std::string out = (dir / "out.svg").string();
  const test::RefusedCase cases[] = {
      {{plan, "--view", "sideways", "-o", out}, "--view"},
      {{plan, "--view", "camera:nope", "-o", out}, "no camera \"nope\""},
      {{plan, "--view", "iso", "--hidden", "grey", "-o", out}, "--hidden"},
      {{plan, "--view", "iso", "--parts", "roof", "-o", out}, "'roof'"},
      {{plan, "--scale", "1:x", "-o", out}, "--scale \"1:x\""},
      {{plan, "--scale", "1:0", "-o", out}, "scale 1:0"},
      {{plan, "--cut-height", "-1", "-o", out}, "cut height"},
      {{plan, "-o", (dir / "out.png").string()}, ".svg", Code::unsupported},
      {{(dir / "missing.json").string(), "-o", out}, "missing.json", Code::io_error},
  };
  test::expect_refused("draw", cases);
  EXPECT_FALSE(fs::exists(out));
}

TEST(DrawCommand, DrawsElevationsIsoAndCameraViews) {
  const TempDir dir;
  std::string text = kRoomPlan;
  text.replace(
      text.rfind('}'), 1,
      R"(, "cameras": [ { "id": "inside", "eye": [2, 2, 1.6], "target": [6, 4, 1.2] } ] })");
  const std::string plan = (dir / "room.json").string();
  ASSERT_TRUE(write_bytes(plan, text));
  for (const char* view : {"north", "south", "east", "west", "iso", "camera:inside"}) {
    SCOPED_TRACE(view);
    const fs::path out = dir / (std::string(view).substr(0, 6) + ".svg");
    const CommandResult run = draw({plan, "--view", view, "-o", out.string()});
    ASSERT_EQ(run.status, 0) << run.err;
    const std::string svg = read_bytes(out);
    EXPECT_NE(svg.find("<g id=\"visible\""), std::string::npos);
    EXPECT_NE(svg.find("<line"), std::string::npos);
    EXPECT_NE(svg.find(std::string(view) == "camera:inside" ? "not to scale" : "scale 1:50"),
              std::string::npos);
  }
  // The south elevation looks at the door and the window: hidden lines dashed, or left out.
  ASSERT_EQ(draw({plan, "--view", "south", "-o", (dir / "dashed.svg").string()}).status, 0);
  ASSERT_EQ(
      draw({plan, "--view", "south", "--hidden", "off", "-o", (dir / "off.svg").string()}).status,
      0);
  const std::string dashed = read_bytes(dir / "dashed.svg"), off = read_bytes(dir / "off.svg");
  EXPECT_GT(lines_in(dashed, "<g id=\"hidden\""), 0u);
  EXPECT_EQ(lines_in(off, "<g id=\"hidden\""), 0u);
}

TEST(DrawCommand, LevelDrawsTheFloorPlanOfOneStorey) {
  const TempDir dir;
  const std::string plan = (source_dir() / "examples" / "version2" / "two-storey.json").string();
  ASSERT_EQ(draw({plan, "--level", "ground", "-o", (dir / "ground.svg").string()}).status, 0);
  ASSERT_EQ(draw({plan, "--level", "first", "-o", (dir / "first.svg").string()}).status, 0);
  const std::string ground = read_bytes(dir / "ground.svg");
  const std::string first = read_bytes(dir / "first.svg");
  EXPECT_NE(ground.find("floor plan of level ground"), std::string::npos);
  EXPECT_NE(first.find("floor plan of level first"), std::string::npos);
  EXPECT_NE(ground, first);
  // Each plan draws its own storey's door leaves: two on the ground floor (entry, hall door),
  // one on the first (the bedroom door).
  EXPECT_EQ(lines_in(ground, "<g class=\"leaves\""), 2u);
  EXPECT_EQ(lines_in(first, "<g class=\"leaves\""), 1u);
  const CommandResult unknown =
      draw({plan, "--level", "cellar", "-o", (dir / "cellar.svg").string()});
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("--level 'cellar': the plan has no such level (its levels: "
                             "'ground', 'first')"),
            std::string::npos)
      << unknown.err;
  EXPECT_FALSE(fs::exists(dir / "cellar.svg"));
}

}  // namespace
}  // namespace roomcad::test
