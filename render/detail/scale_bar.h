// SPDX-License-Identifier: GPL-3.0-or-later
// The scale bar every drawing at a scale carries (floor plan, elevations, isometric).
#pragma once

#include <vector>

#include "render/floor_plan.h"

namespace roomcad::detail {

/// The sheet of every drawing: a blank border around everything drawn, and under it a footer
/// that holds the scale bar and the title (mm).
constexpr double kSheetMarginMm = 10.0;
constexpr double kSheetFooterMm = 25.0;

/// Where a scale bar is added.
struct ScaleBarOut {
  std::vector<PaperPolygon>& black;  ///< filled cells
  std::vector<PaperPolygon>& white;  ///< outlined cells
  std::vector<PaperText>& labels;    ///< "0" and the length
};

/// Adds a scale bar of five cells in the footer of a sheet `width` x `height` mm, at its left
/// margin: as long as a round number of metres (0.5 ... 1000) that fits in about a third of
/// the drawing's width at `mm_per_m`. O(1).
void add_scale_bar(double width, double height, double mm_per_m, ScaleBarOut out);

}  // namespace roomcad::detail
