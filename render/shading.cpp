// SPDX-License-Identifier: GPL-3.0-or-later
// Ambient + Lambert diffuse + Blinn-Phong specular per directional light; tile grid lines.
#include "render/shading.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/detail/wide_loops.h"

namespace roomcad {
namespace {

constexpr float kSpecular = 0.2f;  // white highlights, a matte finish
constexpr float kGridDarkening = 0.6f;
constexpr float kGridHalfWidth = 0.015f;  // of a cell
constexpr float kLastLine = 0x1p24f;      // the last line paint_grid tells from the next

/// The Blinn-Phong highlight (exponent 32) of light direction l on a surface of normal n
/// (both unit) that faces the light, seen from the direction e (any length). With s = |e|,
/// the half vector l + e / s has n . h = (s n.l + n.e) / s and |h|^2 = 2 (s + l.e) / s, so
/// (n . h / |h|)^2 = (s n.l + n.e)^2 / (2 s (s + l.e)): one square root and one division a
/// sample, and the power by squaring (std::pow is slow). Branch-free, so that loops over
/// samples calling it vectorise.
inline float highlight_at(const glm::vec3& l, const glm::vec3& n, float ex, float ey, float ez) {
  constexpr float kTiny = 1e-30f;  // keeps the division finite where e is 0 or opposes l
  const float s = std::sqrt(ex * ex + ey * ey + ez * ez);
  const float cos_half =
      std::max(s * (n.x * l.x + n.y * l.y + n.z * l.z) + (n.x * ex + n.y * ey + n.z * ez),
               0.f);  // times s |h|
  const float h2 =
      cos_half * cos_half / std::max(2.f * s * (s + l.x * ex + l.y * ey + l.z * ez), kTiny);
  const float h4 = h2 * h2, h8 = h4 * h4, h16 = h8 * h8;  // written out: a loop here would
  return kSpecular * (h16 * h16);                         // keep the caller's from vectorising
}

/// The viewer, homogeneous: (eye, 1) in perspective, (-forward, 0) orthographic, so that the
/// direction to it from p is viewer - w * p.
glm::vec4 viewer_of(const ShadingUniforms& u) {
  return u.orthographic ? glm::vec4(-u.forward, 0.f) : glm::vec4(u.eye, 1.f);
}

float highlight_from(const ShadingUniforms& u, const glm::vec3& l, const glm::vec3& n,
                     const glm::vec3& p) {
  const glm::vec4 v = viewer_of(u);
  return highlight_at(l, n, v.x - v.w * p.x, v.y - v.w * p.y, v.z - v.w * p.z);
}

/// The specular of light `k` at every sample of the run, as the mode evaluates it.
void run_specular(const ShadingUniforms& u, const SurfaceLighting& s, const SampleRun& run, int k,
                  float* out) {
  const int n = run.count;
  if (s.diffuse[k] <= 0.f) {  // facing away: no highlight
    std::fill(out, out + n, 0.f);
  } else if (u.mode == ShadingMode::phong) {
    const glm::vec4 v = viewer_of(u);
    const glm::vec3 l = u.lights[k].to_light;
    for (int i = 0; i < n; ++i) {
      out[i] = highlight_at(l, s.normal, v.x - v.w * run.x[i], v.y - v.w * run.y[i],
                            v.z - v.w * run.z[i]);
    }
  } else {
    const std::array<float, 3>& c = s.corner_specular[k];  // flat: three equal values
    for (int i = 0; i < n; ++i) {
      out[i] = (1.f - run.w1[i] - run.w2[i]) * c[0] + run.w1[i] * c[1] + run.w2[i] * c[2];
    }
  }
}

/// unlit: the plain colour, times (1 - sum of s * (1 - a)).
void shade_unlit(const ShadingUniforms& u, const SampleRun& run, glm::vec3* out) {
  for (int i = 0; i < run.count; ++i) {
    float dimming = 0.f;
    for (int k = 0; k < u.light_count; ++k) {
      dimming += run.shadow[k][i] * (1.f - u.lights[k].ambient);
    }
    out[i] = run.color * (run.tint[i] * std::clamp(1.f - dimming, 0.f, 1.f));
  }
}

}  // namespace

std::optional<ShadingMode> parse_shading_mode(std::string_view text) {
  constexpr std::pair<std::string_view, ShadingMode> names[] = {{"unlit", ShadingMode::unlit},
                                                                {"flat", ShadingMode::flat},
                                                                {"gouraud", ShadingMode::gouraud},
                                                                {"phong", ShadingMode::phong}};
  for (const auto& [name, mode] : names)
    if (name == text) return mode;
  return std::nullopt;
}

SurfaceLighting light_surface(const ShadingUniforms& u, const glm::vec3& normal,
                              const std::array<glm::vec3, 3>& corners) {
  SurfaceLighting s;
  s.normal = normal;
  const glm::vec3 centroid = (corners[0] + corners[1] + corners[2]) / 3.f;
  for (int k = 0; k < u.light_count; ++k) {
    const ShadingLight& light = u.lights[k];
    s.ambient += light.ambient * light.intensity;
    s.direct[k] = (1.f - light.ambient) * light.intensity;
    s.diffuse[k] = std::max(glm::dot(normal, light.to_light), 0.f);
    if (s.diffuse[k] <= 0.f || u.mode == ShadingMode::phong) continue;
    for (int c = 0; c < 3; ++c) {
      const glm::vec3& at = u.mode == ShadingMode::flat ? centroid : corners[c];
      s.corner_specular[k][c] = highlight_from(u, light.to_light, normal, at);
    }
  }
  return s;
}

ROOMCAD_WIDE_LOOPS void shade_run(const ShadingUniforms& u, const SurfaceLighting& surface,
                                  const SampleRun& run, glm::vec3* out) {
  if (u.mode == ShadingMode::unlit) return shade_unlit(u, run, out);
  std::array<float, kMaxRunSamples> brightness, highlight, specular;
  std::fill_n(brightness.begin(), run.count, surface.ambient);
  std::fill_n(highlight.begin(), run.count, 0.f);
  for (int k = 0; k < u.light_count; ++k) {
    run_specular(u, surface, run, k, specular.data());
    for (int i = 0; i < run.count; ++i) {
      const float direct = surface.direct[k] * (1.f - run.shadow[k][i]);
      brightness[i] += direct * surface.diffuse[k];
      highlight[i] += direct * specular[i];
    }
  }
  for (int i = 0; i < run.count; ++i) {
    out[i] =
        glm::clamp(run.color * (run.tint[i] * brightness[i]) + glm::vec3(highlight[i]), 0.f, 1.f);
  }
}

void mark_grid_lines(const GridLines& grid, SampleRun& run) {
  const int n = run.count;
  if (!grid.enabled || !(grid.cell_size > 0.0)) {
    std::fill_n(run.tint.begin(), n, 1.f);
    return;
  }
  // In float: the positions are in the scene's frame (metres from the model's centre), where
  // a float resolves 0.1 mm up to a few km, far finer than a line (1.5% of a cell). Line
  // numbers past 2^24 are not resolved (a site of 16 million cells a side).
  const float ox = static_cast<float>(grid.origin.x), oy = static_cast<float>(grid.origin.y);
  const float per_metre = static_cast<float>(1.0 / grid.cell_size);
  const float end_x = std::min(static_cast<float>(grid.cells[0]), kLastLine) + kGridHalfWidth;
  const float end_y = std::min(static_cast<float>(grid.cells[1]), kLastLine) + kGridHalfWidth;
  // fx >= -half width > -0.5 where it counts, so truncating f + 0.5 rounds f to the nearest
  // line (inline and branch-free, so that the loop vectorises; std::round is a library call)
  const auto to_line = [](float f) {
    const float clamped = std::clamp(f, -1.f, kLastLine);
    return std::abs(clamped - static_cast<float>(static_cast<int>(clamped + 0.5f)));
  };
  for (int i = 0; i < n; ++i) {
    const float fx = (run.x[i] - ox) * per_metre, fy = (run.y[i] - oy) * per_metre;
    const bool inside =
        fx >= -kGridHalfWidth && fy >= -kGridHalfWidth && fx <= end_x && fy <= end_y;
    const bool on_line = std::min(to_line(fx), to_line(fy)) < kGridHalfWidth;
    run.tint[i] = inside && on_line ? kGridDarkening : 1.f;
  }
}

ShadingLight to_shading_light(const Light& light) {
  glm::vec3 to_light(-light.direction.x, -light.direction.y, -light.direction.z);
  to_light = glm::length(to_light) > 0.f ? glm::normalize(to_light) : glm::vec3(0.f, 0.f, 1.f);
  return {to_light, static_cast<float>(light.intensity),
          std::clamp(static_cast<float>(light.ambient), 0.f, 1.f)};
}

}  // namespace roomcad
