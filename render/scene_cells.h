// SPDX-License-Identifier: GPL-3.0-or-later
// Which triangles of a scene may be seen from inside each cell of its model: those whose box
// meets the cell's prism or the holes of its portals, grown by a margin. The portal walk
// (render/portal_walk.h) draws a reached cell's triangles from these runs.
#pragma once

#include "mesh/cells.h"
#include "render/scene.h"

namespace roomcad {

/// Heights closer than this to a cell's open top or bottom are taken as on it, metres: the
/// scene's float corners round by far less (a few micrometres 100 m from its origin).
inline constexpr double kPortalPlaneTolerance = 1e-5;

/// How far a cell reaches for its triangles beyond its prism, metres. A ray through the cell's
/// open top rises at least (the eye's least height under it) / (the cell's diagonal) per metre,
/// so a triangle that lies within kPortalPlaneTolerance of the top plane is hit through it only
/// within diagonal * kPortalPlaneTolerance / kPortalEyeClearance of the cell: it is the cell's.
/// @param[in] diagonal  the cell box's diagonal in plan, metres
[[nodiscard]] double cell_reach(double diagonal);

/// Least distance, metres, between the eye and anything that closes its cell, for a walk from
/// that cell (render/portal_walk.h): the near plane must not cut the cell's walls open.
inline constexpr double kPortalEyeClearance = 0.05;

/// @param[in] cells  the model's cells, world metres
/// @param[in] scene  its triangles (corners relative to scene.origin)
/// @return per cell, the runs of triangles whose box meets the cell's bounds or one of its
///         portals' bounds, each grown by cell_reach. O(triangles x cells each meets).
[[nodiscard]] SceneCells index_cells(const Cells& cells, const Scene& scene);

}  // namespace roomcad
