// SPDX-License-Identifier: GPL-3.0-or-later
// Text and panels drawn into a frame: the window's overlay (file, selection, messages, help).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "render/image.h"

namespace roomcad {

using TextColor = std::array<std::uint8_t, 3>;

/// Height of one line of text in pixels (the 6x13 glyphs).
[[nodiscard]] int text_line_height();
/// @return the width in pixels of `text` (6 per character). O(1).
[[nodiscard]] int text_width(std::string_view text);

/// Draws `text` with its top-left corner at (x, y); pixels outside the image are skipped and
/// characters outside ASCII 32..126 are drawn as '?'. O(characters).
void draw_text(RgbImage& image, int x, int y, std::string_view text, TextColor color);

/// Darkens the rectangle [x, x + w) x [y, y + h) (clipped to the image) to a third of its
/// brightness, so that light text reads on any picture. O(w h).
void darken_rect(RgbImage& image, int x, int y, int w, int h);

}  // namespace roomcad
