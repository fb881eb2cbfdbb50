// SPDX-License-Identifier: GPL-3.0-or-later
// The shadow-map pass with memory the caller keeps between frames (render_shadow_map of
// shadow_map.h allocates afresh each time).
#pragma once

#include "render/detail/geometry_pass.h"
#include "render/shadow_map.h"

namespace roomcad::detail {

/// render_shadow_map into `map`, reusing its depth image and `bins`' memory.
/// @param[out] map   replaced: the light's map at `resolution` (>= 1) texels per side
/// @param[out] bins  scratch, contents replaced. O(triangles + texels).
void render_shadow_map_into(const Scene& scene, const Light& light, int resolution, ShadowMap& map,
                            BinnedTriangles& bins);

}  // namespace roomcad::detail
