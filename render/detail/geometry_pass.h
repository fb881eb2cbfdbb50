// SPDX-License-Identifier: GPL-3.0-or-later
// The geometry half of a raster pass: transform, frustum-cull clusters, clip, set up and bin
// triangles into screen tiles. Shared by the colour pass and the shadow-map passes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/portal_walk.h"
#include "render/rasterizer.h"
#include "render/scene.h"

namespace roomcad::detail {

/// A screen triangle's id: its chunk in the high bits, its place in the chunk in the low ones
/// (chunks are kept apart rather than copied into one array).
inline constexpr int kLocalBits = 17;

/// Screen triangles, per chunk of the scene, and per tile the ids of those overlapping it, in
/// scene order.
struct BinnedTriangles {
  std::vector<std::vector<ScreenTriangle>> chunks;
  std::vector<std::uint32_t> tile_offsets;  ///< tile t's ids: [offsets[t], offsets[t + 1])
  std::vector<std::uint32_t> ids;
  std::vector<std::uint32_t> slots;  ///< binning's scratch (per chunk and tile)
  int width = 0, height = 0, tile_size = 0, tiles_x = 0, tiles_y = 0;

  [[nodiscard]] int tile_count() const { return tiles_x * tiles_y; }
  [[nodiscard]] const ScreenTriangle& at(std::uint32_t id) const {
    return chunks[id >> kLocalBits][id & ((1u << kLocalBits) - 1)];
  }
  [[nodiscard]] std::size_t triangle_count() const;
};

/// Inputs of one geometry pass (the `uniform_` state of the vertex stage).
struct GeometryPass {
  glm::mat4 uniform_view_projection{1.f};
  int width = 0;  ///< pixels, <= 2^20
  int height = 0;
  int tile_size = 64;
  bool cull_back_faces = true;      ///< one-sided scene triangles only; two-sided are never culled
  bool cull_frustum = true;         ///< skip clusters whose bounds lie outside the view (clipping
                                    ///< drops their triangles anyway: this only saves work)
  std::uint8_t pass = kColourPass;  ///< draws the clusters that take part in this pass
  const std::uint8_t* uniform_draw = nullptr;  ///< per scene triangle, 0: skip; nullptr: all
  /// The runs of triangles to draw, in scene order, each within one of the scene's clusters
  /// (a portal walk's); nullptr: the scene's clusters.
  const std::vector<Cluster>* uniform_clusters = nullptr;
  /// With uniform_clusters: per run, where its triangles can be seen (the others are skipped);
  /// nullptr: anywhere.
  const RunView* uniform_views = nullptr;
  /// Where the viewer is, homogeneous: (eye, 1) for a perspective view, (unit direction
  /// towards the viewer, 0) for an orthographic one; (0, 0, 0, 0) leaves back faces to the
  /// screen-space test alone. With it, triangles clearly facing away (by their scene normal)
  /// are culled before they are transformed.
  glm::vec4 uniform_viewer{0.f};
};

/// Runs the pass over the whole scene, in parallel over fixed chunks of clusters (the caller's
/// TBB arena decides the thread count). The output does not depend on the thread count.
/// @param[out] bins  contents replaced; its memory is reused (a frame's passes allocate
///                   nothing once the buffers have grown). O(triangles + covered tiles).
void run_geometry_pass(const Scene& scene, const GeometryPass& pass, BinnedTriangles& bins);

/// Rasterises the triangles binned to `tile` into a target covering exactly that tile, in
/// scene order, writing screen-triangle ids (BinnedTriangles::at). O(pixels drawn).
void rasterize_tile(const BinnedTriangles& bins, int tile, RasterTarget target);

/// @return the pixel rectangle [x0, x1) x [y0, y1) of a tile, clipped to the image.
[[nodiscard]] RasterTarget tile_rectangle(const BinnedTriangles& bins, int tile);

}  // namespace roomcad::detail
