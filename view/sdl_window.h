// SPDX-License-Identifier: GPL-3.0-or-later
// The window: SDL2 glue around a Viewer (view/viewer.h). The only file that knows SDL.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "view/input.h"
#include "view/viewer.h"

namespace roomcad {

struct WindowOptions {
  /// Applied in order before the first frame is shown; at a `wait:change` input the window
  /// runs (polling the file) until the session finds its file changed on disk.
  std::vector<InputEvent> script;
  std::filesystem::path screenshot;  ///< set: show `frames` frames, save the window, close
  int frames = 1;                    ///< frames shown before the screenshot, >= 1
  /// Called with each message the session gives (what was done, refused, a conflict), once.
  std::function<void(const std::string&)> on_message;
};

/// Opens a window the size of the viewer's frames and runs it: inputs go to the viewer, the
/// plan file is polled for changes, frames are drawn when something changed. Interactive until
/// the window is closed or 'q' is pressed, unless `options.screenshot` is set.
/// @return success, or why the window could not be opened, a `wait:change` ended without a
///         change (kWaitChangeSeconds) or the screenshot could not be written (names the
///         display or the file and the reason).
[[nodiscard]] Status run_window(Viewer& viewer, const WindowOptions& options);

}  // namespace roomcad
