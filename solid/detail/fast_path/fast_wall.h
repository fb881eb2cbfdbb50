// SPDX-License-Identifier: GPL-3.0-or-later
// The exact fast path: a wall that needs no general boolean (its holes are clear of its
// capless ends, and it meets other walls only through mitres, hubs and tees of equal base and
// height) is built directly. Its (u, z) face is cut by the holes' edges into a grid of cells,
// solid or empty. Side faces are the solid region traced as few polygons (cut only beside holes
// enclosed by material, and left open where a stem is glued on); jambs, sills, lintels, top,
// bottom and free end caps are the maximal runs of cell boundaries between solid and empty.
// Each face carries every vertex lying on its edges (no T-junctions). Capless ends (mitre, hub,
// tee) get no cap: the neighbour's faces meet this wall's at bit-identical corners.
#pragma once

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

/// @return true if every hole lies strictly inside the part of the wall where both side faces
///         exist (clear of its capless ends), so the fast path applies. O(holes).
[[nodiscard]] bool has_holes_clear_of_joins(const WallFrame& frame);

/// Builds a wall with its holes on the fast path.
/// @param[in] frame       the wall; holes must not overlap (validate: opening_overlap).
/// @param[in] wall_object index of the wall in Model::objects
/// @param[in] first_opening_object Model::objects index of opening 0 (holes add their index)
/// @pre has_holes_clear_of_joins(frame)
/// @return faces: sides, top, bottom, free end caps, jambs, sills and lintels.
///         O(h^2) for h holes (the cell grid).
[[nodiscard]] FaceSoup build_fast_wall(const WallFrame& frame, int wall_object,
                                       int first_opening_object);

}  // namespace roomcad::detail
