// SPDX-License-Identifier: GPL-3.0-or-later
// Moving a camera the way a viewer does: orbit and rotate it about its target, pan, zoom and
// switch between perspective and parallel projection. Cameras are the plan's Camera (eye,
// target, up, fov, view height in metres), so a camera reached in the window can be rendered
// by `roomcad render --eye --target --up` and saved into a plan.
#pragma once

#include <glm/glm.hpp>

#include "plan/plan.h"

namespace roomcad {

/// Turns the camera about the axis through its target: eye and up turn, the target stays.
/// Used for orbiting (world z, or the camera's right axis) and for rotating the view about the
/// world's x, y and z axes.
/// @param[in] axis     any non-zero direction (normalised here); zero leaves the camera as is
/// @param[in] degrees  counter-clockwise looking down the axis
/// @return the turned camera; distance to the target and the projection are kept. O(1).
[[nodiscard]] Camera rotate_camera(const Camera& camera, const glm::dvec3& axis, double degrees);

/// Orbits: `yaw` about world z, then `pitch` about the camera's right axis (positive: the eye
/// rises). @return rotate_camera applied twice. O(1).
[[nodiscard]] Camera orbit_camera(const Camera& camera, double yaw_degrees, double pitch_degrees);

/// Pans: eye and target move together along the camera's right and up axes by the given
/// fractions of the height seen at the target (so a pan feels the same at any zoom).
/// @param[in] right, up  fractions of the visible height, e.g. 0.1. O(1).
[[nodiscard]] Camera pan_camera(const Camera& camera, double right, double up);

/// Zooms: perspective moves the eye towards the target (distance * factor, at least 0.1 m
/// kept), parallel shrinks the view height (view_height * factor, at least 0.01 m).
/// @pre factor > 0. @return the zoomed camera. O(1).
[[nodiscard]] Camera zoom_camera(const Camera& camera, double factor);

/// Switches perspective <-> parallel keeping the size of what is seen at the target: parallel
/// gets view_height = 2 d tan(fov / 2) for eye distance d, perspective puts the eye at the
/// distance that sees the current view_height. O(1).
[[nodiscard]] Camera toggle_projection(const Camera& camera);

/// @return the height in metres seen at the target (perspective: 2 d tan(fov / 2)). O(1).
[[nodiscard]] double visible_height(const Camera& camera);

}  // namespace roomcad
