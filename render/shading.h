// Shading: the colour of a visible surface point from the plan's directional lights.
//
// Colours stay in sRGB in [0, 1] (as tinyrenderer does): a lit face of colour c under a light
// of intensity I with ambient share a gets I * (a * c + (1 - a) * (1 - s) * (max(n.l, 0) * c +
// specular)), s being the shadow amount; lights add up, clamped at 1. `unlit` draws the plain
// colour, times (1 - sum of s * (1 - a)): a shadowed pixel keeps its colour times the ambient.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include <glm/glm.hpp>

#include "modeling/plan.h"

namespace roomcad {

enum class ShadingMode { unlit, flat, gouraud, phong };
/// @return the mode named `text` (unlit|flat|gouraud|phong), or nullopt.
[[nodiscard]] std::optional<ShadingMode> parse_shading_mode(std::string_view text);

/// Lights used per frame at most; further lights of a plan are ignored (the CLI warns).
inline constexpr int kMaxLights = 4;

/// One directional light as shading uses it.
struct ShadingLight {
  glm::vec3 to_light{0.f, 0.f, 1.f};  ///< unit
  float intensity = 1.f;
  float ambient = 0.25f;
};

/// The site's tile lines, drawn on floor faces.
struct GridLines {
  bool enabled = false;
  glm::dvec2 origin{0.0};
  double cell_size = 1.0;
  std::array<std::int64_t, 2> cells{0, 0};
};

/// Per-frame shading inputs.
struct ShadingUniforms {
  ShadingMode mode = ShadingMode::phong;
  std::array<ShadingLight, kMaxLights> lights{};
  int light_count = 0;
  glm::vec3 eye{0.f};        ///< perspective: the eye; orthographic: unused
  glm::vec3 forward{0.f};    ///< unit view direction (orthographic view vectors)
  bool orthographic = false;
  GridLines grid;
};

/// What the colour pass knows about one visible point.
struct SurfacePoint {
  glm::vec3 world{0.f};                  ///< metres
  glm::vec3 normal{0.f, 0.f, 1.f};       ///< unit, facing the viewer
  glm::vec3 color{0.f};                  ///< sRGB in [0, 1], grid lines already applied
  std::array<glm::vec3, 3> corners{};    ///< the triangle's corners (flat, gouraud)
  glm::vec3 weights{1.f / 3.f};          ///< the point's barycentrics in that triangle
  std::array<float, kMaxLights> shadow{};  ///< 0 lit ... 1 shadowed, per light
};

/// @return the colour of the point in [0, 1] sRGB. Flat evaluates the lights at the triangle's
///         centroid, Gouraud at its corners (interpolated), Phong at the point; shadows are
///         always per point. O(lights).
[[nodiscard]] glm::vec3 shade_point(const ShadingUniforms& u, const SurfacePoint& s);

/// @return `color` darkened where `world` lies on a tile line of the site (half-width 1.5% of
///         a cell) and inside the site; unchanged elsewhere or when the grid is off. O(1).
[[nodiscard]] glm::vec3 apply_grid(const GridLines& grid, const glm::vec3& world,
                                   const glm::vec3& color);

/// @return the shading light of a plan light (direction normalised; zero: straight down).
[[nodiscard]] ShadingLight to_shading_light(const Light& light);

}  // namespace roomcad
