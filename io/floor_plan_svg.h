// SPDX-License-Identifier: GPL-3.0-or-later
// Floor plans (render/floor_plan.h) as SVG documents.
#pragma once

#include <string>

#include "io/svg_writer.h"
#include "render/floor_plan.h"
#include "render/line_drawing.h"

namespace roomcad {

/// Builds the SVG of a floor plan on a page of its size (mm). Each kind of element sits in a
/// group with an id and class of its own: rooms, walls-below, walls-above, cut-walls, windows,
/// doors, dimensions, room-labels, scale-bar, labels. Cut walls are filled solid (poché).
/// @return the document. O(elements).
[[nodiscard]] SvgDocument make_floor_plan_svg(const FloorPlanDrawing& drawing,
                                              const std::string& title);

/// Builds the SVG of a line drawing (elevation, isometric, camera view): groups hidden (thin,
/// dashed, under everything), visible (0.35 mm), frame, scale-bar and labels.
/// @return the document. O(elements).
[[nodiscard]] SvgDocument make_line_drawing_svg(const LineDrawing& drawing,
                                                const std::string& title);

}  // namespace roomcad
