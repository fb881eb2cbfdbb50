// SPDX-License-Identifier: GPL-3.0-or-later
// The cell-and-portal walk (Luebke and Georges 1995): from the camera's cell, through every
// portal the view, narrowed by the portals passed, still sees, and back the triangles of the
// cells reached. Each narrowed view is a rectangle on the screen (the box of a portal's
// projected corners, cut by the rectangle it was seen through), so the walk costs a few
// projections per portal reached, whatever the model's size.
//
// Conservative: every triangle the z-buffer would show is drawn (the cells are closed but for
// their portals: mesh/cells.h). A portal onto what no cell holds (a window to the outside, an
// open top or bottom) adds every cluster its rectangle sees (beyond the top or bottom plane).
// Triangles are returned in scene order, so the picture is the one drawing all of them makes.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "render/camera.h"
#include "render/scene.h"

namespace roomcad {

/// Where the triangles of a run can be seen: not wholly outside the screen rectangle's view
/// cone, and with a corner beyond the plane of the portal it is seen through (runs seen through
/// a portal onto what no cell holds: a window to the outside, an open top or bottom; others keep
/// every triangle).
struct RunView {
  glm::vec4 scissor{-1.f, -1.f, 1.f, 1.f};  ///< x0, y0, x1, y1: normalised device coordinates
  /// A corner p (scene frame) is beyond when dot(beyond, (p, 1)) > 0; (0, 0, 0, 1): all are.
  glm::vec4 beyond{0.f, 0.f, 0.f, 1.f};
};

struct PortalWalk {
  std::vector<Cluster> runs;      ///< what to draw: in scene order, each within one cluster
  std::vector<RunView> views;     ///< per run
  std::size_t cells_visited = 0;  ///< cells reached
};

/// @param[in] scene   with scene.cells
/// @param[in] camera  rebased into the scene's frame (rebase_camera)
/// @return the runs to draw, or nullopt when the walk cannot start: no cells, an orthographic
///         camera, or an eye in no cell with kPortalEyeClearance (and the near plane's reach)
///         to spare (outside, in a doorway, inside a slab). O(cells + portals reached + runs
///         drawn), plus O(clusters) when a portal opens onto the outside.
[[nodiscard]] std::optional<PortalWalk> walk_portals(const Scene& scene,
                                                     const CameraMatrices& camera);

}  // namespace roomcad
