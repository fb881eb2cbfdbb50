// SPDX-License-Identifier: GPL-3.0-or-later
// Proposals for wall_overlap: two walls drawn over one another.
//
// Parallel walls (drawn twice, split over one another, stacked storeys over one footprint)
// are boxes in one frame (frame_box.h): the one inside the other is removed; the one whose
// footprint the other covers is trimmed in height to meet it; the one whose height and width
// the other covers is trimmed along its line to meet it end to end; a wall beside another by
// at most the tolerance is snapped onto its line (and trimmed in the next round). A wall whose
// end lies inside another (at an angle) has that end moved along its own line onto the
// other's centre line, a T join, as Sweet Home 3D joins them.
//
// Each edit keeps the union (moves 0) where the boxes say so, and the openings of an edited
// wall stay where they stand (opening_places.h).
#pragma once

#include "repair/detail/context.h"
#include "repair/detail/proposal.h"

namespace roomcad::detail {

/// @pre finding.code == wall_overlap.
[[nodiscard]] Attempt propose_wall_overlap(const RepairContext& ctx, const Diagnostic& finding);

/// @return whether the walls are parallel, or so nearly that each one's ends lie at distances
///         from the other's line that differ by at most the tolerance (their boxes then hold
///         them, and the difference counts in what an edit moves). @pre both have length.
[[nodiscard]] bool nearly_parallel(const RepairContext& ctx, const Wall& a, const Wall& b);

/// The proposals for walls a and b (indices) drawn over one another, as for their
/// wall_overlap; also what clears an opening blocked by a wall drawn twice.
[[nodiscard]] Attempt propose_wall_pair(const RepairContext& ctx, std::size_t a, std::size_t b);

}  // namespace roomcad::detail
