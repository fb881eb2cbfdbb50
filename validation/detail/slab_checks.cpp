// SPDX-License-Identifier: GPL-3.0-or-later
// slab_overlap, opening_blocked by slabs, and out_of_bounds of slabs and levels (plan format
// version 2), on the resolved plan (absolute heights). Walls and slabs that share volume are
// joined, never an error.
//
// A slab is its area (outline minus holes) times [top - thickness, top]. Two slabs overlap
// when their bands share a positive height and their areas share interior area (exact, CGAL
// rationals: polygon_overlap.h). An opening's hole (its piece on a straight wall or chord, the
// extent of its outline) is blocked by a slab whose band meets the hole's heights and whose
// area meets the hole's plan quad with positive area: decided exactly (exact::decide), the
// quad's corners carrying the square root of the wall's length.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "geometry/polygon_predicates.h"
#include "plan/plan_levels.h"
#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"
#include "validation/detail/resolved_plan.h"
#include "validation/detail/shapes.h"

namespace roomcad::detail {
namespace {

Where where_of(const Box2& b) { return box_where(b.min_x, b.min_y, b.max_x, b.max_y); }

std::string slab_name(const Slab& s) { return fmt::format("slab '{}'", s.id); }

/// Whether two slabs' bands [top - thickness, top] share a positive height (exact).
bool bands_overlap(const Slab& a, const Slab& b) {
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    return static_cast<bool>(spans_overlap(NT(a.top) - NT(a.thickness), NT(a.top),
                                           NT(b.top) - NT(b.thickness), NT(b.top)));
  });
}

void check_slab_overlaps(const Plan& plan, const std::vector<bool>& usable,
                         const std::vector<Box2>& boxes, Report& report) {
  for (const auto& [i, j] : find_meeting_boxes(boxes)) {
    const Slab& a = plan.slabs[i];
    const Slab& b = plan.slabs[j];
    if (!usable[i] || !usable[j] || !bands_overlap(a, b)) continue;
    if (!areas_overlap(a.outline, a.holes, b.outline, b.holes)) continue;
    const double lo = std::max(a.top - a.thickness, b.top - b.thickness);
    const double hi = std::min(a.top, b.top);
    const Box2 common{
        std::max(boxes[i].min_x, boxes[j].min_x), std::max(boxes[i].min_y, boxes[j].min_y),
        std::min(boxes[i].max_x, boxes[j].max_x), std::min(boxes[i].max_y, boxes[j].max_y), 0};
    report.add(make_diagnostic(
        Severity::error, Code::slab_overlap, {a.id, b.id},
        fmt::format("{} and {} overlap in plan, and in height from z = {} to {}.", slab_name(a),
                    slab_name(b), metres(lo), metres(hi)),
        fmt::format("cut the outline of {} back to where {} ends (or put it at another height, "
                    "or delete it if it is drawn twice)",
                    b.id, a.id),
        where_of(common)));
  }
}

/// Whether the hole of opening `o` in wall `h` shares volume with slab `s` (exact).
bool slab_blocks(const Wall& h, const Opening& o, const Slab& s) {
  const auto orient = [](Polygon p) {  // counter-clockwise, for a positive clipped area
    double twice = 0;
    for (std::size_t k = 0; k < p.size(); ++k)
      twice += p[k].x * p[(k + 1) % p.size()].y - p[k].y * p[(k + 1) % p.size()].x;
    if (twice < 0) std::reverse(p.begin(), p.end());
    return p;
  };
  const Polygon outline = orient(s.outline);
  std::vector<Polygon> holes;
  for (const Polygon& hole : s.holes) holes.push_back(orient(hole));
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    const NT bottom = NT(h.base) + NT(o.sill);
    if (!spans_overlap(bottom, bottom + NT(o.height), NT(s.top) - NT(s.thickness), NT(s.top)))
      return false;
    const Quad<NT> quad = hole_corners<NT>(h, o);
    NT area = clipped_area(outline, quad);
    for (const Polygon& hole : holes) area = area - clipped_area(hole, quad);
    return static_cast<bool>(area > NT(0));
  });
}

void check_blocking_slabs(const ResolvedPlan& r, const std::vector<Box2>& slab_boxes,
                          Report& report) {
  const Plan& plan = r.plan;
  std::vector<Box2> holes;
  std::vector<Box2> hole_of(plan.openings.size());  // by opening, for `where`
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    if (!r.usable.host[i]) continue;
    CGAL::Protect_FPU_rounding<true> upward;
    hole_of[i] =
        box_of(hole_corners<exact::Approx>(plan.walls[*r.usable.host[i]], plan.openings[i]), i);
    holes.push_back(hole_of[i]);
  }
  for (const auto& [i, k] : find_meeting_boxes(holes, slab_boxes)) {
    const Opening& o = plan.openings[i];
    const Wall& h = plan.walls[*r.usable.host[i]];
    const Slab& s = plan.slabs[k];
    if (!r.usable.slabs[k] || !slab_blocks(h, o, s)) continue;
    report.add(make_diagnostic(
        Severity::error, Code::opening_blocked, {o.id, h.id, s.id},
        fmt::format("{} in {} is blocked: {} (z = {} to {}) crosses its hole (z = {} to {}).",
                    name_of(o), name_of(h), slab_name(s), metres(s.top - s.thickness),
                    metres(s.top), metres(h.base + o.sill), metres(h.base + o.sill + o.height)),
        fmt::format("lower {} under the slab or raise its sill above it, or cut the slab's "
                    "outline back from wall '{}'",
                    o.id, h.id),
        where_of(hole_of[i])));
  }
}

/// The site's rectangle contains every corner of `p` (exact).
bool inside_site(const Site& site, const Polygon& p) {
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    const NT x0(site.origin.x), y0(site.origin.y);
    const NT x1 = x0 + NT(static_cast<double>(site.cells[0])) * NT(site.cell_size);
    const NT y1 = y0 + NT(static_cast<double>(site.cells[1])) * NT(site.cell_size);
    return std::all_of(p.begin(), p.end(), [&](const Point2& c) {
      return NT(c.x) >= x0 && NT(c.x) <= x1 && NT(c.y) >= y0 && NT(c.y) <= y1;
    });
  });
}

void check_slab_bounds(const Plan& plan, const Slab& s, const Box2& box, Report& report) {
  const bool inside = inside_site(plan.site, s.outline);
  const bool above = exact::decide([&](auto tag) {
    using NT = decltype(tag);
    return NT(s.top) - NT(s.thickness) >= NT(0);
  });
  const bool under = exact::decide([&](auto tag) {
    using NT = decltype(tag);
    return NT(s.top) <= NT(plan.site.max_height);
  });
  if (inside && above && under) return;
  std::string problem, fix;
  if (!inside) {
    problem = "reaches outside the site";
    fix = "move its outline inside the site, or enlarge the site (cells, origin)";
  } else if (!above) {
    problem = fmt::format("starts at z = {}, below the site's floor (z = 0)",
                          metres(s.top - s.thickness));
    fix = fmt::format("raise its top by {}", metres_at_least(s.thickness - s.top));
  } else {
    problem = fmt::format("rises to z = {}, above the site's max_height {}", metres(s.top),
                          metres(plan.site.max_height));
    fix = fmt::format("lower its top to {} or raise site.max_height",
                      metres_at_most(plan.site.max_height));
  }
  report.add(make_diagnostic(Severity::error, Code::out_of_bounds, {s.id},
                             fmt::format("{} {}.", slab_name(s), problem), fix, where_of(box)));
}

/// out_of_bounds for a level whose floor (its elevation) is not within [0, max_height]. Its
/// height is only the default of its walls, which are judged themselves: a roof level whose
/// nominal storey rises past max_height is not an error.
void check_level_bounds(const Plan& plan, Report& report) {
  for (const Level& l : plan.levels) {
    if (!std::isfinite(l.elevation) || !(l.height > 0)) continue;  // invalid_value already
    const bool fits = exact::decide([&](auto tag) {
      using NT = decltype(tag);
      return NT(l.elevation) >= NT(0) && NT(l.elevation) <= NT(plan.site.max_height);
    });
    if (fits) continue;
    report.add(make_diagnostic(
        Severity::error, Code::out_of_bounds, {l.id},
        fmt::format("level '{}' has its floor at z = {}, outside the site's heights 0 to "
                    "max_height {}.",
                    l.id, metres(l.elevation), metres(plan.site.max_height)),
        l.elevation < 0 ? fmt::format("raise its elevation by {}", metres_at_least(-l.elevation))
                        : fmt::format("raise site.max_height to {} or more, or lower the level",
                                      metres_at_least(l.elevation))));
  }
}

}  // namespace

void check_slabs(const Plan& plan, const Usable& usable, const ResolvedPlan& resolved, const Joins&,
                 const Footprints&, Report& report) {
  const Plan& r = resolved.plan;  // slabs with absolute tops
  std::vector<Box2> boxes;
  for (std::size_t i = 0; i < r.slabs.size(); ++i)
    boxes.push_back(resolved.usable.slabs[i] ? box_of_polygon(r.slabs[i].outline, i)
                                             : Box2{NAN, NAN, NAN, NAN, i});
  std::erase_if(boxes, [](const Box2& b) { return std::isnan(b.min_x); });
  check_slab_overlaps(r, resolved.usable.slabs, boxes, report);
  check_blocking_slabs(resolved, boxes, report);
  if (!usable.site) return;
  for (const Box2& b : boxes) check_slab_bounds(r, r.slabs[b.index], b, report);
  check_level_bounds(plan, report);
}

}  // namespace roomcad::detail
