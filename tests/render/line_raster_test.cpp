// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/line_raster.h"

#include <gtest/gtest.h>

namespace roomcad {
namespace {

int count_colored(const RgbImage& image, Rgb color) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      n += (p[0] == color[0] && p[1] == color[1] && p[2] == color[2]) ? 1 : 0;
    }
  }
  return n;
}

TEST(LineRaster, DrawsEveryPixelOfAStraightLine) {
  RgbImage image(10, 5);
  draw_line(image, {1, 2}, {8, 2}, {255, 0, 0});
  EXPECT_EQ(count_colored(image, {255, 0, 0}), 8);
  for (int x = 1; x <= 8; ++x) EXPECT_EQ(image.at(x, 2)[0], 255) << x;
  EXPECT_EQ(image.at(0, 2)[0], 0);
  EXPECT_EQ(image.at(9, 2)[0], 0);
}

TEST(LineRaster, DiagonalHasOnePixelPerStep) {
  RgbImage image(6, 6);
  draw_line(image, {0, 0}, {5, 5}, {0, 255, 0});
  EXPECT_EQ(count_colored(image, {0, 255, 0}), 6);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(image.at(i, i)[1], 255);
}

TEST(LineRaster, ClipsAtTheImageAndSurvivesWildCoordinates) {
  RgbImage image(4, 4);
  draw_line(image, {-10, 1}, {10, 1}, {9, 9, 9});
  EXPECT_EQ(count_colored(image, {9, 9, 9}), 4);
  draw_line(image, {0, 0}, {1e300, 1e300}, {7, 7, 7});  // bounded work, no crash
  EXPECT_GE(count_colored(image, {7, 7, 7}), 1);
}

TEST(LineRaster, RasterisesASurfaceWithItsPalette) {
  SurfaceDrawing drawing;
  drawing.width = 20.5;
  drawing.height = 10;
  drawing.polylines.push_back({HorizonSide::first, {{0, 9}, {19, 9}}});
  drawing.polylines.push_back({HorizonSide::lower, {{0, 1}, {4, 1}}});
  const SurfacePalette palette;
  const RgbImage image = rasterise_surface(drawing, palette);
  EXPECT_EQ(image.width, 21);
  EXPECT_EQ(image.height, 10);
  EXPECT_EQ(count_colored(image, palette.first), 20);
  EXPECT_EQ(count_colored(image, palette.lower), 5);
  EXPECT_EQ(count_colored(image, palette.upper), 0);
  EXPECT_EQ(count_colored(image, palette.background), 21 * 10 - 25);
}

}  // namespace
}  // namespace roomcad
