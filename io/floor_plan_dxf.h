// SPDX-License-Identifier: GPL-3.0-or-later
// Floor plans as DXF (AutoCAD 2000, AC1015, ASCII): `roomcad draw PLAN --view plan -o plan.dxf`.
//
// The same drawing as the SVG (render/floor_plan.h), mapped back from paper to the plan: every
// entity in model space at true size, in metres ($INSUNITS 6), x east and y north; text heights
// are the paper sizes at the drawing's scale (3 mm at 1:50 is 0.15 m). Layers:
//   WALLS_CUT    cut walls: a closed LWPOLYLINE and a SOLID HATCH each
//   WALLS_BELOW  walls wholly below the cut: closed LWPOLYLINEs
//   WALLS_ABOVE  walls wholly above it: closed LWPOLYLINEs, linetype DASHED
//   WINDOWS      three LINEs per cut window
//   DOORS        each leaf a LINE, its swing an ARC
//   DIMENSIONS   extension and dimension lines (LINE) and lengths (TEXT)
//   ROOMS        room outlines (closed LWPOLYLINE), names and areas (TEXT)
// The scale bar and the title belong to the paper and are left out. Handles are numbered in
// writing order: the same drawing gives the same bytes.
#pragma once

#include <filesystem>
#include <string>

#include "core/error.h"
#include "render/floor_plan.h"

namespace roomcad {

/// The layer names, in the order the file declares them (after layer 0).
inline constexpr const char* kDxfLayers[] = {"WALLS_CUT", "WALLS_BELOW", "WALLS_ABOVE", "WINDOWS",
                                             "DOORS",     "DIMENSIONS",  "ROOMS"};

/// @return the DXF text of the floor plan. O(n) in the drawing's elements.
[[nodiscard]] std::string format_floor_plan_dxf(const FloorPlanDrawing& drawing);

/// Writes format_floor_plan_dxf(drawing) to `path` atomically.
/// @return a failure naming the file and the reason.
Status write_floor_plan_dxf(const FloorPlanDrawing& drawing, const std::filesystem::path& path);

}  // namespace roomcad
