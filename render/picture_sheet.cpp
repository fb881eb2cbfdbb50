// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/picture_sheet.h"

#include <algorithm>
#include <cmath>

#include "core/assert.h"
#include "render/bitmap_font.h"

namespace roomcad {
namespace {

constexpr Rgb kInk{0x10, 0x10, 0x10};

RgbImage white_image(int width, int height) {
  RgbImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), std::uint8_t{0xff});
  return image;
}

/// Copies `from` into `to` with its top-left corner at (x, y); it must fit.
void paste(const RgbImage& from, int x, int y, RgbImage& to) {
  for (int row = 0; row < from.height; ++row)
    std::copy_n(from.at(0, row), 3 * from.width, to.at(x, y + row));
}

/// The height of a strip holding one line of text at `scale`.
int line_height(int scale) { return (kGlyphHeight + 4) * scale; }

}  // namespace

int caption_scale(int width) { return width >= 240 ? 2 : 1; }

RgbImage add_caption(const RgbImage& picture, std::string_view caption) {
  const int scale = caption_scale(picture.width);
  RgbImage out = white_image(picture.width, picture.height + line_height(scale));
  paste(picture, 0, 0, out);
  draw_text(out, 2 * scale, picture.height + 2 * scale, caption, scale, kInk);
  return out;
}

RgbImage lay_out_sheet(const std::vector<RgbImage>& pictures, std::string_view title) {
  RC_ASSERT(!pictures.empty(), "a sheet of pictures");
  const int n = static_cast<int>(pictures.size());
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + columns - 1) / columns;
  const int w = pictures.front().width, h = pictures.front().height;
  const int scale = caption_scale(w), top = kSheetGap + line_height(scale);
  RgbImage sheet = white_image(kSheetGap + columns * (w + kSheetGap), top + rows * (h + kSheetGap));
  draw_text(sheet, kSheetGap, kSheetGap, title, scale, kInk);
  for (int i = 0; i < n; ++i) {
    RC_ASSERT(pictures[i].width == w && pictures[i].height == h, "pictures of one size");
    paste(pictures[i], kSheetGap + (i % columns) * (w + kSheetGap),
          top + (i / columns) * (h + kSheetGap), sheet);
  }
  return sheet;
}

}  // namespace roomcad
