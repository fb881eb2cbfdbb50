// SPDX-License-Identifier: GPL-3.0-or-later
// View and reversed-Z projection matrices; framing a box from a preset direction.
#include "render/camera.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace roomcad {
namespace {

glm::dvec3 to_glm(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 to_vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

std::array<glm::dvec3, 8> corners_of(const Box3& b) {
  std::array<glm::dvec3, 8> out;
  for (int i = 0; i < 8; ++i) {
    out[i] = {(i & 1) ? b.high[0] : b.low[0], (i & 2) ? b.high[1] : b.low[1],
              (i & 4) ? b.high[2] : b.low[2]};
  }
  return out;
}

/// An up vector usable with `forward`: `up` itself unless (nearly) parallel, else world y.
glm::dvec3 usable_up(const glm::dvec3& forward, const glm::dvec3& up) {
  const double len = glm::length(up);
  if (len > 0.0 && glm::length(glm::cross(forward, up / len)) > 1e-6) return up / len;
  return std::abs(forward.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

/// Reversed-Z perspective with an infinite far plane: clip z = near, clip w = -z_eye, so
/// depth = near / distance (1 at the near plane, towards 0 far away).
glm::dmat4 perspective_reversed_z(double fov_deg, double aspect) {
  const double f = 1.0 / std::tan(glm::radians(fov_deg) / 2.0);
  glm::dmat4 p(0.0);
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[3][2] = kPerspectiveNear;
  p[2][3] = -1.0;
  return p;
}

/// Reversed-Z orthographic over the scene's depth range seen by `view` (never behind the eye).
glm::dmat4 orthographic_reversed_z(const glm::dmat4& view, const Box3& scene, double view_height,
                                   double aspect) {
  double near_d = 0.0;
  double far_d = 1.0;
  if (!is_empty(scene)) {
    double lo = 1e300, hi = -1e300;
    for (const glm::dvec3& c : corners_of(scene)) {
      const double d = -(view * glm::dvec4(c, 1.0)).z;
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    const double margin = 0.01 * (hi - lo) + 0.01;
    near_d = std::max(lo - margin, 0.0);
    far_d = std::max(hi + margin, near_d + 1.0);
  }
  const double half_h = view_height / 2.0;
  glm::dmat4 p(0.0);
  p[0][0] = 1.0 / (half_h * aspect);
  p[1][1] = 1.0 / half_h;
  p[2][2] = 1.0 / (far_d - near_d);
  p[3][2] = far_d / (far_d - near_d);
  p[3][3] = 1.0;
  return p;
}

struct Direction {
  glm::dvec3 forward;
  glm::dvec3 up;
};

Direction preset_direction(ViewPreset preset) {
  switch (preset) {
    case ViewPreset::front: return {{0, 1, 0}, {0, 0, 1}};
    case ViewPreset::back: return {{0, -1, 0}, {0, 0, 1}};
    case ViewPreset::left: return {{1, 0, 0}, {0, 0, 1}};
    case ViewPreset::right: return {{-1, 0, 0}, {0, 0, 1}};
    case ViewPreset::top: return {{0, 0, -1}, {0, 1, 0}};
    case ViewPreset::iso: break;
  }
  return {glm::normalize(glm::dvec3(1, 1, -1)), {0, 0, 1}};  // from the south-west, 35 deg down
}

}  // namespace

std::optional<ViewPreset> parse_view_preset(std::string_view text) {
  constexpr std::array<std::pair<std::string_view, ViewPreset>, 6> names{
      {{"front", ViewPreset::front},
       {"back", ViewPreset::back},
       {"left", ViewPreset::left},
       {"right", ViewPreset::right},
       {"top", ViewPreset::top},
       {"iso", ViewPreset::iso}}};
  for (const auto& [name, preset] : names)
    if (name == text) return preset;
  return std::nullopt;
}

CameraMatrices make_camera_matrices(const Camera& camera, const Box3& scene, double aspect) {
  CameraMatrices m;
  m.eye = to_glm(camera.eye);
  const glm::dvec3 to_target = to_glm(camera.target) - m.eye;
  m.forward = glm::length(to_target) > 0.0 ? glm::normalize(to_target) : glm::dvec3(0, 1, 0);
  m.view = glm::lookAtRH(m.eye, m.eye + m.forward, usable_up(m.forward, to_glm(camera.up)));
  m.orthographic = camera.projection == Projection::orthographic;
  m.projection = m.orthographic ? orthographic_reversed_z(m.view, scene, camera.view_height, aspect)
                                : perspective_reversed_z(camera.fov_deg, aspect);
  m.view_projection = m.projection * m.view;
  return m;
}

CameraMatrices rebase_camera(const CameraMatrices& camera, const glm::dvec3& origin) {
  CameraMatrices m = camera;
  m.view = camera.view * glm::translate(glm::dmat4(1.0), origin);
  m.view_projection = m.projection * m.view;
  m.eye = camera.eye - origin;
  return m;
}

namespace {

/// The view basis of a preset and the perspective half-angle tangents (with a 5% margin).
struct Framing {
  glm::dvec3 forward, right, up;
  double tan_h, tan_v;
};

/// The smallest distance from `center` (backwards along the view) at which every corner of
/// `scene` is inside the perspective frustum.
double fitting_distance(const Box3& scene, const Framing& f, const glm::dvec3& center) {
  double distance = kPerspectiveNear;
  for (const glm::dvec3& c : corners_of(scene)) {
    const glm::dvec3 q = c - center;
    const double x = std::abs(glm::dot(q, f.right)), y = std::abs(glm::dot(q, f.up));
    const double z = glm::dot(q, f.forward);
    distance = std::max({distance, x / f.tan_h - z, y / f.tan_v - z, kPerspectiveNear - z});
  }
  return distance;
}

/// Moves the looked-at point so that the box's perspective image is centred in the picture
/// (a box seen from above and aside projects lopsided around its centre's image). A few
/// fixed-point steps; each measures the image's extent and shifts by half its imbalance.
glm::dvec3 centred_target(const Box3& scene, const Framing& f, glm::dvec3 center) {
  for (int step = 0; step < 4; ++step) {
    const double distance = fitting_distance(scene, f, center);
    const glm::dvec3 eye = center - f.forward * distance;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec3& c : corners_of(scene)) {
      const glm::dvec3 q = c - eye;
      const double z = glm::dot(q, f.forward);
      const glm::dvec2 ndc(glm::dot(q, f.right) / (z * f.tan_h), glm::dot(q, f.up) / (z * f.tan_v));
      lo = glm::min(lo, ndc);
      hi = glm::max(hi, ndc);
    }
    const glm::dvec2 offset = (lo + hi) / 2.0;
    center += f.right * (offset.x * distance * f.tan_h) + f.up * (offset.y * distance * f.tan_v);
  }
  return center;
}

}  // namespace

Camera frame_view(const Box3& scene, ViewPreset preset, Projection projection, double fov_deg,
                  double aspect) {
  const Direction dir = preset_direction(preset);
  Framing f;
  f.forward = dir.forward;
  f.right = glm::normalize(glm::cross(dir.forward, dir.up));
  f.up = glm::cross(f.right, dir.forward);
  f.tan_v = std::tan(glm::radians(fov_deg) / 2.0) / 1.05;
  f.tan_h = f.tan_v * aspect;
  glm::dvec3 center = (low_corner(scene) + high_corner(scene)) / 2.0;
  double half_w = 0.0, half_h = 0.0;
  for (const glm::dvec3& c : corners_of(scene)) {
    half_w = std::max(half_w, std::abs(glm::dot(c - center, f.right)));
    half_h = std::max(half_h, std::abs(glm::dot(c - center, f.up)));
  }
  double distance =
      glm::length(high_corner(scene) - low_corner(scene)) / 2.0 + 1.0;  // orthographic: outside
  if (projection == Projection::perspective) {
    center = centred_target(scene, f, center);
    distance = fitting_distance(scene, f, center);
  }
  Camera cam;
  cam.id = "view";
  cam.projection = projection;
  cam.fov_deg = fov_deg;
  cam.view_height = std::max(2.0 * std::max(half_h, half_w / aspect) * 1.05, 1e-3);
  cam.target = to_vec3(center);
  cam.eye = to_vec3(center - dir.forward * distance);
  cam.up = to_vec3(dir.up);
  return cam;
}

Camera default_camera(const Box3& scene, double aspect) {
  return frame_view(scene, ViewPreset::iso, Projection::perspective, 50.0, aspect);
}

}  // namespace roomcad
