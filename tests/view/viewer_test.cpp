// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer without a window: its frames are roomcad's renderer's pictures, keys move the
// camera and toggle the display, clicks select through the id buffer, errors are drawn red.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "io/plan_json.h"
#include "support/run_command.h"
#include "view/input.h"
#include "view/viewer.h"

namespace roomcad {
namespace {

constexpr int kWidth = 192, kHeight = 108;

std::filesystem::path studio() { return test::source_dir() / "examples" / "studio.json"; }

Viewer open_viewer(const std::filesystem::path& path, bool overlay = false) {
  Result<ViewSession> s = ViewSession::open(path);
  EXPECT_TRUE(s.ok()) << s.error();
  return Viewer(std::move(s).value(),
                ViewerOptions{.width = kWidth, .height = kHeight, .overlay = overlay});
}

/// What `roomcad render` draws of the plan with these options (grid on, the plan's lights).
RgbImage rendered(const std::filesystem::path& path, RenderOptions o) {
  const Plan plan = read_plan_file(path).value();
  o.width = kWidth, o.height = kHeight, o.lights = plan.lights;
  o.grid = GridLines{.enabled = true,
                     .origin = {plan.site.origin.x, plan.site.origin.y},
                     .cell_size = plan.site.cell_size,
                     .cells = plan.site.cells};
  FrameBuffers out;
  render_model(build_model(plan), o, out);
  return out.color;
}

InputEvent key(std::string name, bool ctrl = false) {
  InputEvent e;
  e.key = std::move(name), e.ctrl = ctrl;
  return e;
}

TEST(Viewer, FramesAreTheRenderersPictures) {
  Viewer v = open_viewer(studio());
  EXPECT_EQ(v.frame().pixels, rendered(studio(), {}).pixels);
  v.handle(key("1"));
  EXPECT_EQ(v.frame().pixels, rendered(studio(), {.view = ViewPreset::top}).pixels);
  v.handle(key("3"));
  EXPECT_EQ(v.frame().pixels, rendered(studio(), {.view = ViewPreset::right}).pixels);
}

TEST(Viewer, EveryCameraAndDisplayKeyChangesTheFrame) {
  Viewer v = open_viewer(studio());
  for (const char* name : {"a", "d", "w", "s", "x", "y", "z", "plus", "minus", "1", "2", "4", "p",
                           "h", "g", "e", "o", "left", "f"}) {
    const std::vector<std::uint8_t> before = v.frame().pixels;
    EXPECT_TRUE(v.handle(key(name)));
    EXPECT_NE(v.frame().pixels, before) << "key " << name;
  }
  EXPECT_FALSE(v.handle(key("q")));
}

// Walking: the eye stands 1.6 m over the floor where the view looked, steps and turns; every
// frame is what the renderer draws from that camera with back faces culled alone (the window
// walks the cells and keeps its shadow maps: the same picture).
TEST(Viewer, WalkingStandsStepsAndTurnsAtEyeHeight) {
  Viewer v = open_viewer(studio());
  v.handle(key("f"));
  const Camera standing = v.camera();
  EXPECT_DOUBLE_EQ(standing.eye.z, 1.6);
  EXPECT_DOUBLE_EQ(standing.target.z, 1.6);
  EXPECT_EQ(v.frame().pixels, rendered(studio(), {.camera = standing}).pixels);
  v.handle(key("w"));
  const Camera stepped = v.camera();
  EXPECT_NEAR(std::hypot(stepped.eye.x - standing.eye.x, stepped.eye.y - standing.eye.y), 0.5,
              1e-12);
  EXPECT_DOUBLE_EQ(stepped.eye.z, 1.6);
  v.handle(key("a"));
  EXPECT_EQ(v.camera().eye, stepped.eye);  // turning the head keeps the eye
  EXPECT_NE(v.camera().target, stepped.target);
  EXPECT_EQ(v.frame().pixels, rendered(studio(), {.camera = v.camera()}).pixels);
  v.handle(key("h"));  // shadows off and on: the kept maps are still the scene's
  v.handle(key("h"));
  EXPECT_EQ(v.frame().pixels, rendered(studio(), {.camera = v.camera()}).pixels);
  v.handle(key("f"));  // orbiting again: 'a' turns about the target
  const Camera walked = v.camera();
  v.handle(key("a"));
  EXPECT_EQ(v.camera().target, walked.target);
}

TEST(Viewer, ShadingKeyCyclesTheModes) {
  Viewer v = open_viewer(studio());
  const std::vector<std::uint8_t> phong = v.frame().pixels;
  std::vector<ShadingMode> modes;
  for (int i = 0; i < 4; ++i) {
    v.handle(key("m"));
    modes.push_back(v.render_options().shading);
  }
  EXPECT_EQ(modes, (std::vector<ShadingMode>{ShadingMode::flat, ShadingMode::gouraud,
                                             ShadingMode::unlit, ShadingMode::phong}));
  v.handle(key("m"));
  v.handle(key("m"));
  v.handle(key("m"));  // unlit: no light on the faces
  EXPECT_NE(v.frame().pixels, phong);
}

TEST(Viewer, ClickSelectsWhatThePixelShowsAndTintsIt) {
  Viewer v = open_viewer(studio());
  v.handle(key("1"));
  const RgbImage plain = v.frame();
  const RenderOptions& o = v.render_options();
  FrameBuffers ids;
  const Plan plan = v.session().plan();
  const Model model = build_model(plan);
  render_model(model, o, ids);
  int x = -1, y = -1;
  for (int py = 0; py < kHeight && x < 0; ++py)
    for (int px = 0; px < kWidth && x < 0; ++px)
      if (ids.objects.at(px, py) >= 0 && model.objects[ids.objects.at(px, py)] == "east")
        x = px, y = py;
  ASSERT_GE(x, 0) << "the east wall is in the top view";
  InputEvent click;
  click.type = InputEvent::Type::click, click.x = x, click.y = y;
  v.handle(click);
  EXPECT_EQ(v.session().selected(), "east");
  EXPECT_NE(v.frame().pixels, plain.pixels);
  click.x = 0, click.y = 0;  // the background
  v.handle(click);
  EXPECT_FALSE(v.session().selected());
  EXPECT_EQ(v.frame().pixels, plain.pixels);
}

TEST(Viewer, ErrorsAreDrawnRedLiveAndListed) {
  test::TempDir dir;
  Plan plan = read_plan_file(studio()).value();
  ASSERT_TRUE(test::write_bytes(dir / "p.json", write_plan_text(plan)));
  Viewer v = open_viewer(dir / "p.json");
  v.handle(key("1"));
  auto red_pixels = [&] {
    int n = 0;
    const RgbImage& f = v.frame();
    for (std::size_t i = 0; i < f.pixels.size(); i += 3)
      n += f.pixels[i] > 150 && f.pixels[i + 1] < 60 && f.pixels[i + 2] < 60;
    return n;
  };
  EXPECT_EQ(red_pixels(), 0);
  v.handle(key("tab"));  // the first wall, "south"
  ASSERT_EQ(v.session().selected(), "south");
  for (int i = 0; i < 6; ++i) v.handle(key("up"));  // 3 m north: onto the bathroom's wall
  ASSERT_FALSE(v.session().report().ok()) << v.session().message();
  EXPECT_GT(red_pixels(), 50);
  v.handle(key("s", true));
  EXPECT_NE(v.session().message().find("not saved"), std::string::npos);
  for (int i = 0; i < 6; ++i) v.handle(key("z", true));
  EXPECT_TRUE(v.session().report().ok());
  EXPECT_EQ(red_pixels(), 0);
}

TEST(Viewer, RedrawsWhenTheFileChangesOnDisk) {
  test::TempDir dir;
  Plan plan = read_plan_file(studio()).value();
  const auto path = dir / "p.json";
  ASSERT_TRUE(test::write_bytes(path, write_plan_text(plan)));
  Viewer v = open_viewer(path);
  const std::vector<std::uint8_t> before = v.frame().pixels;
  EXPECT_FALSE(v.poll_file());
  EXPECT_FALSE(v.needs_redraw());
  for (Wall& w : plan.walls) w.color = {0x20, 0x60, 0x20};
  const auto later = std::filesystem::last_write_time(path) + std::chrono::seconds(2);
  ASSERT_TRUE(test::write_bytes(path, write_plan_text(plan)));
  std::filesystem::last_write_time(path, later);
  EXPECT_TRUE(v.poll_file());
  EXPECT_TRUE(v.needs_redraw());
  EXPECT_NE(v.frame().pixels, before);
  EXPECT_EQ(v.session().plan(), plan);
}

/// Two storeys side by side in plan (so that each shows alone differently): a room of level
/// `ground` and a room of level `first`.
Plan two_storeys() {
  Plan p;
  p.site.cells = {12, 6};
  p.levels = {Level{.id = "ground", .elevation = 0, .height = 3},
              Level{.id = "first", .elevation = 3, .height = 3}};
  const auto room = [&p](const std::string& level, double x) {
    const Point2 c[] = {{x, 1}, {x + 4, 1}, {x + 4, 5}, {x, 5}};
    for (int i = 0; i < 4; ++i) {
      Wall w;
      w.id = level + std::to_string(i);
      w.level = level;
      w.from = c[i];
      w.to = c[(i + 1) % 4];
      w.height = 2.5;
      p.walls.push_back(w);
    }
  };
  room("ground", 1);
  room("first", 7);
  return p;
}

TEST(Viewer, LevelKeyShowsEachLevelAloneThenAll) {
  const test::TempDir dir;
  const std::filesystem::path path = dir / "storeys.json";
  ASSERT_TRUE(test::write_bytes(path, write_plan_text(two_storeys())));
  Viewer v = open_viewer(path);
  const std::vector<std::uint8_t> all = v.frame().pixels;
  v.handle(key("l"));  // the lowest level alone
  const std::vector<std::uint8_t> ground = v.frame().pixels;
  EXPECT_NE(ground, all);
  v.handle(key("l"));  // the next
  const std::vector<std::uint8_t> first = v.frame().pixels;
  EXPECT_NE(first, all);
  EXPECT_NE(first, ground);
  v.handle(key("l"));  // all levels again
  EXPECT_EQ(v.frame().pixels, all);
  v.handle(key("l", false));
  InputEvent back = key("l");
  back.shift = true;
  v.handle(back);  // shift+l: back to all
  EXPECT_EQ(v.frame().pixels, all);
  v.handle(back);  // and back once more: the last level
  EXPECT_EQ(v.frame().pixels, first);
  // Starting on a level (`roomcad view --level first`) shows it alone, framed.
  Result<ViewSession> s = ViewSession::open(path);
  ASSERT_TRUE(s.ok());
  Viewer started(
      std::move(s).value(),
      ViewerOptions{.width = kWidth, .height = kHeight, .overlay = false, .level = "first"});
  EXPECT_NE(started.frame().pixels, all);
  started.handle(key("l"));  // after the last level: all of them
  EXPECT_NE(started.frame().pixels, first);
}

TEST(Viewer, AConflictIsShownEvenWithTheOverlayOff) {
  test::TempDir dir;
  Plan plan = read_plan_file(studio()).value();
  const auto path = dir / "p.json";
  ASSERT_TRUE(write_plan_file(plan, path).ok());
  Viewer v = open_viewer(path, false);
  v.handle(key("tab"));
  v.handle(key("right"));  // an unsaved edit
  ASSERT_TRUE(v.session().is_modified());
  const std::vector<std::uint8_t> edited = v.frame().pixels;
  for (Wall& w : plan.walls) w.height += 0.5;
  ASSERT_TRUE(write_plan_file(plan, path).ok());  // another editor saves
  EXPECT_TRUE(v.poll_file());
  ASSERT_TRUE(v.session().in_conflict());
  EXPECT_NE(v.frame().pixels, edited);    // the same model, with the conflict's text on it
  EXPECT_TRUE(v.handle(key("k", true)));  // Ctrl+K: keep the window's version
  EXPECT_FALSE(v.session().in_conflict());
  EXPECT_EQ(v.frame().pixels, edited);
  EXPECT_EQ(read_plan_file(path).value(), v.session().plan());
}

TEST(Viewer, OverlayWritesOnTheFrame) {
  Viewer with = open_viewer(studio(), true);
  Viewer without = open_viewer(studio(), false);
  EXPECT_NE(with.frame().pixels, without.frame().pixels);
  with.handle(key("o"));
  EXPECT_EQ(with.frame().pixels, without.frame().pixels);
}

}  // namespace
}  // namespace roomcad
