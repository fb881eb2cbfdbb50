// SPDX-License-Identifier: GPL-3.0-or-later
// The colour pass's fragment stage: shades the visible samples of a tile once each (the depth
// and id buffers are already final), run by run of neighbouring samples of one triangle.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/detail/geometry_pass.h"
#include "render/rasterizer.h"
#include "render/scene.h"
#include "render/shading.h"
#include "render/shadow_map.h"

namespace roomcad::detail {

/// Everything the fragment stage reads (the frame's `uniform_` state).
struct ShadeUniforms {
  const Scene* scene = nullptr;
  const BinnedTriangles* bins = nullptr;
  const std::vector<ShadowMap>* shadow_maps = nullptr;
  ShadowFilter filter = ShadowFilter::off;
  ShadingUniforms shading;
  glm::vec3 background{1.f};  ///< sRGB in [0, 1], where no triangle is seen
  /// A sky: the background goes from `background` at the top row of samples to this at row
  /// `sky_rows` (the frame's height in samples); nullopt: one colour.
  std::optional<glm::vec3> sky_bottom;
  int sky_rows = 1;
};

/// Shades every sample of a rasterised tile: the surface seen there, or the background.
/// @param[in]  target  the tile: its rectangle and its final ids (BinnedTriangles ids)
/// @param[out] rgb     one colour per sample of the tile, row by row
/// Cost: O(samples * lights) plus O(lights) per run of samples showing one triangle.
void shade_tile(const ShadeUniforms& u, const RasterTarget& target, glm::vec3* rgb);

}  // namespace roomcad::detail
