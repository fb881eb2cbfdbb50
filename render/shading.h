// SPDX-License-Identifier: GPL-3.0-or-later
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

#include "plan/plan.h"

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
  glm::vec3 eye{0.f};      ///< perspective: the eye; orthographic: unused
  glm::vec3 forward{0.f};  ///< unit view direction (orthographic view vectors)
  bool orthographic = false;
  GridLines grid;
};

/// What shading needs of one flat surface (a triangle) that is the same at all its points.
/// Normals are per triangle (scene.h), so the diffuse factor of a light is constant; only the
/// specular highlight varies: per point (phong), between the corners (gouraud) or not (flat).
struct SurfaceLighting {
  glm::vec3 normal{0.f, 0.f, 1.f};          ///< unit, facing the viewer
  float ambient = 0.f;                      ///< sum of ambient * intensity over the lights
  std::array<float, kMaxLights> direct{};   ///< (1 - ambient) * intensity of each light
  std::array<float, kMaxLights> diffuse{};  ///< max(n . l, 0) of each light
  std::array<std::array<float, 3>, kMaxLights> corner_specular{};  ///< flat, gouraud
};

/// @param[in] normal   the triangle's unit normal, turned towards the viewer
/// @param[in] corners  its corners, metres
/// @return what shade_run needs of the triangle. O(lights).
[[nodiscard]] SurfaceLighting light_surface(const ShadingUniforms& u, const glm::vec3& normal,
                                            const std::array<glm::vec3, 3>& corners);

/// The most samples one run holds (longer runs of one triangle are split).
inline constexpr int kMaxRunSamples = 64;

/// Neighbouring samples of one surface, as arrays (structure of arrays keeps the loops simple
/// and the compiler free to vectorise them).
struct SampleRun {
  int count = 0;                                    ///< 0 .. kMaxRunSamples
  std::array<float, kMaxRunSamples> w1{}, w2{};     ///< barycentrics of corners 1 and 2
  std::array<float, kMaxRunSamples> x{}, y{}, z{};  ///< world positions, metres
  glm::vec3 color{0.f};                             ///< the surface's plain colour, sRGB [0, 1]
  std::array<float, kMaxRunSamples> tint{};         ///< 1, or darker on a floor's tile line
  std::array<std::array<float, kMaxRunSamples>, kMaxLights> shadow{};  ///< 0 lit ... 1 shadowed
};

/// Shades a run of samples of one surface: out[i] in [0, 1] sRGB for i < run.count.
/// Shadows are always per sample. O(count * lights).
void shade_run(const ShadingUniforms& u, const SurfaceLighting& surface, const SampleRun& run,
               glm::vec3* out);

/// Sets the run's tints: darker where a sample lies on a tile line of the site (half-width
/// 1.5% of a cell) and inside the site, 1 elsewhere or when the grid is off.
/// @pre run.x, run.y set for run.count samples. O(count).
void mark_grid_lines(const GridLines& grid, SampleRun& run);

/// @return an 8-bit colour as sRGB in [0, 1]. O(1).
[[nodiscard]] inline glm::vec3 to_unit_rgb(Color c) { return glm::vec3(c.r, c.g, c.b) / 255.f; }

/// @return the shading light of a plan light (direction normalised; zero: straight down).
[[nodiscard]] ShadingLight to_shading_light(const Light& light);

}  // namespace roomcad
