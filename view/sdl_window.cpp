// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/sdl_window.h"

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <SDL.h>
#include <fmt/format.h>

#include "io/image_io.h"

namespace roomcad {
namespace {

constexpr int kClickSlop = 3;       ///< pixels a press may move and still be a click
constexpr Uint32 kPollMs = 100;     ///< how often the plan file is checked when idle
constexpr Uint32 kWaitPollMs = 10;  ///< how often a `wait:change` input checks the file

struct SdlDeleter {
  void operator()(SDL_Window* w) const { SDL_DestroyWindow(w); }
  void operator()(SDL_Surface* s) const { SDL_FreeSurface(s); }
};
using WindowPtr = std::unique_ptr<SDL_Window, SdlDeleter>;
using SurfacePtr = std::unique_ptr<SDL_Surface, SdlDeleter>;

/// The InputEvent key name of an SDL key, or "" for keys the viewer does not know.
std::string key_name(SDL_Keycode k) {
  if (k >= SDLK_a && k <= SDLK_z) return std::string(1, static_cast<char>(k));
  if (k >= SDLK_0 && k <= SDLK_9) return std::string(1, static_cast<char>(k));
  switch (k) {
    case SDLK_LEFT: return "left";
    case SDLK_RIGHT: return "right";
    case SDLK_UP: return "up";
    case SDLK_DOWN: return "down";
    case SDLK_DELETE: return "delete";
    case SDLK_BACKSPACE: return "backspace";
    case SDLK_TAB: return "tab";
    case SDLK_ESCAPE: return "escape";
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS: return "plus";
    case SDLK_MINUS:
    case SDLK_KP_MINUS: return "minus";
    default: return "";
  }
}

/// A click, drag or wheel input.
InputEvent pointer_event(InputEvent::Type type, int x, int y, bool right_button = false) {
  InputEvent e;
  e.type = type, e.x = x, e.y = y, e.right_button = right_button;
  return e;
}

/// Mouse state between SDL events: a press becomes a click or a drag.
struct Pointer {
  bool left = false, right = false, dragged = false;
  int press_x = 0, press_y = 0;
};

/// Turns one SDL event into a viewer input, or nullopt. Sets `quit` on a window close.
std::optional<InputEvent> translate(const SDL_Event& e, Pointer& p, bool& quit) {
  switch (e.type) {
    case SDL_QUIT: quit = true; return std::nullopt;
    case SDL_KEYDOWN: {
      InputEvent key{.key = key_name(e.key.keysym.sym)};
      if (key.key.empty()) return std::nullopt;
      key.ctrl = (e.key.keysym.mod & KMOD_CTRL) != 0;
      key.shift = (e.key.keysym.mod & KMOD_SHIFT) != 0 && key.key != "plus" && key.key != "minus";
      return key;
    }
    case SDL_MOUSEBUTTONDOWN:
      (e.button.button == SDL_BUTTON_RIGHT ? p.right : p.left) = true;
      p.dragged = false, p.press_x = e.button.x, p.press_y = e.button.y;
      return std::nullopt;
    case SDL_MOUSEBUTTONUP: {
      const bool was_click = e.button.button == SDL_BUTTON_LEFT && p.left && !p.dragged;
      (e.button.button == SDL_BUTTON_RIGHT ? p.right : p.left) = false;
      if (!was_click) return std::nullopt;
      return pointer_event(InputEvent::Type::click, e.button.x, e.button.y);
    }
    case SDL_MOUSEMOTION:
      if (!p.left && !p.right) return std::nullopt;
      if (std::abs(e.motion.x - p.press_x) + std::abs(e.motion.y - p.press_y) > kClickSlop)
        p.dragged = true;
      if (!p.dragged) return std::nullopt;
      return pointer_event(InputEvent::Type::drag, e.motion.xrel, e.motion.yrel, p.right);
    case SDL_MOUSEWHEEL: return pointer_event(InputEvent::Type::wheel, e.wheel.y, 0);
    default: return std::nullopt;
  }
}

/// Copies a frame into the window and shows it. @return false (SDL's error set) on failure.
bool present(SDL_Window* window, const RgbImage& frame) {
  SDL_Surface* target = SDL_GetWindowSurface(window);
  SurfacePtr source(SDL_CreateRGBSurfaceWithFormatFrom(
      const_cast<std::uint8_t*>(frame.pixels.data()), frame.width, frame.height, 24,
      frame.width * 3, SDL_PIXELFORMAT_RGB24));
  return target && source && SDL_BlitSurface(source.get(), nullptr, target, nullptr) == 0 &&
         SDL_UpdateWindowSurface(window) == 0;
}

/// @return what the window shows now, as RGB.
Result<RgbImage> read_window(SDL_Window* window) {
  SDL_Surface* shown = SDL_GetWindowSurface(window);
  SurfacePtr rgb(shown ? SDL_ConvertSurfaceFormat(shown, SDL_PIXELFORMAT_RGB24, 0) : nullptr);
  if (!rgb)
    return Result<RgbImage>::failure(Code::io_error,
                                     fmt::format("reading the window: {}", SDL_GetError()));
  RgbImage image(rgb->w, rgb->h);
  for (int y = 0; y < rgb->h; ++y) {
    const auto* row =
        static_cast<const std::uint8_t*>(rgb->pixels) + static_cast<std::size_t>(y) * rgb->pitch;
    std::copy(row, row + static_cast<std::size_t>(rgb->w) * 3, image.at(0, y));
  }
  return image;
}

/// Hands each new message of the session to WindowOptions::on_message, once.
class MessageLog {
 public:
  MessageLog(const WindowOptions& options, const Viewer& viewer)
      : on_message_(options.on_message), viewer_(viewer), seen_(viewer.session().message_count()) {}
  void flush() {
    const ViewSession& session = viewer_.session();
    if (!on_message_ || session.message_count() == seen_) return;
    seen_ = session.message_count();
    on_message_(session.message());
  }

 private:
  const std::function<void(const std::string&)>& on_message_;
  const Viewer& viewer_;
  std::uint64_t seen_;
};

/// A `wait:change` input: polls the plan file (events drained) until the session finds it
/// changed on disk, at most kWaitChangeSeconds.
Status wait_for_change(Viewer& viewer, MessageLog& log) {
  const std::uint64_t before = viewer.session().disk_changes();
  const Uint64 deadline = SDL_GetTicks64() + kWaitChangeSeconds * Uint64{1000};
  while (viewer.session().disk_changes() == before) {
    if (SDL_GetTicks64() >= deadline)
      return Status::failure(
          Code::io_error, fmt::format("--keys wait:change: {} did not change on disk within {} s",
                                      viewer.session().path().string(), kWaitChangeSeconds));
    for (SDL_Event e; SDL_PollEvent(&e) != 0;) {}  // a scripted run takes no live input
    viewer.poll_file();
    log.flush();
    SDL_Delay(kWaitPollMs);
  }
  return Status::success();
}

/// The interactive loop: until the window closes or the viewer is asked to quit.
Status run_interactive(SDL_Window* window, Viewer& viewer, MessageLog& log) {
  Pointer pointer;
  for (bool quit = false; !quit;) {
    SDL_Event e;
    for (bool got = SDL_WaitEventTimeout(&e, kPollMs) != 0; got && !quit;
         got = SDL_PollEvent(&e) != 0) {
      if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_EXPOSED &&
          !present(window, viewer.frame()))
        return Status::failure(Code::io_error,
                               fmt::format("drawing the window: {}", SDL_GetError()));
      if (const std::optional<InputEvent> input = translate(e, pointer, quit))
        quit = quit || !viewer.handle(*input);
      log.flush();
    }
    viewer.poll_file();
    log.flush();
    if (!quit && viewer.needs_redraw() && !present(window, viewer.frame()))
      return Status::failure(Code::io_error, fmt::format("drawing the window: {}", SDL_GetError()));
  }
  return Status::success();
}

/// Scripted run: `frames` frames shown (events drained between them), then the screenshot.
Status run_screenshot(SDL_Window* window, Viewer& viewer, const WindowOptions& options,
                      MessageLog& log) {
  for (int i = 0; i < options.frames; ++i) {
    for (SDL_Event e; SDL_PollEvent(&e) != 0;) {}  // a headless run takes no live input
    viewer.poll_file();
    log.flush();
    if (!present(window, viewer.frame()))
      return Status::failure(Code::io_error, fmt::format("drawing the window: {}", SDL_GetError()));
  }
  const Result<RgbImage> shot = read_window(window);
  if (!shot) return shot.status();
  return write_png(shot.value(), options.screenshot);
}

/// Starts SDL's video on a real screen. SDL falls back to its invisible "offscreen" driver
/// when there is no display, which would leave an interactive user staring at nothing: that
/// driver (or "dummy") is accepted only when asked for by SDL_VIDEODRIVER.
Status start_video() {
  const char* display = std::getenv("DISPLAY");
  const std::string where = fmt::format("DISPLAY='{}'", display ? display : "");
  if (SDL_Init(SDL_INIT_VIDEO) != 0)
    return Status::failure(Code::io_error,
                           fmt::format("cannot open a window ({}): {}; without a screen, run "
                                       "under Xvfb (xvfb-run -a roomcad view ...)",
                                       where, SDL_GetError()));
  const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
  if ((driver == "offscreen" || driver == "dummy") && !std::getenv("SDL_VIDEODRIVER")) {
    SDL_Quit();
    return Status::failure(
        Code::io_error,
        fmt::format(
            "cannot open a window ({}): no screen to show it on; run under Xvfb (xvfb-run -a "
            "roomcad view ...), or set SDL_VIDEODRIVER=offscreen for a --screenshot run",
            where));
  }
  return Status::success();
}

}  // namespace

Status run_window(Viewer& viewer, const WindowOptions& options) {
  if (Status video = start_video(); !video) return video;
  const RenderOptions& size = viewer.render_options();
  const std::string title = "roomcad view - " + viewer.session().path().filename().string();
  WindowPtr window(SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                    size.width, size.height, SDL_WINDOW_SHOWN));
  Status status = window ? Status::success()
                         : Status::failure(Code::io_error,
                                           fmt::format("cannot open a window: {}", SDL_GetError()));
  bool quit = false;
  MessageLog log(options, viewer);
  for (const InputEvent& input : options.script) {
    if (!status || quit) break;
    if (input.type == InputEvent::Type::wait_change) status = wait_for_change(viewer, log);
    else quit = !viewer.handle(input);
    log.flush();
  }
  if (status && quit && !options.screenshot.empty())
    status = Status::failure(Code::usage_error,
                             fmt::format("--keys quits ('q') before the screenshot {} is taken",
                                         options.screenshot.string()));
  else if (status && !quit)
    status = options.screenshot.empty() ? run_interactive(window.get(), viewer, log)
                                        : run_screenshot(window.get(), viewer, options, log);
  window.reset();
  SDL_Quit();
  return status;
}

}  // namespace roomcad
