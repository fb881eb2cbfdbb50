// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle set-up and rasterisation with edge functions.
//
// Screen positions are fixed point (1/256 pixel), so edge functions are exact 64-bit integers:
// the top-left fill rule is then exact (a pixel centre on an edge shared by two triangles is
// drawn by exactly one of them) and the result does not depend on the order of operations.
// Pixel (x, y) has its centre at (x + 0.5, y + 0.5), y down from the top. Depth is reversed-Z
// float (1 near, 0 infinitely far): float's exponent keeps relative precision constant, so a
// building 1 km away still resolves surfaces millimetres apart (tests/render/depth_test.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "render/clip.h"

namespace roomcad {

inline constexpr int kSubpixelBits = 8;
inline constexpr std::int32_t kSubpixelScale = 1 << kSubpixelBits;
/// The id written where no triangle covers a pixel.
inline constexpr std::uint32_t kNoTriangle = 0xffffffffu;

/// A triangle after the divide by w and the viewport transform, oriented so that its edge
/// functions are positive inside.
struct ScreenTriangle {
  std::array<std::int32_t, 3> x{};    ///< 1/256 pixel
  std::array<std::int32_t, 3> y{};    ///< 1/256 pixel, down
  std::array<float, 3> depth{};       ///< reversed-Z, in [0, 1]
  std::array<float, 3> inv_w{};       ///< 1 / clip w, for perspective-correct interpolation
  std::array<glm::vec2, 3> source{};  ///< barycentrics in the scene triangle (see ClipVertex)
  std::uint32_t triangle = 0;         ///< index of the scene triangle
};

/// Which screen-space orientations survive set-up.
enum class Culling { back_faces, none };

/// Projects three clipped vertices to the screen.
/// @param[in] v        clip-space vertices inside the view volume, w > 0
/// @param[in] width, height  viewport in pixels, each <= 2^20 so fixed point fits 32 bits
/// @return the triangle, or nullopt if it has zero area in fixed point or is back-facing (its
///         world counter-clockwise order appears clockwise) and `culling` is back_faces.
[[nodiscard]] std::optional<ScreenTriangle> set_up_triangle(const std::array<ClipVertex, 3>& v,
                                                            int width, int height,
                                                            std::uint32_t triangle,
                                                            Culling culling);

/// @return true if the triangle's bounding box holds no pixel centre, so it cannot draw
///         anything (a sub-pixel sliver between centres): callers skip it before binning. O(1).
[[nodiscard]] bool covers_no_sample(const ScreenTriangle& t);

/// The part of a depth (and optional id) buffer one rasterisation call may write: pixels
/// [x0, x1) x [y0, y1); pixel (x, y) is stored at depth[(y - y0) * stride + (x - x0)].
struct RasterTarget {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  float* depth = nullptr;        ///< start at 0 (far)
  std::uint32_t* ids = nullptr;  ///< same layout, or nullptr for depth-only passes
  std::uint32_t id_value = 0;    ///< written to `ids` where the triangle wins the depth test
  int stride = 0;                ///< values per row; 0 means x1 - x0
};

/// Rasterises one triangle into the target with the top-left rule and a reversed-Z depth test
/// (a pixel is written when its depth is greater than the stored one, so among equal depths
/// the first triangle drawn stays). O(pixels of the triangle's box within the target).
void rasterize_triangle(const ScreenTriangle& t, const RasterTarget& target);

/// The depth rasterize_triangle writes at one pixel, bit for bit: the same coverage (top-left
/// rule) and the same float rounding, which depends on where the rasterised box starts, that
/// is on the target's corner (x0, y0) (a tile's). Used to decide visibility exactly as the
/// z-buffer does without drawing.
/// @return the depth, or nullopt if the triangle does not cover the pixel's centre. O(1).
[[nodiscard]] std::optional<float> depth_at_pixel(const ScreenTriangle& t, int px, int py, int x0,
                                                  int y0);

/// The perspective-correct weights of a screen triangle's scene triangle as planes over the
/// screen: each sample then costs six multiply-adds and a division. Double precision.
struct BarycentricPlanes {
  glm::dvec3 denominator{0.0};  ///< (per pixel across, per pixel down, at the origin)
  glm::dvec3 weight1{0.0};      ///< numerator of the weight of scene corner 1
  glm::dvec3 weight2{0.0};      ///< and of corner 2 (corner 0 takes the rest)

  /// @return the scene triangle's weights at (px, py) pixels, summing to 1. O(1).
  [[nodiscard]] glm::vec3 at(float px, float py) const {
    const double d = denominator.x * px + denominator.y * py + denominator.z;
    const double w1 = (weight1.x * px + weight1.y * py + weight1.z) / d;
    const double w2 = (weight2.x * px + weight2.y * py + weight2.z) / d;
    return {static_cast<float>(1.0 - w1 - w2), static_cast<float>(w1), static_cast<float>(w2)};
  }
};

/// @return the planes of a set-up triangle (edge functions over 1 / w). O(1).
[[nodiscard]] BarycentricPlanes barycentric_planes(const ScreenTriangle& t);

/// Perspective-correct barycentric weights of the scene triangle's three corners at a point
/// of the screen triangle: barycentric_planes(t).at(px, py).
/// @param[in] px, py  position in pixels (a pixel centre is x + 0.5)
/// @return weights summing to 1 (outside the triangle some are negative). O(1).
[[nodiscard]] glm::vec3 source_barycentrics(const ScreenTriangle& t, float px, float py);

}  // namespace roomcad
