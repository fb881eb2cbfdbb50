// SPDX-License-Identifier: GPL-3.0-or-later
// Walking through a model in the first person: the eye at a person's height over a floor,
// stepping along the level direction it looks in and turning its head about itself (the orbit
// camera, view/orbit_camera.h, turns about the target instead).
#pragma once

#include "plan/plan.h"

namespace roomcad {

/// The eye's height over the floor walked on, metres.
inline constexpr double kWalkEyeHeight = 1.6;

/// Stands where `camera` looks: the eye at the target's x and y, kWalkEyeHeight over `floor_z`,
/// looking level along the camera's direction (north when it looks straight down or up), in
/// perspective with the camera's field of view. @return the walking camera. O(1).
[[nodiscard]] Camera stand_at_target(const Camera& camera, double floor_z);

/// Steps `metres` along the level direction the camera looks in (negative: back); eye and
/// target move together, so the height stays. @return the moved camera. O(1).
[[nodiscard]] Camera walk_forward(const Camera& camera, double metres);

/// Turns the head: `yaw` about the world's z axis, then `pitch` up about the camera's right
/// axis, both about the eye, which stays; the pitch stops 1 degree short of straight up or
/// down. @return the turned camera. O(1).
[[nodiscard]] Camera look_around(const Camera& camera, double yaw_degrees, double pitch_degrees);

}  // namespace roomcad
