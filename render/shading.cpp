// Ambient + Lambert diffuse + Blinn-Phong specular per directional light; tile grid lines.
#include "render/shading.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace roomcad {
namespace {

constexpr float kSpecular = 0.2f;    // white highlights, a matte finish
constexpr int kShininessLog2 = 5;  // exponent 32, by repeated squaring (std::pow is slow)
constexpr float kGridDarkening = 0.6f;
constexpr double kGridHalfWidth = 0.015;  // of a cell

/// The Blinn-Phong highlight of a light at a point seen along `to_eye` (unit), on a surface
/// that faces the light.
float specular(const glm::vec3& to_light, const glm::vec3& normal, const glm::vec3& to_eye) {
  const glm::vec3 half = to_light + to_eye;  // n . h over |h|: one square root, one division
  const float length_sq = glm::dot(half, half);
  if (!(length_sq > 0.f)) return 0.f;  // looking straight against the light
  float highlight = std::max(glm::dot(normal, half) / std::sqrt(length_sq), 0.f);
  for (int i = 0; i < kShininessLog2; ++i) highlight *= highlight;
  return kSpecular * highlight;
}

glm::vec3 to_eye_from(const ShadingUniforms& u, const glm::vec3& p) {
  if (u.orthographic) return -u.forward;
  const glm::vec3 d = u.eye - p;
  const float len = glm::length(d);
  return len > 0.f ? d * (1.f / len) : -u.forward;
}

/// The specular of light `k` at sample i of the run, as the mode evaluates it.
float sample_specular(const ShadingUniforms& u, const SurfaceLighting& s, const SampleRun& run,
                      int k, int i) {
  if (s.diffuse[k] <= 0.f) return 0.f;  // facing away: no highlight
  if (u.mode == ShadingMode::phong) {
    return specular(u.lights[k].to_light, s.normal, to_eye_from(u, run.world[i]));
  }
  const std::array<float, 3>& c = s.corner_specular[k];  // flat: three equal values
  return (1.f - run.w1[i] - run.w2[i]) * c[0] + run.w1[i] * c[1] + run.w2[i] * c[2];
}

/// unlit: the plain colour, times (1 - sum of s * (1 - a)).
void shade_unlit(const ShadingUniforms& u, const SampleRun& run, glm::vec3* out) {
  for (int i = 0; i < run.count; ++i) {
    float dimming = 0.f;
    for (int k = 0; k < u.light_count; ++k) {
      dimming += run.shadow[k][i] * (1.f - u.lights[k].ambient);
    }
    out[i] = run.color[i] * std::clamp(1.f - dimming, 0.f, 1.f);
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
      s.corner_specular[k][c] = specular(light.to_light, normal, to_eye_from(u, at));
    }
  }
  return s;
}

void shade_run(const ShadingUniforms& u, const SurfaceLighting& surface, const SampleRun& run,
               glm::vec3* out) {
  if (u.mode == ShadingMode::unlit) return shade_unlit(u, run, out);
  for (int i = 0; i < run.count; ++i) {
    float brightness = surface.ambient, highlight = 0.f;
    for (int k = 0; k < u.light_count; ++k) {
      const float direct = surface.direct[k] * (1.f - run.shadow[k][i]);
      brightness += direct * surface.diffuse[k];
      highlight += direct * sample_specular(u, surface, run, k, i);
    }
    out[i] = glm::clamp(run.color[i] * brightness + glm::vec3(highlight), 0.f, 1.f);
  }
}

glm::vec3 apply_grid(const GridLines& grid, const glm::vec3& world, const glm::vec3& color) {
  if (!grid.enabled || !(grid.cell_size > 0.0)) return color;
  const double fx = (world.x - grid.origin.x) / grid.cell_size;
  const double fy = (world.y - grid.origin.y) / grid.cell_size;
  const double margin = kGridHalfWidth;
  if (fx < -margin || fy < -margin || fx > static_cast<double>(grid.cells[0]) + margin ||
      fy > static_cast<double>(grid.cells[1]) + margin) {
    return color;
  }
  // fx, fy >= -margin > -0.5 here, so truncating f + 0.5 rounds f to the nearest line
  // (inline, where std::round is a library call on SSE2, and this runs per floor sample).
  const auto to_line = [](double f) {
    return std::abs(f - static_cast<double>(static_cast<std::int64_t>(f + 0.5)));
  };
  const double dx = to_line(fx), dy = to_line(fy);
  return std::min(dx, dy) < kGridHalfWidth ? color * kGridDarkening : color;
}

ShadingLight to_shading_light(const Light& light) {
  glm::vec3 to_light(-light.direction.x, -light.direction.y, -light.direction.z);
  to_light = glm::length(to_light) > 0.f ? glm::normalize(to_light) : glm::vec3(0.f, 0.f, 1.f);
  return {to_light, static_cast<float>(light.intensity),
          std::clamp(static_cast<float>(light.ambient), 0.f, 1.f)};
}

}  // namespace roomcad
