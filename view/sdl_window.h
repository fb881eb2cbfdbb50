// The window: SDL2 glue around a Viewer (view/viewer.h). The only file that knows SDL.
#pragma once

#include <filesystem>
#include <vector>

#include "core/error.h"
#include "view/input.h"
#include "view/viewer.h"

namespace roomcad {

struct WindowOptions {
  std::vector<InputEvent> script;      ///< applied in order before the first frame is shown
  std::filesystem::path screenshot;    ///< set: show `frames` frames, save the window, close
  int frames = 1;                      ///< frames shown before the screenshot, >= 1
};

/// Opens a window the size of the viewer's frames and runs it: inputs go to the viewer, the
/// plan file is polled for changes, frames are drawn when something changed. Interactive until
/// the window is closed or 'q' is pressed, unless `options.screenshot` is set.
/// @return success, or why the window could not be opened or the screenshot written (names
///         the display or the file and the reason).
[[nodiscard]] Status run_window(Viewer& viewer, const WindowOptions& options);

}  // namespace roomcad
