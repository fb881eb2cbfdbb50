// The exact fast path: a wall that needs no general boolean (its holes are clear of its mitred
// ends and it meets no wall except through mitres of equal base and height) is built
// directly. Its (u, z) face is cut by the holes' edges into a grid of cells, solid or empty;
// faces are the maximal runs of cell boundaries between solid and empty, so a wall with one
// window has four faces per side, and each face carries every vertex lying on its edges
// (no T-junctions). Mitred ends get no cap: the partner's faces meet this wall's exactly.
#pragma once

#include "modeling/detail/face_soup.h"
#include "modeling/detail/wall_frame.h"

namespace roomcad::detail {

/// @return true if every hole lies strictly inside the part of the wall where both side faces
///         exist (clear of mitred ends), so the fast path applies. O(holes).
[[nodiscard]] bool has_holes_clear_of_mitres(const WallFrame& frame);

/// Builds a wall with its holes on the fast path.
/// @param[in] frame       the wall; holes must not overlap (validate: opening_overlap).
/// @param[in] wall_object index of the wall in Model::objects
/// @param[in] first_opening_object Model::objects index of opening 0 (holes add their index)
/// @pre has_holes_clear_of_mitres(frame)
/// @return faces: sides, top, bottom, free end caps, jambs, sills and lintels.
///         O(h^2) for h holes (the cell grid).
[[nodiscard]] FaceSoup build_fast_wall(const WallFrame& frame, int wall_object,
                                       int first_opening_object);

}  // namespace roomcad::detail
