// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures laid out on one sheet (the shadow study): each with a caption under it, in a grid
// under a title, on white.
#pragma once

#include <string_view>
#include <vector>

#include "render/image.h"

namespace roomcad {

/// Pixels between pictures on a sheet and around them.
inline constexpr int kSheetGap = 8;

/// @return the font scale of labels under a picture `width` pixels wide: 2 from 240 pixels up,
///         else 1. O(1).
[[nodiscard]] int caption_scale(int width);

/// @return `picture` with a white strip under it holding `caption` (bitmap_font.h) in black,
///         at caption_scale, cut at the picture's width. O(pixels).
[[nodiscard]] RgbImage add_caption(const RgbImage& picture, std::string_view caption);

/// @return the pictures (all of one size) in a grid of ceil(sqrt(n)) columns, in order row by
///         row, kSheetGap apart and from the edges, under a title line. O(pixels).
/// @pre !pictures.empty(), all the size of the first
[[nodiscard]] RgbImage lay_out_sheet(const std::vector<RgbImage>& pictures, std::string_view title);

}  // namespace roomcad
