// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/text.h"

#include <algorithm>

#include "view/detail/font_6x13.h"

namespace roomcad {

int text_line_height() { return detail::kGlyphHeight; }

int text_width(std::string_view text) {
  return static_cast<int>(text.size()) * detail::kGlyphWidth;
}

void draw_text(RgbImage& image, int x, int y, std::string_view text, TextColor color) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    int code = static_cast<unsigned char>(text[i]);
    if (code < detail::kFirstGlyph || code >= detail::kFirstGlyph + detail::kGlyphCount) code = '?';
    const detail::Glyph& glyph = detail::kFont6x13[code - detail::kFirstGlyph];
    const int left = x + static_cast<int>(i) * detail::kGlyphWidth;
    for (int row = 0; row < detail::kGlyphHeight; ++row) {
      const int py = y + row;
      if (py < 0 || py >= image.height) continue;
      for (int col = 0; col < detail::kGlyphWidth; ++col) {
        const int px = left + col;
        if (px < 0 || px >= image.width || !(glyph[row] & (0x80 >> col))) continue;
        std::copy(color.begin(), color.end(), image.at(px, py));
      }
    }
  }
}

void darken_rect(RgbImage& image, int x, int y, int w, int h) {
  const int x0 = std::max(x, 0), x1 = std::min(x + w, image.width);
  const int y0 = std::max(y, 0), y1 = std::min(y + h, image.height);
  for (int py = y0; py < y1; ++py)
    for (int px = x0; px < x1; ++px)
      for (std::uint8_t* c = image.at(px, py); c != image.at(px, py) + 3; ++c) *c /= 3;
}

}  // namespace roomcad
