// SPDX-License-Identifier: GPL-3.0-or-later
// A DDA line drawer (lab 4, variant 4 of the Tomsk manual "Laboratory works in computer
// graphics": its raster step) and surface rasterisation.
#include "render/line_raster.h"

#include <algorithm>
#include <cmath>

namespace roomcad {
namespace {

void put_pixel(RgbImage& image, double x, double y, Rgb color) {
  const double px = std::round(x);
  const double py = std::round(y);
  if (!(px >= 0.0 && py >= 0.0 && px < image.width && py < image.height)) return;
  std::copy(color.begin(), color.end(), image.at(static_cast<int>(px), static_cast<int>(py)));
}

}  // namespace

void draw_line(RgbImage& image, ScreenPoint a, ScreenPoint b, Rgb color) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  // Clamp the step count so a wild coordinate cannot make the loop run for ever.
  const double limit = 4.0 * (image.width + image.height);
  const double steps = std::min(std::ceil(std::max(std::fabs(dx), std::fabs(dy))), limit);
  if (!(steps > 0.0)) {
    put_pixel(image, a.x, a.y, color);
    return;
  }
  for (double i = 0.0; i <= steps; i += 1.0) {
    put_pixel(image, a.x + dx * (i / steps), a.y + dy * (i / steps), color);
  }
}

void draw_polyline(RgbImage& image, std::span<const ScreenPoint> points, Rgb color) {
  for (std::size_t i = 1; i < points.size(); ++i) draw_line(image, points[i - 1], points[i], color);
}

RgbImage rasterise_surface(const SurfaceDrawing& drawing, const SurfacePalette& palette) {
  RgbImage image(static_cast<int>(std::ceil(drawing.width)),
                 static_cast<int>(std::ceil(drawing.height)));
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    std::copy(palette.background.begin(), palette.background.end(), image.pixels.begin() + i);
  }
  for (const HorizonPolyline& line : drawing.polylines) {
    const Rgb color = line.side == HorizonSide::first   ? palette.first
                      : line.side == HorizonSide::upper ? palette.upper
                                                        : palette.lower;
    draw_polyline(image, line.points, color);
  }
  return image;
}

}  // namespace roomcad
