// SPDX-License-Identifier: GPL-3.0-or-later
// Drawing thin lines into an RgbImage: how line drawings (surfaces, plans) become PNG pictures.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "render/floating_horizon.h"
#include "render/image.h"

namespace roomcad {

using Rgb = std::array<std::uint8_t, 3>;

/// Draws the segment [a, b] (pixel coordinates, pixel centres at integers) one pixel wide with
/// a digital differential analyser: max(|dx|, |dy|) + 1 pixels, each rounded to the nearest.
/// Pixels outside the image are skipped. O(length in pixels).
void draw_line(RgbImage& image, ScreenPoint a, ScreenPoint b, Rgb color);

/// Draws the consecutive segments of a polyline. O(total length in pixels).
void draw_polyline(RgbImage& image, std::span<const ScreenPoint> points, Rgb color);

/// The colours of a surface picture (the seed suggests one per kind of visible piece).
struct SurfacePalette {
  Rgb background{255, 255, 255};
  Rgb first{0, 0, 0};      ///< the front section
  Rgb upper{20, 60, 160};  ///< the top of the surface
  Rgb lower{190, 40, 40};  ///< its underside
};

/// Rasterises a surface drawing whose units are pixels into a new image of its size
/// (width and height rounded up). O(pixels + drawn length).
[[nodiscard]] RgbImage rasterise_surface(const SurfaceDrawing& drawing,
                                         const SurfacePalette& palette = {});

}  // namespace roomcad
