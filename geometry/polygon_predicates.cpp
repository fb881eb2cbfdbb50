// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/polygon_predicates.h"

#include "geometry/exact_polygon_set.h"

namespace roomcad {
namespace {

using Kernel = CGAL::Epeck;
using FT = Kernel::FT;
using CgalPolygon = detail::ExactPolygon;
using WithHoles = detail::ExactPolygonWithHoles;
using detail::ExactPolygonSet;

CgalPolygon to_cgal(const Polygon& p) {
  CgalPolygon out;
  for (const Point2& c : p) out.push_back(Kernel::Point_2(c.x, c.y));
  return out;
}

/// An area as CGAL wants it: outline counter-clockwise, holes clockwise.
WithHoles area_of(const Polygon& outline, const std::vector<Polygon>& holes) {
  CgalPolygon outer = to_cgal(outline);
  if (outer.is_clockwise_oriented()) outer.reverse_orientation();
  WithHoles area(outer);
  for (const Polygon& h : holes) {
    CgalPolygon hole = to_cgal(h);
    if (hole.is_counterclockwise_oriented()) hole.reverse_orientation();
    area.add_hole(hole);
  }
  return area;
}

/// The outline of an opening in its wall's (u, v) frame, in exact rationals.
CgalPolygon outline_in_wall(const Opening& o) {
  static const Polygon kRectangle{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Polygon& unit = o.shape.empty() ? kRectangle : o.shape;
  CgalPolygon out;
  for (const Point2& p : unit)
    out.push_back(
        Kernel::Point_2(FT(o.offset) + FT(p.x) * FT(o.width), FT(o.sill) + FT(p.y) * FT(o.height)));
  if (out.is_clockwise_oriented()) out.reverse_orientation();
  return out;
}

bool segments_meet(const CgalPolygon& a, const CgalPolygon& b) {
  for (auto ea = a.edges_begin(); ea != a.edges_end(); ++ea)
    for (auto eb = b.edges_begin(); eb != b.edges_end(); ++eb)
      if (CGAL::do_intersect(*ea, *eb)) return true;
  return false;
}

}  // namespace

bool is_simple_polygon(const Polygon& polygon) {
  if (polygon.size() < 3) return false;
  const CgalPolygon p = to_cgal(polygon);
  return p.is_simple() && p.orientation() != CGAL::COLLINEAR;
}

bool is_strictly_inside(const Polygon& inner, const Polygon& outer) {
  const CgalPolygon in = to_cgal(inner), out = to_cgal(outer);
  if (segments_meet(in, out)) return false;
  return out.bounded_side(in.vertex(0)) == CGAL::ON_BOUNDED_SIDE;
}

bool are_disjoint(const Polygon& a, const Polygon& b) {
  const CgalPolygon pa = to_cgal(a), pb = to_cgal(b);
  if (segments_meet(pa, pb)) return false;
  return pb.bounded_side(pa.vertex(0)) == CGAL::ON_UNBOUNDED_SIDE &&
         pa.bounded_side(pb.vertex(0)) == CGAL::ON_UNBOUNDED_SIDE;
}

bool areas_overlap(const Polygon& a, const std::vector<Polygon>& a_holes, const Polygon& b,
                   const std::vector<Polygon>& b_holes) {
  // CGAL's Boolean operations are regularised: what only touches is no part of the result.
  ExactPolygonSet common(area_of(a, a_holes));
  common.intersection(ExactPolygonSet(area_of(b, b_holes)));
  return !common.is_empty();
}

bool outlines_overlap(const Opening& a, const Opening& b) {
  ExactPolygonSet common(outline_in_wall(a));
  common.intersection(ExactPolygonSet(outline_in_wall(b)));
  return !common.is_empty();
}

namespace {

Polygon rounded(const CgalPolygon& p) {
  Polygon out;
  for (const auto& c : p.vertices())
    out.push_back({CGAL::to_double(c.x()), CGAL::to_double(c.y())});
  return out;
}

}  // namespace

std::vector<Area> area_difference(const Polygon& a, const std::vector<Polygon>& a_holes,
                                  const Polygon& b, const std::vector<Polygon>& b_holes) {
  ExactPolygonSet rest(area_of(a, a_holes));
  rest.difference(ExactPolygonSet(area_of(b, b_holes)));
  std::vector<Area> out;
  for (const WithHoles& piece : rest.polygons_with_holes()) {
    Area area{rounded(piece.outer_boundary()), {}};
    for (const CgalPolygon& hole : piece.holes()) area.holes.push_back(rounded(hole));
    out.push_back(std::move(area));
  }
  return out;
}

}  // namespace roomcad
