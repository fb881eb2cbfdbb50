// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/walk_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace roomcad {
namespace {

glm::dvec3 to_glm(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 to_vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

/// The level direction the camera looks in: its view direction without z (north when none).
glm::dvec3 level_direction(const Camera& c) {
  glm::dvec3 d = to_glm(c.target) - to_glm(c.eye);
  d.z = 0.0;
  const double length = glm::length(d);
  return length > 1e-12 ? d / length : glm::dvec3(0.0, 1.0, 0.0);
}

}  // namespace

Camera stand_at_target(const Camera& camera, double floor_z) {
  Camera c = camera;
  c.projection = Projection::perspective;
  const glm::dvec3 eye(camera.target.x, camera.target.y, floor_z + kWalkEyeHeight);
  c.eye = to_vec3(eye);
  c.target = to_vec3(eye + level_direction(camera));
  c.up = {0.0, 0.0, 1.0};
  return c;
}

Camera walk_forward(const Camera& camera, double metres) {
  const glm::dvec3 step = level_direction(camera) * metres;
  Camera c = camera;
  c.eye = to_vec3(to_glm(camera.eye) + step);
  c.target = to_vec3(to_glm(camera.target) + step);
  return c;
}

Camera look_around(const Camera& camera, double yaw_degrees, double pitch_degrees) {
  const glm::dvec3 eye = to_glm(camera.eye);
  glm::dvec3 d = to_glm(camera.target) - eye;
  const double distance = glm::length(d);
  if (!(distance > 0.0)) return camera;
  d /= distance;
  const double yaw = std::atan2(d.y, d.x) + glm::radians(yaw_degrees);
  const double limit = glm::radians(89.0);
  const double pitch = std::clamp(
      std::asin(std::clamp(d.z, -1.0, 1.0)) + glm::radians(pitch_degrees), -limit, limit);
  const glm::dvec3 turned(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                          std::sin(pitch));
  Camera c = camera;
  c.target = to_vec3(eye + turned * distance);
  c.up = {0.0, 0.0, 1.0};
  return c;
}

}  // namespace roomcad
