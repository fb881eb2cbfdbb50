// SPDX-License-Identifier: GPL-3.0-or-later
// The visible-surface pre-pass of Makarov & Safin, "Finding the visible parts of opaque
// surfaces of spatial objects" (2007): which scene triangles a
// view can show, found by recursively splitting the picture and carrying the depth order along
// each splitting line, so the renderer can skip the rest (`roomcad render --cull visibility`).
//
// The method: back-face cull; project; start with the picture's four sides as the contour of
// one region; split a region by a line through pixel centres, find where the line crosses the
// projected triangles, carry the set of triangles covering each stretch of the line from
// crossing to crossing (a triangle enters at one crossing and leaves at the other) and take its
// nearest as the face seen there; stop splitting when the whole contour sees one face (or
// none) and no triangle lies wholly inside, or when no pixel centre is left inside the region.
// Every sample centre lies on some line or inside a region where splitting stopped, and each
// is decided as the z-buffer decides it (the rasteriser's own screen triangles, coverage and
// float depth), so the set is exactly the triangles the z-buffer shows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.h"
#include "render/portal_walk.h"
#include "render/scene.h"

namespace roomcad {

/// What the pre-pass found.
struct VisibilityResult {
  std::vector<std::uint8_t> visible;  ///< per scene triangle: 1 seen somewhere, 0 never
  std::size_t visible_count = 0;
  std::size_t front_facing = 0;  ///< triangles left after back-face culling
  std::size_t regions = 0;       ///< regions examined
  std::size_t crossings = 0;     ///< line-triangle crossings computed
};

/// The picture the pre-pass looks at: the camera and the sample grid.
struct VisibilityView {
  CameraMatrices camera;  ///< as the colour pass uses it: in the scene's frame (rebase_camera)
  int width = 1;          ///< samples across (output pixels * ssaa), >= 1
  int height = 1;
  int tile_size = 128;  ///< the rasteriser's tiles (the renderer's): float depth rounds per tile
  /// The runs of triangles to look at (a portal walk's, render/portal_walk.h); nullptr: all.
  const std::vector<Cluster>* clusters = nullptr;
  const RunView* views = nullptr;  ///< with clusters: where each run is seen (or nullptr)
};

/// Finds the triangles visible in a view.
/// @pre view.width, view.height in 1 .. 2^20
/// @return per triangle whether it is seen: the triangle ids the rasteriser's id buffer shows
///         at the same sample grid and tile size. Deterministic; parallel over regions.
/// Cost: O(T log T) per splitting line for the T triangles overlapping its region; regions
///       stop early where one face covers them, so the total follows the length of the
///       projected edges in pixels rather than the pixel count.
[[nodiscard]] VisibilityResult find_visible_faces(const Scene& scene, const VisibilityView& view);

/// The triangles a directional light reaches somewhere, found the same way from the light
/// (its shadow map's orthographic frame at `resolution` texels a side). The others are wholly
/// in shadow. @pre resolution >= 1. Cost as find_visible_faces.
[[nodiscard]] VisibilityResult find_lit_faces(const Scene& scene, const Light& light,
                                              int resolution);

}  // namespace roomcad
