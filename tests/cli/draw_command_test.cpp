// `roomcad draw` end to end: the floor plan view, exit statuses and messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

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
  const struct {
    std::vector<std::string> args;
    std::string message;
  } cases[] = {
      {{plan, "--view", "north", "-o", out}, "--view"},
      {{plan, "--scale", "1:x", "-o", out}, "--scale \"1:x\""},
      {{plan, "--scale", "1:0", "-o", out}, "scale 1:0"},
      {{plan, "--cut-height", "-1", "-o", out}, "cut height"},
      {{plan, "-o", (dir / "out.png").string()}, ".svg"},
      {{(dir / "missing.json").string(), "-o", out}, "missing.json"},
  };
  for (const auto& c : cases) {
    const CommandResult run = draw(c.args);
    EXPECT_EQ(run.status, 2) << c.message << "\n" << run.err;
    EXPECT_NE((run.out + run.err).find(c.message), std::string::npos) << run.out << run.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace roomcad::test
