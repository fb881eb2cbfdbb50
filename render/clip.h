// SPDX-License-Identifier: GPL-3.0-or-later
// Clipping in homogeneous clip space, before the divide by w.
//
// Triangles are clipped against all six planes of the reversed-Z view volume: near (w - z >= 0),
// far (z >= 0), left, right, bottom, top (w +- x >= 0, w +- y >= 0). Clipping before the divide
// is what keeps a vertex behind the eye from being mirrored to the front; clipping the sides
// too (rather than a guard band) keeps every screen coordinate inside the viewport, so the
// rasteriser's fixed-point edge functions never overflow. Sutherland-Hodgman, float.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace roomcad {

/// A vertex in clip space, with its barycentric coordinates (of corners 1 and 2) in the
/// triangle it was cut from, so that attributes can be looked up after clipping.
struct ClipVertex {
  glm::vec4 position{0.f};
  glm::vec2 source{0.f};  ///< weights of source corners 1 and 2; corner 0 has 1 - x - y
};

/// A clipped triangle: a convex polygon of up to 3 + 6 vertices.
struct ClipPolygon {
  std::array<ClipVertex, 9> vertices;
  int count = 0;
};

/// @return one bit per view-volume plane that `p` is outside of (0: inside all). O(1).
[[nodiscard]] std::uint32_t outcode(const glm::vec4& p);

/// Clips a triangle against the six planes.
/// @param[in] triangle  three clip-space vertices
/// @return the convex polygon inside the volume, in the triangle's order; count 0 when nothing
///         is left, count < 3 never happens otherwise. A triangle lying exactly in a plane is
///         kept (>= 0 is inside). O(1).
[[nodiscard]] ClipPolygon clip_triangle(const std::array<ClipVertex, 3>& triangle);

}  // namespace roomcad
