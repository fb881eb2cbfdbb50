// SPDX-License-Identifier: GPL-3.0-or-later
// Merging collinear pieces of drawn lines, so that a wall's top edge, split into many mesh
// edges and pieces, is one SVG line.
#pragma once

#include <vector>

#include "render/line_drawing.h"

namespace roomcad::detail {

/// Merges segments on one line (direction within 1e-7 rad, offset within 1e-7 units) whose
/// extents overlap or touch (gap <= 1e-9). Zero-length segments are dropped.
/// @return the merged segments, ordered by line then position (deterministic). O(n log n).
[[nodiscard]] std::vector<Segment2> merge_collinear(std::vector<Segment2> segments);

}  // namespace roomcad::detail
