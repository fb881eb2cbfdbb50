// SPDX-License-Identifier: GPL-3.0-or-later
// The text over a frame: status and selection at the top left, the plan's errors in red under
// them, one line of key help at the bottom.
#pragma once

#include <string>
#include <vector>

#include "render/image.h"

namespace roomcad {

struct OverlayText {
  std::vector<std::string> status;     ///< file, problems, camera (white)
  std::string message;                 ///< the last thing done or refused (yellow)
  std::vector<std::string> selection;  ///< the selected object's properties (light blue)
  std::vector<std::string> errors;     ///< validation errors, one per line (red)
  std::string help;                    ///< the bottom line
};

/// Most error lines shown; the rest are counted in one more line.
inline constexpr std::size_t kMaxErrorLines = 8;

/// Draws the overlay on a darkened panel; lines longer than the frame are cut. O(text + panel).
void draw_overlay(RgbImage& image, const OverlayText& text);

}  // namespace roomcad
