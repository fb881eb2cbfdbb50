// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad surface` end to end: exit statuses, messages and the files it writes.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/refused_commands.h"
#include "support/run_command.h"

namespace roomcad::test {
namespace {

namespace fs = std::filesystem;

CommandResult surface(std::vector<std::string> args) {
  args.insert(args.begin(), "surface");
  return run_roomcad(args);
}

TEST(SurfaceCommand, WritesAnSvgOfTheSaddle) {
  const TempDir dir;
  const CommandResult run =
      surface({"x*x - z*z", "--x", "-2:2", "--z", "-2:2", "-o", (dir / "saddle.svg").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string svg = read_bytes(dir / "saddle.svg");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("width=\"200mm\" height=\"150mm\""), std::string::npos);
  EXPECT_NE(svg.find("<g id=\"upper\""), std::string::npos);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  // Deterministic: the same command gives the same bytes.
  ASSERT_EQ(surface({"x*x - z*z", "--x", "-2:2", "--z", "-2:2", "-o", (dir / "again.svg").string()})
                .status,
            0);
  EXPECT_EQ(read_bytes(dir / "again.svg"), svg);
}

TEST(SurfaceCommand, WritesAPngOfTheDampedWave) {
  const TempDir dir;
  const fs::path out = dir / "wave.png";
  const CommandResult run =
      surface({"cos(sqrt(x*x+z*z))/(sqrt(x*x+z*z)+1)", "--x=-2*pi:2*pi", "--z=-2*pi:2*pi",
               "--width", "320", "--height", "200", "-o", out.string()});
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string png = read_bytes(out);
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // IHDR holds the size, big-endian, at bytes 16..23.
  const auto u32 = [&](std::size_t at) {
    unsigned value = 0;
    for (std::size_t i = 0; i < 4; ++i)
      value = value << 8 | static_cast<unsigned char>(png[at + i]);
    return value;
  };
  EXPECT_EQ(u32(16), 320u);
  EXPECT_EQ(u32(20), 200u);
}

TEST(SurfaceCommand, ExpressionStartingWithMinusGoesAfterDoubleDash) {
  const TempDir dir;
  const CommandResult run =
      surface({"--x", "-2:2", "--z", "-2:2", "-o", (dir / "cap.svg").string(), "--", "-x*x"});
  EXPECT_EQ(run.status, 0) << run.err;
}

TEST(SurfaceCommand, UndefinedEverywhereWarnsAndDrawsAnEmptyPicture) {
  const TempDir dir;
  const CommandResult run =
      surface({"sqrt(-1-x*x)", "--x", "-1:1", "--z", "-1:1", "-o", (dir / "none.svg").string()});
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("has no finite value"), std::string::npos) << run.err;
  EXPECT_EQ(read_bytes(dir / "none.svg").find("<polyline"), std::string::npos);
}

TEST(SurfaceCommand, BadExpressionNamesTheColumn) {
  const TempDir dir;
  const CommandResult run =
      surface({"x^", "--x", "-2:2", "--z", "-2:2", "-o", (dir / "bad.svg").string()});
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(test::failure_code(run), Code::usage_error);
  EXPECT_NE(run.err.find("EXPR \"x^\": expected a number, variable or '(' at column 3"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "bad.svg"));
}

TEST(SurfaceCommand, BadOptionsExitTwoAndWriteNothing) {
  const TempDir dir;
  const std::string out = (dir / "out.svg").string();
  const test::RefusedCase cases[] = {
      {{"x", "--x", "2", "--z", "-1:1", "-o", out}, "--x \"2\": expected A:B"},
      {{"x", "--x", "-1:1", "--z", "q:1", "-o", out}, "--z \"q:1\""},
      {{"x", "--x", "-1:x", "--z", "-1:1", "-o", out}, "must not use x or z"},
      {{"x", "--x", "-1:1", "--z", "-1:1", "--dx", "0", "-o", out}, "dx must be positive, got 0"},
      {{"x", "--x", "-1:1", "--z", "-1:1", "--rotate-x", "90", "-o", out}, "rotate_x"},
      {{"x", "--x", "1:-1", "--z", "-1:1", "-o", out}, "x range 1:-1 is empty"},
      {{"x", "--x", "-1:1", "--z", "-1:1", "--dx", "1e-7", "-o", out}, "samples"},
      {{"x", "--x", "-1:1", "--z", "-1:1", "--width", "5", "-o", out}, "--width"},
      {{"x", "--x", "-1:1", "--z", "-1:1", "-o", (dir / "out.txt").string()},
       ".svg or .png",
       Code::unsupported},
      {{"x", "--x", "-1:1", "--z", "-1:1"}, "--output is required"},
  };
  test::expect_refused("surface", cases);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(SurfaceCommand, UnwritableOutputExitsTwo) {
  const TempDir dir;
  const fs::path out = dir / "no" / "such" / "dir" / "out.svg";
  const CommandResult run = surface({"x", "--x", "-1:1", "--z", "-1:1", "-o", out.string()});
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(test::failure_code(run), Code::io_error);
  EXPECT_NE(run.err.find("out.svg"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace roomcad::test
