// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace roomcad {
namespace {

glm::dvec3 to_glm(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 to_vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

double half_fov_tan(const Camera& c) { return std::tan(glm::radians(c.fov_deg) / 2.0); }

/// The camera's unit right axis; world x when the view is along up (degenerate).
glm::dvec3 right_axis(const Camera& c) {
  const glm::dvec3 forward = to_glm(c.target) - to_glm(c.eye);
  const glm::dvec3 right = glm::cross(forward, to_glm(c.up));
  const double length = glm::length(right);
  return length > 0.0 ? right / length : glm::dvec3(1.0, 0.0, 0.0);
}

/// Puts the eye at `distance` from the target along the current view direction.
Camera with_distance(Camera c, double distance) {
  glm::dvec3 back = to_glm(c.eye) - to_glm(c.target);
  const double length = glm::length(back);
  back = length > 0.0 ? back / length : glm::dvec3(0.0, -1.0, 0.0);
  c.eye = to_vec3(to_glm(c.target) + back * distance);
  return c;
}

}  // namespace

Camera rotate_camera(const Camera& camera, const glm::dvec3& axis, double degrees) {
  const double length = glm::length(axis);
  if (!(length > 0.0) || !std::isfinite(degrees)) return camera;
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis / length);
  const glm::dvec3 target = to_glm(camera.target);
  Camera out = camera;
  out.eye = to_vec3(target + glm::dvec3(turn * glm::dvec4(to_glm(camera.eye) - target, 0.0)));
  out.up = to_vec3(glm::dvec3(turn * glm::dvec4(to_glm(camera.up), 0.0)));
  return out;
}

Camera orbit_camera(const Camera& camera, double yaw_degrees, double pitch_degrees) {
  const Camera turned = rotate_camera(camera, {0.0, 0.0, 1.0}, yaw_degrees);
  // Turning about the right axis by +pitch lowers the forward vector, so the eye rises.
  return rotate_camera(turned, right_axis(turned), -pitch_degrees);
}

double visible_height(const Camera& camera) {
  if (camera.projection == Projection::orthographic) return camera.view_height;
  return 2.0 * glm::length(to_glm(camera.eye) - to_glm(camera.target)) * half_fov_tan(camera);
}

Camera pan_camera(const Camera& camera, double right, double up) {
  const glm::dvec3 r = right_axis(camera);
  const glm::dvec3 forward = glm::normalize(to_glm(camera.target) - to_glm(camera.eye));
  const glm::dvec3 u = glm::cross(r, forward);
  const glm::dvec3 shift = (r * right + u * up) * visible_height(camera);
  Camera out = camera;
  out.eye = to_vec3(to_glm(camera.eye) + shift);
  out.target = to_vec3(to_glm(camera.target) + shift);
  return out;
}

Camera zoom_camera(const Camera& camera, double factor) {
  if (camera.projection == Projection::orthographic) {
    Camera out = camera;
    out.view_height = std::max(0.01, camera.view_height * factor);
    return out;
  }
  const double distance = glm::length(to_glm(camera.eye) - to_glm(camera.target));
  return with_distance(camera, std::max(0.1, distance * factor));
}

Camera toggle_projection(const Camera& camera) {
  Camera out = camera;
  if (camera.projection == Projection::perspective) {
    out.projection = Projection::orthographic;
    out.view_height = visible_height(camera);
    return out;
  }
  out.projection = Projection::perspective;
  return with_distance(out, std::max(0.1, camera.view_height / (2.0 * half_fov_tan(camera))));
}

}  // namespace roomcad
