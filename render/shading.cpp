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

/// Diffuse factor and specular amount of one light at a point seen along `to_eye`.
struct DirectLight {
  float diffuse = 0.f;
  float specular = 0.f;
};

DirectLight direct_light(const ShadingLight& light, const glm::vec3& normal,
                         const glm::vec3& to_eye) {
  const float n_dot_l = glm::dot(normal, light.to_light);
  if (n_dot_l <= 0.f) return {};
  const glm::vec3 half = glm::normalize(light.to_light + to_eye);
  float highlight = std::max(glm::dot(normal, half), 0.f);
  for (int i = 0; i < kShininessLog2; ++i) highlight *= highlight;
  return {n_dot_l, kSpecular * highlight};
}

glm::vec3 to_eye_from(const ShadingUniforms& u, const glm::vec3& p) {
  if (u.orthographic) return -u.forward;
  const glm::vec3 d = u.eye - p;
  const float len = glm::length(d);
  return len > 0.f ? d / len : -u.forward;
}

/// The direct light of light `k` at the point, as the mode evaluates it.
DirectLight evaluate(const ShadingUniforms& u, const SurfacePoint& s, int k) {
  const ShadingLight& light = u.lights[k];
  if (u.mode == ShadingMode::phong) return direct_light(light, s.normal, to_eye_from(u, s.world));
  if (u.mode == ShadingMode::flat) {
    const glm::vec3 centroid = (s.corners[0] + s.corners[1] + s.corners[2]) / 3.f;
    return direct_light(light, s.normal, to_eye_from(u, centroid));
  }
  DirectLight sum;  // gouraud: per corner, interpolated
  for (int c = 0; c < 3; ++c) {
    const DirectLight d = direct_light(light, s.normal, to_eye_from(u, s.corners[c]));
    sum.diffuse += s.weights[c] * d.diffuse;
    sum.specular += s.weights[c] * d.specular;
  }
  return sum;
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

glm::vec3 shade_point(const ShadingUniforms& u, const SurfacePoint& s) {
  if (u.mode == ShadingMode::unlit) {
    float dimming = 0.f;
    for (int k = 0; k < u.light_count; ++k) dimming += s.shadow[k] * (1.f - u.lights[k].ambient);
    return s.color * std::clamp(1.f - dimming, 0.f, 1.f);
  }
  glm::vec3 out(0.f);
  for (int k = 0; k < u.light_count; ++k) {
    const ShadingLight& light = u.lights[k];
    const DirectLight d = evaluate(u, s, k);
    const float direct = (1.f - light.ambient) * (1.f - s.shadow[k]) * light.intensity;
    out += s.color * (light.ambient * light.intensity + direct * d.diffuse) +
           glm::vec3(direct * d.specular);
  }
  return glm::clamp(out, 0.f, 1.f);
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
  const double dx = std::abs(fx - std::round(fx)), dy = std::abs(fy - std::round(fy));
  return std::min(dx, dy) < kGridHalfWidth ? color * kGridDarkening : color;
}

ShadingLight to_shading_light(const Light& light) {
  glm::vec3 to_light(-light.direction.x, -light.direction.y, -light.direction.z);
  to_light = glm::length(to_light) > 0.f ? glm::normalize(to_light) : glm::vec3(0.f, 0.f, 1.f);
  return {to_light, static_cast<float>(light.intensity),
          std::clamp(static_cast<float>(light.ambient), 0.f, 1.f)};
}

}  // namespace roomcad
