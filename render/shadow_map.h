// SPDX-License-Identifier: GPL-3.0-or-later
// Shadow maps for directional lights: an orthographic depth image seen from the light, its
// frustum fitted to the scene's bounds, looked up with a slope-scaled bias (hard or PCF).
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "plan/plan.h"
#include "render/image.h"
#include "render/scene.h"

namespace roomcad {

enum class ShadowFilter { off, hard, pcf };

/// Texels around a shadow map that never occlude (see ShadowMap::depth).
inline constexpr int kShadowBorder = 2;

/// The depth the scene shows a directional light. Depth is reversed (1 nearest the light), as
/// in the colour pass, so both share the rasteriser.
struct ShadowMap {
  glm::mat4 light_view_projection{1.f};  ///< scene frame (world - Scene::origin) -> light clip
  int resolution = 0;                    ///< texels per side
  /// The map, resolution x resolution texels (0 where nothing is), inside a frame of
  /// kShadowBorder texels a side that never occlude (-infinity): lookups at the map's edge
  /// read the frame instead of testing bounds. Map texel (x, y) is depth.at(x + kShadowBorder,
  /// y + kShadowBorder).
  FloatImage depth;
  glm::mat3 light_rotation{1.f};      ///< world -> light view directions (z to the light)
  glm::vec3 to_light{0.f, 0.f, 1.f};  ///< unit, from the scene towards the light
  float texel_x = 0.f;                ///< metres covered by one texel, across
  float texel_y = 0.f;                ///< and up the map
  float depth_range = 1.f;            ///< metres per unit of depth

  /// The larger side of a texel, metres: what "one texel from a shadow edge" measures.
  [[nodiscard]] float texel_size() const { return texel_x > texel_y ? texel_x : texel_y; }
};

/// Renders the shadow map of one light. Only faces turned towards the light are drawn (the
/// backs of closed solids lie behind their fronts; two-sided fixtures are always drawn), so
/// the map holds the first surface the light meets.
/// @param[in] light       direction must be non-zero (else straight down is used)
/// @param[in] resolution  texels per side, >= 1
/// @return the map; for an empty scene, a map where nothing is shadowed. O(triangles + texels),
///         parallel over tiles, identical at any thread count.
[[nodiscard]] ShadowMap render_shadow_map(const Scene& scene, const Light& light, int resolution);

/// What the lookup needs of a surface (a triangle), the same at all its points: whether it
/// faces the light, where its corners fall in the map (texel units and depth, so a sample's
/// position is a weighted sum of corners), the receiver plane's depth change per texel across
/// (u) and down (v) the map, and the depth bias: a twentieth of a texel plus a slope-scaled
/// tenth of a texel times tan(angle to the light).
struct ShadowReceiver {
  bool faces_light = false;
  float grad_u = 0.f;
  float grad_v = 0.f;
  float bias = 0.f;
  glm::vec3 corner0{0.f};     ///< (u, v, depth) of corner 0
  glm::vec3 to_corner1{0.f};  ///< corner 1 minus corner 0
  glm::vec3 to_corner2{0.f};  ///< corner 2 minus corner 0
};

/// @param[in] normal   the surface's unit normal (facing the viewer)
/// @param[in] corners  the triangle's corners, metres in the scene's frame (Scene::corners). O(1).
[[nodiscard]] ShadowReceiver shadow_receiver(const ShadowMap& map, const glm::vec3& normal,
                                             const std::array<glm::vec3, 3>& corners);

/// How much of the light samples of a surface do not get. Each texel is compared with the
/// receiver's plane extended to the texel's centre (so PCF's neighbours do not shadow their own
/// surface) plus the receiver's bias.
/// @param[in]  w1, w2  the samples' barycentric weights of corners 1 and 2, `count` of each
/// @param[out] out     `count` amounts, 0 lit ... 1 shadowed: hard is 0 or 1, pcf the
///                     bilinearly weighted share of the 2 x 2 texels around the point that
///                     shadow it. Points outside the map are lit; surfaces facing away from
///                     the light are shadowed; with `off` (or an empty scene's map) every
///                     sample is lit. O(count).
void shadow_amounts(const ShadowMap& map, const ShadowReceiver& receiver, ShadowFilter filter,
                    const float* w1, const float* w2, int count, float* out);

}  // namespace roomcad
