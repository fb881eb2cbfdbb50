// SPDX-License-Identifier: GPL-3.0-or-later
// The walls of the floor plan: cut parts between the openings the section passes through,
// window symbols, door leaves and swings, and walls wholly below or above the cut.
#include <algorithm>

#include "plan/plan_objects.h"
#include "render/detail/plan_paper.h"

namespace roomcad::detail {
namespace {

/// A wall's own frame: u along from -> to (metres from `from`), n its left normal.
struct WallFrame {
  Point2 origin;
  Point2 d;
  Point2 n;
  double half_thickness = 0.0;

  [[nodiscard]] double u_of(Point2 p) const { return dot(p - origin, d); }
  [[nodiscard]] Point2 at(double u, double across) const { return origin + u * d + across * n; }
};

WallFrame frame_of(const Wall& wall) {
  const Point2 along = wall.to - wall.from;
  const Point2 d = (1.0 / length(along)) * along;
  return {wall.from, d, left_normal(d), 0.5 * wall.thickness};
}

/// Keeps the part of a convex polygon where sign * (u - bound) >= 0 (Sutherland-Hodgman).
std::vector<Point2> clip_by_u(const std::vector<Point2>& polygon, const WallFrame& f, double bound,
                              double sign) {
  std::vector<Point2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2 p = polygon[i];
    const Point2 q = polygon[(i + 1) % polygon.size()];
    const double sp = sign * (f.u_of(p) - bound);
    const double sq = sign * (f.u_of(q) - bound);
    if (sp >= 0.0) out.push_back(p);
    if ((sp < 0.0) != (sq < 0.0)) out.push_back(p + (sp / (sp - sq)) * (q - p));
  }
  return out;
}

/// Whether the section at `v_cut` above the wall's base passes through the opening. A door is
/// always cut: plans show door openings whatever the cut height.
bool is_cut(const Opening& o, double v_cut) {
  return o.type == OpeningType::door || (o.sill < v_cut && v_cut < o.sill + o.height);
}

void draw_window(const WallFrame& f, double a, double b, const PaperMap& map,
                 FloorPlanDrawing& out) {
  for (const double across : {-f.half_thickness, 0.0, f.half_thickness}) {
    out.windows.push_back({map.to_paper(f.at(a, across)), map.to_paper(f.at(b, across))});
  }
}

void draw_door(const WallFrame& f, const Opening& o, const PaperMap& map, FloorPlanDrawing& out) {
  const bool hinge_at_start = o.hinge == Hinge::left;
  const double side = o.swing == Swing::in ? 1.0 : -1.0;
  const double hinge_u = hinge_at_start ? o.offset : o.offset + o.width;
  const Point2 hinge = f.at(hinge_u, side * f.half_thickness);
  const Point2 open_end = hinge + (side * o.width) * f.n;
  const Point2 closed_end = hinge + ((hinge_at_start ? 1.0 : -1.0) * o.width) * f.d;
  out.door_leaves.push_back({map.to_paper(hinge), map.to_paper(open_end)});
  out.door_swings.push_back({map.to_paper(hinge), map.to_paper(open_end), map.to_paper(closed_end),
                             o.width * map.mm_per_m});
}

/// Draws a cut wall: its footprint minus the spans of the openings the section cuts.
void draw_cut_wall(const std::vector<Point2>& footprint, const WallFrame& f, double v_cut,
                   const std::vector<const Opening*>& openings, const PaperMap& map,
                   FloorPlanDrawing& out) {
  double solid_from = -INFINITY;
  const auto add_solid = [&](double to) {
    std::vector<Point2> part = footprint;
    if (std::isfinite(solid_from)) part = clip_by_u(part, f, solid_from, 1.0);
    if (std::isfinite(to)) part = clip_by_u(part, f, to, -1.0);
    if (part.size() >= 3) out.cut_walls.push_back(map.to_paper(part));
  };
  for (const Opening* o : openings) {
    if (!is_cut(*o, v_cut)) continue;
    add_solid(o->offset);
    solid_from = o->offset + o->width;
    if (o->type == OpeningType::window) {
      draw_window(f, o->offset, solid_from, map, out);
    } else {
      draw_door(f, *o, map, out);
    }
  }
  add_solid(INFINITY);
}

/// The openings of each wall (by index), sorted along the wall.
std::vector<std::vector<const Opening*>> openings_along_walls(const Plan& plan) {
  std::vector<std::vector<const Opening*>> out(plan.walls.size());
  const OpeningsByWall by_wall = openings_by_wall(plan);
  for (std::size_t w = 0; w < by_wall.size(); ++w)
    for (const std::size_t o : by_wall[w]) out[w].push_back(&plan.openings[o]);
  for (auto& list : out) {
    std::stable_sort(list.begin(), list.end(),
                     [](const Opening* a, const Opening* b) { return a->offset < b->offset; });
  }
  return out;
}

}  // namespace

void draw_plan_walls(const Plan& plan, const Joins& joins, const FloorPlanOptions& options,
                     const PaperMap& map, FloorPlanDrawing& out) {
  const auto openings = openings_along_walls(plan);
  for (std::size_t i = 0; i < plan.walls.size(); ++i) {
    const Wall& wall = plan.walls[i];
    if (!(length(wall.to - wall.from) > 0.0 && wall.thickness > 0.0)) continue;
    const auto corners = wall_footprint(plan, joins, i);
    const std::vector<Point2> footprint(corners.begin(), corners.end());
    const double top = wall.base + wall.height;
    if (top <= options.cut_height) {
      out.walls_below.push_back(map.to_paper(footprint));
    } else if (wall.base >= options.cut_height) {
      out.walls_above.push_back(map.to_paper(footprint));
    } else {
      draw_cut_wall(footprint, frame_of(wall), options.cut_height - wall.base, openings[i], map,
                    out);
    }
  }
}

}  // namespace roomcad::detail
