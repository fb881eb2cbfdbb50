// SPDX-License-Identifier: GPL-3.0-or-later
// An outdoor picture (`roomcad render --sun`, the shadow study): the model on a ground that
// receives its shadows, under a sky, with the plan's obstructions (neighbouring buildings,
// trees) casting shadows but drawn in outline only, so that they never hide the model.
#pragma once

#include <vector>

#include "plan/plan.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/scene.h"

namespace roomcad {

/// What an outdoor picture adds to the model. The sky is a gradient behind everything, from
/// `sky_top` at the top of the picture to `sky_horizon` at its bottom.
struct Outdoors {
  std::vector<Obstruction> obstructions{};
  Color sky_top{0x5b, 0x8f, 0xd0};
  Color sky_horizon{0xcf, 0xe2, 0xf3};
  Color ground{0xb9, 0xc2, 0x9e};
  Color outline{0x2a, 0x2a, 0x2a};  ///< the obstructions' edges
};

/// The sky after sunset: the same picture in the colours of dusk.
[[nodiscard]] Outdoors night_outdoors(std::vector<Obstruction> obstructions);

/// The light of an outdoor picture: with the sun up (to_sun.z > 0), a directional light from
/// it whose ambient share (0.35) is the sky's; else the sky alone, a dimmer light that is all
/// ambient (no direction, no shadows). O(1).
[[nodiscard]] Light sun_and_sky_light(const Vec3& to_sun);

/// The ground's margin around the model and its obstructions, in times the largest of their
/// width, depth and height: wide enough for the shadows of a sun 10 degrees high.
inline constexpr double kGroundMargin = 3.0;

/// Appends the ground and the obstructions to a scene holding the model (flatten_model): the
/// ground is a square 1 cm under the model's lowest point reaching kGroundMargin beyond it
/// (colour pass only: it receives shadows and casts none); each obstruction is its prism's
/// sides and top (shadow pass only). O(obstruction corners^2) (their tops are triangulated).
void add_outdoors(const Outdoors& outdoors, Scene& scene);

/// Draws the obstructions' edges (their outlines at base and top, and their vertical edges)
/// over a rendered frame, one pixel wide, each point hidden where the frame's depth shows a
/// surface nearer the camera (by more than 2 cm plus 0.2%).
/// @param[in] camera  the frame's camera in world metres (frame_camera)
/// @param[in] depth   the frame's depth (metres along the view, 0 where nothing is drawn),
///                    the size of `color`. O(edges' length in pixels).
void outline_obstructions(const Outdoors& outdoors, const CameraMatrices& camera,
                          const FloatImage& depth, RgbImage& color);

}  // namespace roomcad
