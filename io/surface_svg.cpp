// SPDX-License-Identifier: GPL-3.0-or-later
// Surface drawings as SVG: one group per kind of visible piece.
#include "io/surface_svg.h"

#include <array>
#include <vector>

namespace roomcad {

SvgDocument make_surface_svg(const SurfaceDrawing& drawing, const std::string& title) {
  SvgDocument doc(drawing.width, drawing.height);
  if (!title.empty()) doc.set_title(title);
  doc.add_rect({0, 0}, drawing.width, drawing.height, {.fill = "#fff"});
  struct Group {
    HorizonSide side;
    const char* name;
    const char* colour;
  };
  // Colours as the raster picture's (render/line_raster.h SurfacePalette).
  constexpr std::array<Group, 3> kGroups{{{HorizonSide::first, "front", "#000000"},
                                          {HorizonSide::upper, "upper", "#143ca0"},
                                          {HorizonSide::lower, "lower", "#be2828"}}};
  std::vector<Point2> points;
  for (const Group& group : kGroups) {
    doc.begin_group(
        group.name, group.name,
        {.stroke = group.colour, .stroke_width = 0.2, .fill = "none", .linecap = "round"});
    for (const HorizonPolyline& line : drawing.polylines) {
      if (line.side != group.side) continue;
      points.clear();
      for (const ScreenPoint& p : line.points) points.push_back({p.x, p.y});
      doc.add_polyline(points);
    }
    doc.end_group();
  }
  return doc;
}

}  // namespace roomcad
