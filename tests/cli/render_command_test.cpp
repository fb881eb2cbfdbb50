// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad render: files written, stats, determinism across threads, and every bad input
// giving a clear error, the right exit status and no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/image_io.h"
#include "io/plan_json.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

using test::run_roomcad;
using test::TempDir;

/// One 10 m wall facing south with a window at x in [5, 7], z in [1, 2] m, and a camera.
Plan window_wall() {
  Plan plan;
  Wall& w = plan.walls.emplace_back();
  w.id = "south", w.from = {1, 1}, w.to = {11, 1}, w.color = {200, 60, 40};
  Opening& o = plan.openings.emplace_back();
  o.id = "win", o.type = OpeningType::window, o.wall = "south", o.offset = 4.0, o.width = 2.0,
  o.height = 1.0, o.sill = 1.0;
  Camera& c = plan.cameras.emplace_back();
  c.id = "view", c.eye = {16, -9, 10}, c.target = {6, 4, 1};
  return plan;
}

std::string write_plan(const TempDir& dir, const Plan& plan) {
  const auto path = dir / "plan.json";
  EXPECT_TRUE(test::write_bytes(path, write_plan_text(plan)));
  return path.string();
}

TEST(RenderCommand, WritesPictureDepthIdsAndStats) {
  TempDir dir;
  const std::string plan = write_plan(dir, window_wall());
  const auto r = run_roomcad({"render", plan, "-o", (dir / "out.png").string(), "--width", "160",
                              "--height", "120", "--depth", (dir / "d.pfm").string(), "--ids",
                              (dir / "ids.png").string(), "--stats", "--camera", "view"});
  ASSERT_EQ(r.status, 0) << r.err;
  const Result<RgbImage> png = read_png(dir / "out.png");
  ASSERT_TRUE(png.ok()) << png.error();
  EXPECT_EQ(png.value().width, 160);
  EXPECT_EQ(png.value().height, 120);
  EXPECT_EQ(test::read_bytes(dir / "d.pfm").substr(0, 11), "Pf\n160 120\n");
  EXPECT_TRUE(read_png(dir / "ids.png").ok());
  EXPECT_NE(test::read_bytes(dir / "ids.json").find("\"south\""), std::string::npos);
  for (const char* key : {"\"triangles\"", "\"shadow_ms\"", "\"raster_ms\"", "\"frame_ms\""}) {
    EXPECT_NE(r.err.find(key), std::string::npos) << key << " in " << r.err;
  }
}

TEST(RenderCommand, SamePictureAtAnyThreadCount) {
  TempDir dir;
  const std::string plan = write_plan(dir, window_wall());
  for (const char* threads : {"1", "2"}) {
    const auto r =
        run_roomcad({"render", plan, "-o", (dir / (std::string(threads) + ".png")).string(),
                     "--width", "120", "--height", "90", "--ssaa", "2", "--threads", threads});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  EXPECT_EQ(test::read_bytes(dir / "1.png"), test::read_bytes(dir / "2.png"));
}

TEST(RenderCommand, FrontViewOfTheBuiltWallShowsBackgroundThroughTheWindow) {
  TempDir dir;
  const std::string plan = write_plan(dir, window_wall());
  const auto out = dir / "front.png";
  const auto r = run_roomcad(
      {"render",    plan,     "-o",        out.string(),   "--width",      "200",     "--height",
       "100",       "--view", "front",     "--projection", "orthographic", "--parts", "walls",
       "--shading", "unlit",  "--shadows", "off",          "--background", "#0000ff"});
  ASSERT_EQ(r.status, 0) << r.err;
  const Result<RgbImage> png = read_png(out);
  ASSERT_TRUE(png.ok());
  // The wall spans x 1..11 m (plus its thickness at the ends) and z 0..2.8 m, framed with a 5%
  // margin, centred: the window's centre (6, 1.5) is just above the picture's centre.
  const RgbImage& image = png.value();
  const std::uint8_t* window = image.at(100, 47);
  EXPECT_EQ((Color{window[0], window[1], window[2]}), (Color{0, 0, 255}));
  const std::uint8_t* wall = image.at(30, 50);
  EXPECT_EQ((Color{wall[0], wall[1], wall[2]}), (Color{200, 60, 40}));
}

TEST(RenderCommand, BadInputsNameFlagAndValueAndWriteNothing) {
  TempDir dir;
  const std::string plan = write_plan(dir, window_wall());
  const std::string out = (dir / "bad.png").string();
  const std::vector<std::vector<std::string>> cases = {{"--shading", "toon"},
                                                       {"--shadows", "soft"},
                                                       {"--ssaa", "3"},
                                                       {"--background", "red"},
                                                       {"--parts", "roof"},
                                                       {"--camera", "nope"},
                                                       {"--eye", "1,2,3"},
                                                       {"--eye", "1,2", "--target", "0,0,0"},
                                                       {"--view", "below"},
                                                       {"--width", "0"},
                                                       {"--projection", "fisheye"},
                                                       {"--grid", "maybe"},
                                                       {"--fov", "180"}};
  for (const auto& extra : cases) {
    std::vector<std::string> args{"render", plan, "-o", out};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_roomcad(args);
    EXPECT_EQ(r.status, 2) << extra[0] << ": " << r.err;
    EXPECT_EQ(test::failure_code(r), Code::usage_error) << extra[0] << ": " << r.err;
    EXPECT_NE(r.err.find(extra[0]), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << extra[0];
  }
}

TEST(RenderCommand, PlanErrorsExitOneMissingFileExitsTwo) {
  TempDir dir;
  Plan broken = window_wall();
  broken.walls[0].thickness = -1.0;
  const std::string plan = write_plan(dir, broken);
  const std::string out = (dir / "x.png").string();
  EXPECT_EQ(run_roomcad({"render", plan, "-o", out}).status, 1);
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto missing = run_roomcad({"render", (dir / "none.json").string(), "-o", out});
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(test::failure_code(missing), Code::io_error);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
  const auto unwritable = run_roomcad(
      {"render", write_plan(dir, window_wall()), "-o", (dir / "no" / "dir.png").string()});
  EXPECT_EQ(unwritable.status, 2);
  EXPECT_EQ(test::failure_code(unwritable), Code::io_error);
  EXPECT_NE(unwritable.err.find("dir.png"), std::string::npos) << unwritable.err;
}

}  // namespace
}  // namespace roomcad
