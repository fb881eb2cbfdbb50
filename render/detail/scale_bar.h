// SPDX-License-Identifier: GPL-3.0-or-later
// The scale bar every drawing at a scale carries (floor plan, elevations, isometric).
#pragma once

#include <vector>

#include "render/floor_plan.h"

namespace roomcad::detail {

/// Where a scale bar is added.
struct ScaleBarOut {
  std::vector<PaperPolygon>& black;  ///< filled cells
  std::vector<PaperPolygon>& white;  ///< outlined cells
  std::vector<PaperText>& labels;    ///< "0" and the length
};

/// Adds a scale bar of five cells at `origin` (its top-left corner, mm), as long as a round
/// number of metres (0.5 ... 1000) that fits in `room_mm` at `mm_per_m`. O(1).
void add_scale_bar(Point2 origin, double room_mm, double mm_per_m, ScaleBarOut out);

}  // namespace roomcad::detail
