// SPDX-License-Identifier: GPL-3.0-or-later
// Surface drawings (render/floating_horizon.h) as SVG documents.
#pragma once

#include <string>

#include "io/svg_writer.h"
#include "render/floating_horizon.h"

namespace roomcad {

/// Builds the SVG of a surface drawing whose units are millimetres. The visible polylines go
/// into three groups, `front`, `upper` and `lower` (classes of the same names), coloured apart.
/// @param[in] title  the document title (e.g. the expression), may be empty
/// @return the document. O(points).
[[nodiscard]] SvgDocument make_surface_svg(const SurfaceDrawing& drawing, const std::string& title);

}  // namespace roomcad
