// SPDX-License-Identifier: GPL-3.0-or-later
// The faces of the solid on a plane whose polygons are nearly all rectangles in its view: their
// edges run along the view's two axes (convex_pieces.h's dominant_axis drops the third). That
// is where walls drawn along x and y meet: on a wall's vertical side (walls with flat tops,
// their openings' holes, the sections of walls across it), and on a storey's horizontal plane
// (tops, bottoms, slabs), where only mitres and walls drawn askew have slanted edges. On the
// homes of examples/sweethome3d/ such planes carry most of the planes' work, on the 504-wall
// tower all of it.
//
// There the plane's 2D boolean (plane_faces.h) needs no arrangement of edges: the distinct
// lines of each direction, in order of the coordinate they fix, make a grid in which each
// rectangle is a block of cells. Only the order of the lines is decided by exact predicates
// (exact_planes.h); the rest is integer work on the grid. Each cell's owners come from the
// polygons covering it by the rule a piece's sides follow (Presence). Around each slanted edge
// a window of the cells it may cross is left to one general boolean of every polygon there,
// clipped to the window (windows that share a cell merged); outside the windows a polygon
// with slanted edges holds a cell whole or not at all (exact tests of the cell's corners).
// Each owner's cells are traced into loops along the grid lines, turning left where two of its
// cells touch at a corner only; a face with a hole is cut along the grid line through the
// hole's top, so every face is one simple polygon with no new line. A face's vertices are its
// corners and the points of its edges where another polygon's edge crosses or ends (or a
// window's corner), as the general boolean splits its edges; stitching adds the rest
// (face_stitching.h).
#pragma once

#include <optional>
#include <vector>

#include "solid/detail/general_path/plane_faces.h"

namespace roomcad::detail {

/// The faces of the solid on a plane whose contributions are rectangles in its view, but for
/// a few with slanted edges.
/// @param[in] plane          canonical orientation (sign +1)
/// @param[in] contributions  every primitive near the plane with area in it (run_plane's)
/// @return the faces: simple polygons, counter-clockwise seen from outside, each owner's
///         covering the region PlaneBoolean gives it (so the same solid); none where the grid
///         does not pay or cannot tell: most polygons slanted, the windows' polygons more than
///         the plane's, a slanted polygon beyond the grid's lines, a grid of more than
///         kMaxGridCells, or a face in a window with a hole (then PlaneBoolean applies to the
///         whole plane). O(l log l) exact comparisons for l distinct lines, O(c) for the c
///         cells the rectangles cover, the corner tests of the cells the slanted polygons
///         reach, and the general boolean of the windows.
[[nodiscard]] std::optional<std::vector<SolidFace>> grid_faces(
    const PlaneSet& set, PlaneRef plane, const std::vector<Contribution>& contributions);

/// The most cells grid_faces works on (the grid's, and those the polygons cover together);
/// beyond, the general boolean's O(n log n) is the cheaper one.
inline constexpr std::size_t kMaxGridCells = std::size_t{1} << 18;

}  // namespace roomcad::detail
