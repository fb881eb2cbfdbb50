// SPDX-License-Identifier: GPL-3.0-or-later
// The recursive split of Makarov & Safin's pre-pass over triangles already projected to the sample
// grid (render/visibility.h says what it finds).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/box.h"
#include "render/rasterizer.h"

namespace roomcad::detail {

/// A front-facing triangle on the sample grid (x right, y down, samples; centre of sample
/// (i, j) at (i + 0.5, j + 0.5)) with its depth as a plane: larger is nearer (reversed-Z).
/// The plane orders faces along contours; `screen` decides each sample exactly.
struct FlatTriangle {
  ScreenTriangle screen;  ///< as the rasteriser draws it (depth_at_pixel)
  std::array<Point2, 3> p{};
  glm::dvec3 depth{0.0};  ///< depth(x, y) = depth.x * x + depth.y * y + depth.z
  Box2 box = empty_box2();
  std::uint32_t id = 0;     ///< scene triangle
  std::uint32_t group = 0;  ///< triangles joined by shared edges in one plane (group_coplanar)
  std::array<bool, 3> boundary{true, true, true};  ///< edge p[i] -> p[i + 1] is not shared
                                                   ///< with a triangle of its plane
  [[nodiscard]] double depth_at(double x, double y) const {
    return depth.x * x + depth.y * y + depth.z;
  }
};

/// Sets FlatTriangle::group and ::boundary: two triangles with an edge of the same two
/// projected corners (bit for bit: the scene's shared vertices) and the same depth plane
/// (within 1e-5 relative) are one group and that edge is not a boundary. Deterministic.
/// O(n log n).
void group_coplanar(std::vector<FlatTriangle>& triangles);

/// Counters of one run (atomic: regions run in parallel).
struct SplitCounters {
  std::atomic<std::size_t> regions{0};
  std::atomic<std::size_t> crossings{0};
};

/// The sample grid and the rasteriser's tiles (depth rounding depends on the tile corner).
struct SampleGrid {
  int width = 1, height = 1, tile_size = 128;
};

/// Splits the picture [0, width] x [0, height] recursively and marks in `visible` (indexed by
/// FlatTriangle::id) every triangle the z-buffer shows at some sample centre: each centre on a
/// splitting line or the picture's sides, and inside a region where splitting stops, is
/// decided as the rasteriser decides it (nearest depth_at_pixel, ties to the triangle drawn
/// first).
/// @pre triangles in the rasteriser's draw order
/// @param[in,out] visible  entries are only ever set to 1
void split_picture(const std::vector<FlatTriangle>& triangles, const SampleGrid& grid,
                   std::vector<std::atomic<std::uint8_t>>& visible, SplitCounters& counters);

}  // namespace roomcad::detail
