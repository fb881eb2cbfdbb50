// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/cells/find_cells.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_2_algorithms.h>

#include "geometry/box_grid.h"
#include "geometry/exact_polygon_set.h"

namespace roomcad::detail {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using PlanePoint = Epick::Point_2;
using PlanPolygon = roomcad::Polygon;  // (detail has a Polygon of its own)

Box2 grown(Box2 b, double margin) {
  b.min_x -= margin, b.min_y -= margin, b.max_x += margin, b.max_y += margin;
  return b;
}

Box2 box_of(const PlanPolygon& polygon) {
  Box2 b = empty_box2();
  for (const Point2& p : polygon) add_point(b, p.x, p.y);
  return b;
}

Box2 plan_box(const Box3& b) { return {b.low[0], b.low[1], b.high[0], b.high[1], 0}; }

std::vector<PlanePoint> plane_points(const PlanPolygon& polygon) {
  std::vector<PlanePoint> out;
  out.reserve(polygon.size());
  for (const Point2& p : polygon) out.emplace_back(p.x, p.y);
  return out;
}

PlanPolygon rounded(const ExactPolygon& polygon) {
  PlanPolygon out;
  out.reserve(polygon.size());
  for (const auto& v : polygon.vertices())
    out.push_back({CGAL::to_double(v.x()), CGAL::to_double(v.y())});
  return out;
}

ExactPolygon exact(const PlanPolygon& polygon) {
  ExactPolygon out;
  for (const Point2& p : polygon) out.push_back({p.x, p.y});
  return out;
}

/// The lowest top of a wall over its footprint (a sloped top's plane at the footprint's
/// corners: mitres reach past the ends).
double lowest_top(const WallFrame& f) {
  double low = std::min(f.top, f.top_end);
  if (!is_sloped(f)) return low;
  for (const Point2& c : f.footprint)
    low = std::min(low, f.top + (f.heights[1] - f.heights[0]) * u_of(f, c) / f.length);
  return low - 1e-9 * (1.0 + std::abs(low));  // the doubles above round; a bound must not
}

bool is_simple_counter_clockwise(const ExactPolygon& p) {
  return p.size() >= 3 && p.is_simple() && p.orientation() == CGAL::COUNTERCLOCKWISE;
}

/// A slab's area, outline counter-clockwise and holes clockwise; nullopt when not simple.
std::optional<ExactPolygonWithHoles> slab_area(const Slab& s) {
  ExactPolygon outline = exact(s.outline);
  if (outline.size() < 3 || !outline.is_simple()) return std::nullopt;
  if (outline.orientation() == CGAL::CLOCKWISE) outline.reverse_orientation();
  ExactPolygonWithHoles area(outline);
  for (const PlanPolygon& h : s.holes) {
    ExactPolygon hole = exact(h);
    if (hole.size() < 3 || !hole.is_simple()) return std::nullopt;
    if (hole.orientation() == CGAL::COUNTERCLOCKWISE) hole.reverse_orientation();
    area.add_hole(hole);
  }
  return area;
}

/// An outline (a part of a band's solid) with its edges filed by box, for is_inside_an_outline.
struct Outline {
  PlanPolygon polygon;
  std::vector<PlanePoint> points;
  Box2 box;
  BoxGrid edges;  ///< edge i from points[i] to points[i + 1]

  explicit Outline(PlanPolygon p) : polygon(std::move(p)), points(plane_points(polygon)) {
    box = box_of(polygon);
    std::vector<Box2> boxes;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Point2& a = polygon[i];
      const Point2& b = polygon[(i + 1) % polygon.size()];
      boxes.push_back(
          {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y), i});
    }
    edges = BoxGrid(std::move(boxes));
  }
};

/// Whether the closed box lies inside one of the outlines, touching none of their edges. A box
/// no edge meets lies wholly on one side: one corner tells which. O(edges near the box + n) a
/// candidate outline.
bool is_inside_an_outline(const Box2& b, std::vector<Outline>& outlines) {
  const Epick::Iso_rectangle_2 box(PlanePoint(b.min_x, b.min_y), PlanePoint(b.max_x, b.max_y));
  for (Outline& o : outlines) {
    if (b.min_x <= o.box.min_x || b.max_x >= o.box.max_x || b.min_y <= o.box.min_y ||
        b.max_y >= o.box.max_y)
      continue;
    bool crossed = false;
    o.edges.for_each_meeting(b, [&](std::size_t i) {
      crossed =
          crossed || CGAL::do_intersect(
                         Epick::Segment_2(o.points[i], o.points[(i + 1) % o.points.size()]), box);
    });
    if (!crossed && CGAL::bounded_side_2(o.points.begin(), o.points.end(), box.vertex(0),
                                         Epick()) == CGAL::ON_BOUNDED_SIDE)
      return true;
  }
  return false;
}

/// A wall as the cells see it: its footprint, base and lowest top.
struct CellWall {
  std::size_t frame = 0;
  ExactPolygon footprint;
  double base = 0.0, top = 0.0;
};

/// A band of heights whose walls are found together: every point of `solid` is inside some
/// wall at every height from `low` to `high`.
struct Band {
  double low = 0.0, high = 0.0;
  ExactPolygonSet solid{};
  double area = 0.0;
  std::size_t first_cell = 0;
  std::vector<ExactPolygon> faces{};  ///< per cell, its face (counter-clockwise), exact
  std::vector<Outline> outlines{};    ///< the outlines of the solid's parts
};

double area_of(const ExactPolygonSet& set) {
  double area = 0.0;
  for (const ExactPolygonWithHoles& p : set.polygons_with_holes()) {
    area += CGAL::to_double(p.outer_boundary().area());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) area += CGAL::to_double(h->area());
  }
  return area;
}

/// Whether a slab spans height z (a band ends there: the slab closes cells from above or below).
bool is_slab_height(const Plan& plan, bool slabs, double z) {
  return slabs && std::any_of(plan.slabs.begin(), plan.slabs.end(), [z](const Slab& s) {
           return s.top - s.thickness <= z && z <= s.top;
         });
}

/// The bands of the walls, from the bottom. Heights split where a wall starts or ends; two
/// neighbouring spans join into one band while the solid both share keeps at least
/// kKeptArea of the lower one's (walls stacked on walls, a beam or a parapet) and no slab lies
/// between them (there a band ends, so that slabs can close its cells).
std::vector<Band> find_bands(const Plan& plan, bool slabs, const std::vector<CellWall>& walls) {
  constexpr double kKeptArea = 0.95;
  std::vector<double> heights;
  for (const CellWall& w : walls) heights.push_back(w.base), heights.push_back(w.top);
  std::sort(heights.begin(), heights.end());
  heights.erase(std::unique(heights.begin(), heights.end()), heights.end());
  std::vector<Band> bands;
  for (std::size_t k = 0; k + 1 < heights.size(); ++k) {
    std::vector<ExactPolygon> feet;
    for (const CellWall& w : walls)
      if (w.base <= heights[k] && w.top >= heights[k + 1]) feet.push_back(w.footprint);
    if (feet.empty()) continue;
    Band span{.low = heights[k], .high = heights[k + 1]};
    span.solid.join(feet, {});
    span.area = area_of(span.solid);
    if (!bands.empty() && bands.back().high == span.low && !is_slab_height(plan, slabs, span.low)) {
      Band& last = bands.back();
      ExactPolygonSet shared;
      shared.join({}, last.solid.polygons_with_holes());
      shared.intersection(span.solid);
      const double area = area_of(shared);
      if (area >= kKeptArea * last.area) {
        last.high = span.high;
        last.solid = std::move(shared);
        last.area = area;
        continue;
      }
    }
    bands.push_back(std::move(span));
  }
  return bands;
}

/// Fills the band's cells: faces of its solid, islands, boxes.
void add_cells(Band& band, Cells& out) {
  band.first_cell = out.cells.size();
  for (const ExactPolygonWithHoles& part : band.solid.polygons_with_holes()) {
    band.outlines.emplace_back(rounded(part.outer_boundary()));
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h) {
      ExactPolygon face = *h;
      face.reverse_orientation();
      Cell& c = out.cells.emplace_back();
      c.outline = rounded(face);
      c.floor_z = c.eye_low = band.low;
      c.top_z = c.eye_high = band.high;
      band.faces.push_back(std::move(face));
    }
  }
  for (std::size_t k = band.first_cell; k < out.cells.size(); ++k) {
    Cell& c = out.cells[k];
    const Box2 box = grown(box_of(c.outline), kCellMargin);
    const std::vector<PlanePoint> pts = plane_points(c.outline);
    for (const Outline& outline : band.outlines) {  // the part around the face is outside it
      if (boxes_meet(box, outline.box) &&
          CGAL::bounded_side_2(pts.begin(), pts.end(), outline.points[0], Epick()) ==
              CGAL::ON_BOUNDED_SIDE) {
        c.islands.push_back(outline.polygon);
        std::reverse(c.islands.back().begin(), c.islands.back().end());
      }
    }
    add_point(c.bounds, box.min_x, box.min_y, c.floor_z - kCellMargin);
    add_point(c.bounds, box.max_x, box.max_y, c.top_z + kCellMargin);
  }
}

/// Closes the band's cells at `height` where slabs spanning it cover their faces, and keeps
/// the eye off those slabs. `above`: the slabs close the tops (else the bottoms).
void close_by_slabs(const Plan& plan, const Band& band, double height, bool above, Cells& out) {
  std::vector<ExactPolygonWithHoles> areas;
  std::vector<Box3> boxes;
  for (const Slab& s : plan.slabs) {
    const double bottom = s.top - s.thickness;
    if (!(bottom <= height && height <= s.top && bottom < s.top)) continue;
    if (auto area = slab_area(s)) {
      areas.push_back(std::move(*area));
      Box3 b = empty_box3();
      for (const Point2& p : s.outline) add_point(b, p.x, p.y, bottom);
      add_point(b, s.outline[0].x, s.outline[0].y, s.top);
      boxes.push_back(b);
    }
  }
  if (areas.empty()) return;
  ExactPolygonSet blockers;
  blockers.join({}, areas);
  ExactPolygonSet uncovered;
  uncovered.join(band.faces, {});
  uncovered.difference(blockers);
  std::vector<Box2> gaps;
  for (const ExactPolygonWithHoles& gap : uncovered.polygons_with_holes())
    gaps.push_back(grown(box_of(rounded(gap.outer_boundary())), kCellMargin));
  BoxGrid gap_grid(std::move(gaps));
  for (std::size_t k = band.first_cell; k < band.first_cell + band.faces.size(); ++k) {
    Cell& c = out.cells[k];
    const Box2 box = plan_box(c.bounds);
    bool covered = true;
    gap_grid.for_each_meeting(box, [&](std::size_t) { covered = false; });
    (above ? c.open_top : c.open_bottom) = !covered;
    for (const Box3& b : boxes) {
      if (!boxes_meet(box, plan_box(b))) continue;
      if (above) c.eye_high = std::min(c.eye_high, b.low[2]);
      else c.eye_low = std::max(c.eye_low, b.high[2]);
    }
  }
}

/// The grown box of a hole through a wall, as its 8 corners.
std::array<Vec3, 8> hole_corners(const WallFrame& f, const Hole& h) {
  double u0 = h.u0 - kCellMargin, u1 = h.u1 + kCellMargin;
  for (const Point2& c : f.footprint) {  // a hole running on through a mitre reaches its corners
    if (h.through_mitre[0]) u0 = std::min(u0, u_of(f, c) - kCellMargin);
    if (h.through_mitre[1]) u1 = std::max(u1, u_of(f, c) + kCellMargin);
  }
  const double n = f.half + kCellMargin, z0 = h.z0 - kCellMargin, z1 = h.z1 + kCellMargin;
  std::array<Vec3, 8> corners;
  for (int k = 0; k < 8; ++k) {
    const double u = (k & 1) ? u1 : u0, v = (k & 2) ? n : -n;
    corners[k] = {f.from.x + f.dir.x * u + f.normal.x * v, f.from.y + f.dir.y * u + f.normal.y * v,
                  (k & 4) ? z1 : z0};
  }
  return corners;
}

/// @return a grid of the plan boxes of the band's cells, tagged with their indices.
BoxGrid cell_grid(const Band& band, const Cells& out) {
  std::vector<Box2> boxes;
  for (std::size_t k = band.first_cell; k < band.first_cell + band.faces.size(); ++k) {
    Box2 b = plan_box(out.cells[k].bounds);
    b.index = k;
    boxes.push_back(b);
  }
  return BoxGrid(std::move(boxes));
}

/// Adds a portal per hole of the walls standing in the band, as an exit of every cell of the
/// band its box meets.
void add_portals(const std::vector<WallFrame>& frames, Band& band, Cells& out) {
  BoxGrid grid = cell_grid(band, out);
  for (const WallFrame& f : frames) {
    if (f.base >= band.high || f.top_max <= band.low) continue;
    for (const Hole& h : f.holes) {
      if (h.z0 >= band.high || h.z1 <= band.low) continue;
      Portal p;
      p.corners = hole_corners(f, h);
      for (const Vec3& c : p.corners) add_point(p.bounds, c.x, c.y, c.z);
      const Box2 box = plan_box(p.bounds);
      grid.for_each_meeting(box, [&](std::size_t k) {
        if (!boxes_meet(out.cells[k].bounds, p.bounds)) return;
        p.cells.push_back(static_cast<std::uint32_t>(k));
      });
      if (p.cells.empty()) continue;
      std::sort(p.cells.begin(), p.cells.end());
      // a hole reaching past the band, or out of its walls' outlines, opens onto what no cell
      // holds
      p.to_outside = p.bounds.high[2] > band.high || p.bounds.low[2] < band.low - kCellMargin ||
                     !is_inside_an_outline(box, band.outlines);
      const auto index = static_cast<std::uint32_t>(out.portals.size());
      for (std::uint32_t k : p.cells) out.cells[k].portals.push_back(index);
      out.portals.push_back(std::move(p));
    }
  }
}

/// Links the open tops (`up`) or bottoms of `from`'s cells with the cells of `to`, the band
/// right above or below: each reaches the cells of `to` its box meets, and opens onto no cell
/// where its box leaves `to`'s outlines.
void link_bands(const Band& from, Band& to, bool up, Cells& out) {
  BoxGrid cells_of_to = cell_grid(to, out);
  for (std::size_t k = from.first_cell; k < from.first_cell + from.faces.size(); ++k) {
    Cell& c = out.cells[k];
    if (!(up ? c.open_top : c.open_bottom)) continue;
    const Box2 box = plan_box(c.bounds);
    (up ? c.top_outside : c.bottom_outside) = !is_inside_an_outline(box, to.outlines);
    std::vector<std::uint32_t>& reached = up ? c.cells_above : c.cells_below;
    cells_of_to.for_each_meeting(
        box, [&](std::size_t j) { reached.push_back(static_cast<std::uint32_t>(j)); });
  }
}

}  // namespace

Cells find_cells(const Plan& plan, const std::vector<WallFrame>& frames, bool slabs) {
  std::vector<CellWall> walls;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    ExactPolygon footprint = exact({frames[i].footprint.begin(), frames[i].footprint.end()});
    if (has_crossed_footprint(frames[i]) || !is_simple_counter_clockwise(footprint)) continue;
    walls.push_back({i, std::move(footprint), frames[i].base, lowest_top(frames[i])});
  }
  Cells out;
  out.uses_slabs = slabs && !plan.slabs.empty();
  std::vector<Band> bands = find_bands(plan, out.uses_slabs, walls);
  for (Band& band : bands) {
    add_cells(band, out);
    if (out.uses_slabs) {
      close_by_slabs(plan, band, band.low, false, out);
      close_by_slabs(plan, band, band.high, true, out);
    }
    add_portals(frames, band, out);
  }
  for (std::size_t k = 0; k + 1 < bands.size(); ++k)
    if (bands[k].high == bands[k + 1].low) {
      link_bands(bands[k], bands[k + 1], true, out);
      link_bands(bands[k + 1], bands[k], false, out);
    }
  return out;
}

}  // namespace roomcad::detail
