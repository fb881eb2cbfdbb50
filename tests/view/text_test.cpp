// SPDX-License-Identifier: GPL-3.0-or-later
// The overlay's text: glyphs land inside their cells, clipping is safe, panels darken.
#include <gtest/gtest.h>

#include "view/frame_overlay.h"
#include "view/text.h"

namespace roomcad {
namespace {

int lit_pixels(const RgbImage& image, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) n += image.at(x, y)[0] > 0;
  return n;
}

TEST(Text, GlyphsStayInTheirCells) {
  RgbImage image(100, 40);
  draw_text(image, 10, 5, "Hi!", {255, 255, 255});
  const int all = lit_pixels(image, 0, 0, 100, 40);
  EXPECT_GT(all, 10);
  EXPECT_EQ(lit_pixels(image, 10, 5, 10 + text_width("Hi!"), 5 + text_line_height()), all);
  RgbImage space(20, 20);
  draw_text(space, 0, 0, "  ", {255, 255, 255});
  EXPECT_EQ(lit_pixels(space, 0, 0, 20, 20), 0);
}

TEST(Text, UnknownCharactersAreQuestionMarksAndClippingIsSafe) {
  RgbImage a(20, 20), b(20, 20);
  draw_text(a, 0, 0, "\x01", {255, 0, 0});
  draw_text(b, 0, 0, "?", {255, 0, 0});
  EXPECT_EQ(a.pixels, b.pixels);
  RgbImage small(5, 5);
  draw_text(small, -3, -7, "WWWW", {255, 255, 255});
  draw_text(small, 4, 4, "WWWW", {255, 255, 255});
  darken_rect(small, -10, -10, 100, 100);
  SUCCEED();
}

TEST(Text, OverlayDarkensItsPanelAndCutsLongLines) {
  RgbImage image(120, 60);
  std::fill(image.pixels.begin(), image.pixels.end(), 240);
  OverlayText text;
  text.status = {std::string(500, 'x')};
  text.help = "q quit";
  draw_overlay(image, text);
  EXPECT_EQ(image.at(119, 20)[0], 240);  // below the one-line panel, above the help
  EXPECT_EQ(image.at(1, 1)[0], 80);      // darkened, no glyph pixel in the margin
  EXPECT_LT(image.at(1, 59)[0], 240);    // the help panel
}

}  // namespace
}  // namespace roomcad
