// SPDX-License-Identifier: GPL-3.0-or-later
// find_cells: the closed spaces (mesh/cells.h) of the solid build_model makes from the same
// wall frames.
//
// Why a portal walk over them never loses a visible triangle: every wall is solid over its
// footprint from its base to its top, but where an opening's hole is cut (the build refuses
// any wall it cannot make, so every frame given here stands in the solid). Heights are cut into
// bands (find_bands); the points inside some wall at every height of a band make its solid, and
// a cell is a bounded face F of the complement of that solid, taken as the prism
// F x [band's low, band's high]. A ray from inside the prism can leave it only through a hole,
// its top or its bottom. The top (bottom) is closed when slabs spanning that height cover all
// of F: a ray reaching that height anywhere over F is inside a slab, so it was stopped.
// Everything is decided on boxes grown by a millimetre (far above the doubles' rounding of the
// exact solid's corners), so any doubt opens a cell rather than closing it.
#pragma once

#include <vector>

#include "mesh/cells.h"
#include "plan/plan.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

/// How far every box is grown, metres.
inline constexpr double kCellMargin = 1e-3;

/// @param[in] plan    the plan as built (BuildablePlan::plan: bases absolute, arcs as chords)
/// @param[in] frames  make_wall_frames(plan, ...), as the build used them
/// @param[in] slabs   whether the slabs were built (they close cells only then)
/// @return the cells of every band and the portals between them. Walls whose footprint is not
///         a simple polygon (crossed mitres) bound no cell. O(h n log n) for n walls and slabs
///         and h distinct base and top heights (the exact unions), plus O(cells + h openings)
///         box queries.
[[nodiscard]] Cells find_cells(const Plan& plan, const std::vector<WallFrame>& frames, bool slabs);

}  // namespace roomcad::detail
