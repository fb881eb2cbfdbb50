// SPDX-License-Identifier: GPL-3.0-or-later
// obstruction_overlap (plan format version 2): a neighbouring building or tree drawn into the
// plan's own walls or slabs. An obstruction is the prism over its outline from base to
// base + height; a wall is its mitred footprint from its base to its highest top (a sloped
// top counts at its higher end); a slab its area times [top - thickness, top]. They overlap
// when the heights share a positive span and the plan areas share interior area, both decided
// exactly.
#include <algorithm>

#include <fmt/format.h>

#include "geometry/polygon_predicates.h"
#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"
#include "validation/detail/resolved_plan.h"
#include "validation/detail/shapes.h"

namespace roomcad::detail {
namespace {

/// Whether the obstruction's outline (counter-clockwise) and wall w's footprint share
/// interior area, and their heights a positive span. Exact.
bool meets_wall(const Obstruction& o, const Polygon& outline, const Wall& w,
                const Footprints& footprints, std::size_t index) {
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    if (!spans_overlap(NT(o.base), NT(o.base) + NT(o.height), NT(w.base),
                       NT(w.base) + NT(highest_height(w))))
      return false;
    return static_cast<bool>(clipped_area(outline, footprints.get<NT>(index)) > NT(0));
  });
}

bool meets_slab(const Obstruction& o, const Slab& s) {
  const bool heights = exact::decide([&](auto tag) {
    using NT = decltype(tag);
    return static_cast<bool>(spans_overlap(NT(o.base), NT(o.base) + NT(o.height),
                                           NT(s.top) - NT(s.thickness), NT(s.top)));
  });
  return heights && areas_overlap(o.outline, {}, s.outline, s.holes);
}

void report_overlap(const Obstruction& o, std::string_view kind, const std::string& id,
                    const Box2& box, Report& report) {
  report.add(make_diagnostic(
      Severity::error, Code::obstruction_overlap, {o.id, id},
      fmt::format("obstruction '{}' shares volume with {} '{}': a neighbour drawn into the plan.",
                  o.id, kind, id),
      fmt::format("move the outline of obstruction '{}' off {} '{}' (or lower it below it)", o.id,
                  kind, id),
      box_where(box.min_x, box.min_y, box.max_x, box.max_y)));
}

}  // namespace

void check_obstructions(const Usable& usable, const ResolvedPlan& resolved,
                        const Footprints& footprints, Report& report) {
  const Plan& r = resolved.plan;
  for (std::size_t i = 0; i < r.obstructions.size(); ++i) {
    if (!usable.obstructions[i]) continue;
    const Obstruction& o = r.obstructions[i];
    Polygon outline = o.outline;  // counter-clockwise, as clipped_area wants
    double twice = 0;
    for (std::size_t k = 0; k < outline.size(); ++k)
      twice += outline[k].x * outline[(k + 1) % outline.size()].y -
               outline[k].y * outline[(k + 1) % outline.size()].x;
    if (twice < 0) std::reverse(outline.begin(), outline.end());
    const Box2 box = box_of_polygon(outline, i);
    std::vector<bool> reported(usable.walls.size(), false);  // by input wall: arcs say it once
    for (const Box2& wall_box : footprints.boxes()) {
      const std::size_t w = wall_box.index;
      if (!boxes_meet(box, wall_box) || reported[resolved.source_wall[w]]) continue;
      if (!meets_wall(o, outline, r.walls[w], footprints, w)) continue;
      reported[resolved.source_wall[w]] = true;
      report_overlap(o, "wall", r.walls[w].id, box, report);
    }
    for (std::size_t s = 0; s < r.slabs.size(); ++s)
      if (resolved.usable.slabs[s] && boxes_meet(box, box_of_polygon(r.slabs[s].outline, s)) &&
          meets_slab(o, r.slabs[s]))
        report_overlap(o, "slab", r.slabs[s].id, box, report);
  }
}

}  // namespace roomcad::detail
