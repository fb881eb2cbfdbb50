// SPDX-License-Identifier: GPL-3.0-or-later
// A 5 x 7 pixel bitmap font for labels on pictures (the shadow study's times and sun
// positions): digits, letters (lower case drawn as upper case), space and : . , - + / ( ) °.
#pragma once

#include <string_view>

#include "render/image.h"
#include "render/line_raster.h"

namespace roomcad {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  ///< a column of space between glyphs

/// @return the width in pixels of `text` (UTF-8) drawn at `scale` pixels a font pixel. O(length).
[[nodiscard]] int text_width(std::string_view text, int scale);

/// Draws `text` (UTF-8; a character the font lacks is drawn as '?') with its top-left corner at
/// (x, y), each font pixel a `scale` x `scale` square; pixels outside the image are skipped.
/// O(length * scale^2).
void draw_text(RgbImage& image, int x, int y, std::string_view text, int scale, Rgb color);

}  // namespace roomcad
