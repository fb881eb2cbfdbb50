// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad view PLAN: the interactive window (view/), or a scripted headless run of it. Built
// into roomcad-view (cli/view_main.cpp), which `roomcad view` runs.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "cli/window_program.h"
#include "plan/plan_levels.h"
#include "view/key_bindings.h"
#include "view/sdl_window.h"
#include "view/viewer.h"

namespace roomcad::cli {
namespace {

struct ViewArgs {
  std::string plan, camera, view = "iso", keys, screenshot, level;
  int width = 1280, height = 720, frames = 1, threads = 0;
  double wait_seconds = 0.0;
  bool no_overlay = false;
};

/// @return the viewer options the flags ask for, or an error naming the flag and value.
Result<ViewerOptions> make_options(const ViewArgs& a, const Plan& plan) {
  ViewerOptions o{
      .width = a.width, .height = a.height, .overlay = !a.no_overlay, .threads = a.threads};
  if (const Status size = check_render_options({.width = a.width, .height = a.height}); !size)
    return Result<ViewerOptions>::failure(Code::usage_error,
                                          fmt::format("--width, --height: {}", size.message()));
  const auto preset = parse_view_preset(a.view);
  if (!preset)
    return Result<ViewerOptions>::failure(
        Code::usage_error,
        fmt::format("--view '{}': expected one of front, back, left, right, top, iso", a.view));
  o.view = *preset;
  if (const Result<Plan> level = select_level(plan, a.level); !level) return level.error();
  o.level = a.level;
  if (a.camera.empty()) return o;
  for (const Camera& c : plan.cameras)
    if (c.id == a.camera) o.camera = c;
  if (!o.camera)
    return Result<ViewerOptions>::failure(
        Code::usage_error,
        fmt::format("--camera '{}': {} has no camera with that id", a.camera, a.plan));
  return o;
}

/// The window's messages (saved, refused, a conflict and its choices) also go to stderr: a
/// log in the terminal, and what a scripted run is checked by.
void print_message(const std::string& message) {
  fmt::print(stderr, "roomcad view: {}\n", message);
}

int run_view(const ViewArgs& a) {
  const Result<LoadedPlan> loaded = load_plan("view", a.plan);  // prints what reading found
  if (!loaded) return exit_status_of(loaded.code());
  const Result<std::vector<InputEvent>> script = parse_key_script(a.keys);
  const Result<ViewerOptions> options = make_options(a, loaded->plan);
  Result<ViewSession> session = ViewSession::open(a.plan, wait_duration(a.wait_seconds));
  for (const Status& step : {script.status(), options.status(), session.status()})
    if (!step) return report_failure("view", step.error());
  Viewer viewer(std::move(session).value(), options.value());
  const Status shown = run_window(viewer, WindowOptions{.script = script.value(),
                                                        .screenshot = a.screenshot,
                                                        .frames = a.frames,
                                                        .on_message = print_message});
  return shown ? kExitOk : report_failure("view", shown.error());
}

}  // namespace

void add_view_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* app = root.add_subcommand(kWindowCommand, kWindowDescription);
  app->add_option("plan", args->plan, "The plan file (JSON)")->required();
  const auto pixels = CLI::Range(1, 16384);
  app->add_option("--width", args->width, "Window width in pixels")
      ->check(pixels)
      ->capture_default_str();
  app->add_option("--height", args->height, "Window height in pixels")
      ->check(pixels)
      ->capture_default_str();
  app->add_option("--camera", args->camera, "Start from the plan's camera with this id");
  app->add_option("--view", args->view, "Else frame the model from front|back|left|right|top|iso")
      ->capture_default_str();
  app->add_option("--keys", args->keys,
                  "Inputs applied at start: " + std::string(kKeyScriptSyntax));
  app->add_option("--screenshot", args->screenshot,
                  "Show --frames frames, save the window's content as this PNG and close");
  app->add_option("--frames", args->frames, "Frames shown before the screenshot")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app->add_option("--level", args->level,
                  "Start showing only the level with this id ('l' steps through the levels)");
  app->add_flag("--no-overlay", args->no_overlay,
                "Start without the text overlay ('o' toggles it)");
  app->add_option("--threads", args->threads, "Render threads, 0 = all cores")
      ->check(CLI::NonNegativeNumber);
  add_wait_option(*app, args->wait_seconds,
                  "seconds a save (Ctrl+S, Ctrl+K) waits for another editor of the plan to "
                  "finish; then it is not made, and says who holds the plan");
  app->footer("Keys:\n" + key_help());
  commands.push_back({app, [args] { return run_view(*args); }});
}

}  // namespace roomcad::cli
