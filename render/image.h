// SPDX-License-Identifier: GPL-3.0-or-later
// Images the renderer draws into. The caller owns the buffer, so a window, a file writer or a
// test can share one renderer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace roomcad {

/// 8-bit sRGB pixels, row-major from the top-left corner, 3 bytes (r, g, b) per pixel.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  ///< width * height * 3 bytes

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 3, 0) {}
  [[nodiscard]] std::uint8_t* at(int x, int y) {
    return pixels.data() + (static_cast<std::size_t>(y) * width + x) * 3;
  }
  [[nodiscard]] const std::uint8_t* at(int x, int y) const {
    return pixels.data() + (static_cast<std::size_t>(y) * width + x) * 3;
  }
};

/// A single-channel float image (depth maps), row-major from the top-left corner.
struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<float> values;

  FloatImage() = default;
  FloatImage(int w, int h, float fill = 0.f)
      : width(w), height(h), values(static_cast<std::size_t>(w) * h, fill) {}
  [[nodiscard]] float& at(int x, int y) { return values[static_cast<std::size_t>(y) * width + x]; }
  [[nodiscard]] float at(int x, int y) const {
    return values[static_cast<std::size_t>(y) * width + x];
  }
};

}  // namespace roomcad
