// `roomcad surface` end to end: exit statuses, messages and the files it writes.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_test_support.h"

namespace roomcad::cli_test {
namespace {

namespace fs = std::filesystem;

class SurfaceCommand : public ::testing::Test {
 protected:
  ScratchDir scratch_{std::string("surface_") +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name()};
  const fs::path& dir_ = scratch_.path();
};

TEST_F(SurfaceCommand, WritesAnSvgOfTheSaddle) {
  const fs::path out = dir_ / "saddle.svg";
  const CommandRun run =
      run_roomcad("surface 'x*x - z*z' --x -2:2 --z -2:2 -o " + shell_quoted(out));
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string svg = read_bytes(out);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("width=\"200mm\" height=\"150mm\""), std::string::npos);
  EXPECT_NE(svg.find("<g id=\"upper\""), std::string::npos);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  // Deterministic: the same command gives the same bytes.
  const fs::path again = dir_ / "again.svg";
  ASSERT_EQ(run_roomcad("surface 'x*x - z*z' --x -2:2 --z -2:2 -o " + shell_quoted(again)).status,
            0);
  EXPECT_EQ(read_bytes(again), svg);
}

TEST_F(SurfaceCommand, WritesAPngOfTheDampedWave) {
  const fs::path out = dir_ / "wave.png";
  const CommandRun run = run_roomcad(
      "surface 'cos(sqrt(x*x+z*z))/(sqrt(x*x+z*z)+1)' --x=-2*pi:2*pi --z=-2*pi:2*pi "
      "--width 320 --height 200 -o " +
      shell_quoted(out));
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string png = read_bytes(out);
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // IHDR holds the size, big-endian, at bytes 16..23.
  const auto u32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) |
           (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  EXPECT_EQ(u32(16), 320u);
  EXPECT_EQ(u32(20), 200u);
}

TEST_F(SurfaceCommand, BadExpressionNamesTheColumn) {
  const fs::path out = dir_ / "bad.svg";
  const CommandRun run = run_roomcad("surface 'x^' --x -2:2 --z -2:2 -o " + shell_quoted(out));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("expected a number, variable or '(' at column 3"), std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(SurfaceCommand, BadOptionsExitTwoAndWriteNothing) {
  const std::string out = shell_quoted(dir_ / "out.svg");
  const struct {
    std::string args;
    std::string message;
  } cases[] = {
      {"'x' --x 2 --z -1:1 -o " + out, "--x \"2\": expected A:B"},
      {"'x' --x -1:1 --z q:1 -o " + out, "--z \"q:1\""},
      {"'x' --x -1:1 --z -1:1 --dx 0 -o " + out, "dx must be positive, got 0"},
      {"'x' --x -1:1 --z -1:1 --rotate-x 90 -o " + out, "rotate_x"},
      {"'x' --x 1:-1 --z -1:1 -o " + out, "x range 1:-1 is empty"},
      {"'x' --x -1:1 --z -1:1 --dx 1e-7 -o " + out, "samples"},
      {"'x' --x -1:1 --z -1:1 -o " + shell_quoted(dir_ / "out.txt"), ".svg or .png"},
      {"'x' --x -1:1 --z -1:1", "--output is required"},
  };
  for (const auto& c : cases) {
    const CommandRun run = run_roomcad("surface " + c.args);
    EXPECT_EQ(run.status, 2) << c.args << "\n" << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.args << "\n" << run.output;
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(SurfaceCommand, UnwritableOutputExitsTwo) {
  const fs::path out = dir_ / "no" / "such" / "dir" / "out.svg";
  const CommandRun run = run_roomcad("surface 'x' --x -1:1 --z -1:1 -o " + shell_quoted(out));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("out.svg"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace roomcad::cli_test
