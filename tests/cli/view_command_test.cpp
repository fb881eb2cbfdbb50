// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad view under Xvfb: the window's screenshot is `roomcad render`'s picture of the same
// camera, keys move the camera, and click + arrow + Ctrl+S moves a wall one cell in the saved
// file (Ctrl+Z before saving gives the plan back); a command-line edit while the window holds
// unsaved edits gives the conflict prompt, and Ctrl+K and Ctrl+R each do what it says. Xvfb
// missing is a failure, not a skip: scripts/setup.sh installs it.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "io/image_io.h"
#include "io/plan_json.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

using test::run_roomcad;
using test::TempDir;

constexpr const char* kWidth = "320";
constexpr const char* kHeight = "180";

/// An X server of its own for each test process (display number from the pid, so parallel
/// test processes do not meet), stopped with the test.
class ViewCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int attempt = 0; attempt < 20 && display_ < 0; ++attempt) {
      const int n = 100 + (getpid() * 7 + attempt) % 800;
      if (!std::filesystem::exists(fmt::format("/tmp/.X{}-lock", n))) display_ = n;
    }
    ASSERT_GE(display_, 0) << "no free X display number";
    const std::string name = fmt::format(":{}", display_);
    server_ = fork();
    ASSERT_GE(server_, 0);
    if (server_ == 0) {
      execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
      _exit(127);  // no Xvfb: the socket never appears and SetUp fails
    }
    const auto socket = fmt::format("/tmp/.X11-unix/X{}", display_);
    for (int i = 0; i < 200 && !std::filesystem::exists(socket); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(std::filesystem::exists(socket))
        << "Xvfb did not start on " << name << " (scripts/setup.sh installs the xvfb package)";
    setenv("DISPLAY", name.c_str(), 1);
  }
  void TearDown() override {
    if (server_ > 0) {
      kill(server_, SIGTERM);
      waitpid(server_, nullptr, 0);
    }
  }

  int display_ = -1;
  pid_t server_ = -1;
  TempDir dir_;
};

std::string studio() { return (test::source_dir() / "examples" / "studio.json").string(); }

RgbImage read_picture(const std::filesystem::path& path) {
  Result<RgbImage> png = read_png(path);
  EXPECT_TRUE(png.ok()) << png.error();
  return png.ok() ? png.value() : RgbImage();
}

/// Runs `roomcad view` headless to a screenshot. @return the picture.
RgbImage view_shot(const std::filesystem::path& out, std::vector<std::string> args) {
  args.insert(args.end(), {"--width", kWidth, "--height", kHeight, "--no-overlay", "--frames", "3",
                           "--screenshot", out.string()});
  args.insert(args.begin(), "view");
  const auto r = run_roomcad(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return read_picture(out);
}

RgbImage render_shot(const std::filesystem::path& out, std::vector<std::string> args) {
  args.insert(args.end(), {"--width", kWidth, "--height", kHeight, "-o", out.string()});
  args.insert(args.begin(), "render");
  const auto r = run_roomcad(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return read_picture(out);
}

TEST_F(ViewCommand, ScreenshotIsTheRenderOfTheSameCamera) {
  const RgbImage shown = view_shot(dir_ / "view.png", {studio(), "--camera", "view"});
  const RgbImage drawn = render_shot(dir_ / "render.png", {studio(), "--camera", "view"});
  ASSERT_EQ(shown.width, 320);
  ASSERT_EQ(shown.height, 180);
  EXPECT_EQ(shown.pixels, drawn.pixels);
}

TEST_F(ViewCommand, KeysMoveTheCamera) {
  const RgbImage iso = view_shot(dir_ / "iso.png", {studio()});
  const RgbImage top = view_shot(dir_ / "top.png", {studio(), "--keys", "a,1"});
  EXPECT_EQ(iso.pixels, render_shot(dir_ / "r-iso.png", {studio()}).pixels);
  EXPECT_EQ(top.pixels, render_shot(dir_ / "r-top.png", {studio(), "--view", "top"}).pixels);
  EXPECT_NE(top.pixels, iso.pixels);
}

/// A pixel of the top view where object `id` is seen, from `roomcad render --ids`.
std::pair<int, int> pixel_of(const TempDir& dir, const std::string& plan, const std::string& id) {
  const auto ids_png = dir / "ids.png";
  render_shot(dir / "top.png", {plan, "--view", "top", "--ids", ids_png.string()});
  const RgbImage ids = read_picture(ids_png);
  const auto legend = nlohmann::json::parse(test::read_bytes(dir / "ids.json"));
  long index = -1;
  for (const auto& o : legend.at("objects"))
    if (o.at("id") == id) index = o.at("index").get<long>();
  std::vector<std::pair<int, int>> hits;
  for (int y = 0; y < ids.height; ++y)
    for (int x = 0; x < ids.width; ++x) {
      const std::uint8_t* c = ids.at(x, y);
      if (c[0] + (c[1] << 8) + (c[2] << 16) - 1 == index) hits.emplace_back(x, y);
    }
  EXPECT_FALSE(hits.empty()) << id << " is not seen from the top";
  return hits.empty() ? std::pair{0, 0} : hits[hits.size() / 2];
}

/// The --keys input that clicks object `id` in the top view.
std::string click_on(const TempDir& dir, const std::string& plan, const std::string& id) {
  const auto [x, y] = pixel_of(dir, plan, id);
  return fmt::format("click:{}:{}", x, y);
}

TEST_F(ViewCommand, ClickArrowAndSaveMoveAWallOneCell) {
  const auto plan = dir_ / "studio.json";
  std::filesystem::copy_file(studio(), plan);
  const Plan original = read_plan_file(plan).value();
  const std::string click = click_on(dir_, plan.string(), "east");
  view_shot(dir_ / "a.png", {plan.string(), "--keys", fmt::format("1,{},right,ctrl+s", click)});
  const Plan moved = read_plan_file(plan).value();
  const double cell = original.site.cell_size;
  ASSERT_EQ(moved.walls.size(), original.walls.size());
  for (std::size_t i = 0; i < moved.walls.size(); ++i) {
    const Wall& a = original.walls[i];
    const Wall& b = moved.walls[i];
    const double dx = a.id == "east" ? cell : 0.0;
    EXPECT_EQ(b.from, (Point2{a.from.x + dx, a.from.y})) << a.id;
    EXPECT_EQ(b.to, (Point2{a.to.x + dx, a.to.y})) << a.id;
  }
  const std::string click_moved = click_on(dir_, plan.string(), "east");
  view_shot(dir_ / "b.png",
            {plan.string(), "--keys", fmt::format("1,{},left,ctrl+z,ctrl+s", click_moved)});
  EXPECT_EQ(read_plan_file(plan).value(), moved);  // the undone move was not saved
  view_shot(dir_ / "c.png",
            {plan.string(), "--keys", fmt::format("1,{},left,ctrl+s", click_moved)});
  EXPECT_EQ(read_plan_file(plan).value(), original);
}

/// Runs `roomcad view PLAN --keys KEYS` to a screenshot in a thread while, as soon as the
/// window's first save changes the file, another editor runs `roomcad set PLAN west height=2.9`.
/// @return what the window printed and its exit status.
test::CommandResult view_while_another_edits(const TempDir& dir, const std::filesystem::path& plan,
                                             const std::string& keys) {
  const std::string before = test::read_bytes(plan);
  test::CommandResult window;
  std::thread view([&] {
    window = run_roomcad({"view", plan.string(), "--keys", keys, "--width", kWidth, "--height",
                          kHeight, "--screenshot", (dir / "conflict.png").string()});
  });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (test::read_bytes(plan) == before && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const auto other = run_roomcad({"set", plan.string(), "west", "height=2.9", "--wait", "60"});
  view.join();
  EXPECT_EQ(other.status, 0) << other.err;
  EXPECT_EQ(window.status, 0) << window.err;
  // The change was seen while the window held unsaved edits, and the prompt named both keys.
  EXPECT_NE(window.err.find("changed on disk and the window has unsaved edits: Ctrl+R loads the "
                            "file"),
            std::string::npos)
      << window.err;
  EXPECT_NE(window.err.find("Ctrl+K keeps the window's version"), std::string::npos) << window.err;
  return window;
}

/// `plan` with wall `id` moved by (dx, dy) and wall west `height` tall.
Plan moved(Plan plan, const std::string& id, double dx, double dy, double west_height) {
  for (Wall& w : plan.walls) {
    if (w.id == id) w.from = {w.from.x + dx, w.from.y + dy}, w.to = {w.to.x + dx, w.to.y + dy};
    if (w.id == "west") w.height = west_height;
  }
  return plan;
}

TEST_F(ViewCommand, AnotherEditDuringUnsavedEditsPromptsAndKeepSavesTheWindows) {
  const auto plan = dir_ / "studio.json";
  std::filesystem::copy_file(studio(), plan);
  const Plan original = read_plan_file(plan).value();
  const std::string click = click_on(dir_, plan.string(), "east");
  // Saves a move, moves back (unsaved), waits for the other edit, tries to save (the prompt
  // again, nothing written), then keeps the window's version: the plan as it was at first.
  const auto window = view_while_another_edits(
      dir_, plan, fmt::format("1,{},right,ctrl+s,left,wait:change,ctrl+s,ctrl+k", click));
  EXPECT_NE(window.err.find("not saved: " + plan.string() +
                            " changed on disk since the window "
                            "read or saved it"),
            std::string::npos)
      << window.err;
  EXPECT_LT(window.err.find("not saved"), window.err.rfind("saved " + plan.string())) << window.err;
  EXPECT_EQ(read_plan_file(plan).value(), original);
}

TEST_F(ViewCommand, AnotherEditDuringUnsavedEditsPromptsAndReloadTakesTheFiles) {
  const auto plan = dir_ / "studio.json";
  std::filesystem::copy_file(studio(), plan);
  const Plan original = read_plan_file(plan).value();
  const double cell = original.site.cell_size;
  const std::string click = click_on(dir_, plan.string(), "east");
  // Saves a move, moves back (unsaved), waits for the other edit, reloads (dropping the
  // unsaved move), moves north and saves: on top of the other edit, without a prompt.
  const auto window = view_while_another_edits(
      dir_, plan, fmt::format("1,{},right,ctrl+s,left,wait:change,ctrl+r,up,ctrl+s", click));
  EXPECT_NE(window.err.find("the window's edits dropped"), std::string::npos) << window.err;
  EXPECT_EQ(read_plan_file(plan).value(), moved(original, "east", cell, cell, 2.9));
}

TEST_F(ViewCommand, BadInputsAreNamedWithExitStatus2) {
  const auto keys = run_roomcad(
      {"view", studio(), "--keys", "1,nokey", "--screenshot", (dir_ / "x.png").string()});
  EXPECT_EQ(keys.status, 2);
  EXPECT_EQ(test::failure_code(keys), Code::usage_error);
  EXPECT_NE(keys.err.find("input 2 'nokey'"), std::string::npos) << keys.err;
  const auto camera = run_roomcad({"view", studio(), "--camera", "nope"});
  EXPECT_EQ(camera.status, 2);
  EXPECT_EQ(test::failure_code(camera), Code::usage_error);
  EXPECT_NE(camera.err.find("--camera 'nope'"), std::string::npos) << camera.err;
  const auto huge = run_roomcad({"view", studio(), "--width", "16384", "--height", "16384"});
  EXPECT_EQ(huge.status, 2);
  EXPECT_EQ(test::failure_code(huge), Code::usage_error);
  EXPECT_NE(huge.err.find("--width, --height: width x height is 16384 x 16384"), std::string::npos)
      << huge.err;
  const auto missing = run_roomcad({"view", (dir_ / "missing.json").string()});
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(test::failure_code(missing), Code::io_error);
  const auto quits =
      run_roomcad({"view", studio(), "--keys", "1,q", "--screenshot", (dir_ / "q.png").string()});
  EXPECT_EQ(quits.status, 2);
  EXPECT_EQ(test::failure_code(quits), Code::usage_error);
  EXPECT_NE(quits.err.find("before the screenshot"), std::string::npos) << quits.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "q.png"));
  unsetenv("DISPLAY");  // no screen: SDL's invisible fallback is refused
  unsetenv("SDL_VIDEODRIVER");
  const auto no_screen = run_roomcad({"view", studio(), "--screenshot", (dir_ / "y.png").string()});
  EXPECT_EQ(no_screen.status, 2);
  EXPECT_EQ(test::failure_code(no_screen), Code::io_error);
  EXPECT_NE(no_screen.err.find("Xvfb"), std::string::npos) << no_screen.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "y.png"));
}

}  // namespace
}  // namespace roomcad
