// SPDX-License-Identifier: GPL-3.0-or-later
// The wireframe toggle: every triangle edge of the scene drawn over the frame.
#pragma once

#include "render/camera.h"
#include "render/image.h"
#include "render/scene.h"

namespace roomcad {

/// Draws the edges of every triangle (hidden ones too: a see-through wireframe) one pixel wide
/// in dark blue. Edges with an end behind the eye's near plane are skipped, not clipped.
/// @param[in] camera  the frame's matrices (frame_camera), for an image of this size
/// Cost: O(triangles + drawn length in pixels).
void draw_wireframe(RgbImage& image, const Scene& scene, const CameraMatrices& camera);

}  // namespace roomcad
