// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/convex_pieces.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <exception>
#include <iterator>
#include <tuple>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <boost/container/small_vector.hpp>

#include "solid/build_model.h"

namespace roomcad::detail {
namespace {

// a + b = hi + lo exactly, hi the rounded sum (Knuth's TwoSum; round to nearest).
std::pair<double, double> two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

PlaneRef axis_plane(PlaneSet& set, int axis, double hi, double lo, int sign) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::axis;
  r.v[0] = axis, r.v[1] = hi, r.v[2] = lo;
  return {set.add(r), sign};
}

// The vertical plane through plan points p -> q, its right side outside. @pre p != q.
PlaneRef plane_through(PlaneSet& set, Point2 p, Point2 q) {
  if (p.x == q.x) return axis_plane(set, 0, p.x, 0.0, q.y > p.y ? 1 : -1);
  if (p.y == q.y) return axis_plane(set, 1, p.y, 0.0, q.x > p.x ? -1 : 1);
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::through2;
  r.v[0] = p.x, r.v[1] = p.y, r.v[2] = q.x, r.v[3] = q.y;
  return {set.add(r), 1};
}

// The plane of a slanted wall's square end: through its end point, square to its centre line
// exactly (not through its two rounded corners), so that the square ends of walls ending at one
// point all pass through it: walls drawn along one line, end to end or over one another, have
// one plane there whatever their thickness, and walls at other angles meet on the vertical
// line through the point. Through their own rounded corners, two such caps cross at a hair's
// angle or a hair off the point, and the slivers between them round into faces that cross
// when written. Outside beyond the end.
PlaneRef square_end_plane(PlaneSet& set, const WallFrame& f, WallEnd end) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::square_end;
  const Point2 e = end == WallEnd::from ? f.from : f.to;
  r.v[0] = f.from.x, r.v[1] = f.from.y, r.v[2] = f.to.x, r.v[3] = f.to.y, r.v[4] = e.x,
  r.v[5] = e.y;
  return {set.add(r), end == WallEnd::from ? -1 : 1};
}

// The plane (p - from) . dir = u of a wall's frame; outside where u is larger (outward +1) or
// smaller (-1). An axis-aligned wall's is an axis plane at an exact sum.
PlaneRef plane_at_u(PlaneSet& set, const WallFrame& f, double u, int outward) {
  if (f.dir.y == 0.0) {
    const auto [hi, lo] = two_sum(f.from.x, f.dir.x * u);  // dir.x is +-1: the product is exact
    return axis_plane(set, 0, hi, lo, outward * (f.dir.x > 0 ? 1 : -1));
  }
  if (f.dir.x == 0.0) {
    const auto [hi, lo] = two_sum(f.from.y, f.dir.y * u);
    return axis_plane(set, 1, hi, lo, outward * (f.dir.y > 0 ? 1 : -1));
  }
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::frame_line;
  r.v[0] = f.from.x, r.v[1] = f.from.y, r.v[2] = f.dir.x, r.v[3] = f.dir.y;
  r.v[6] = 1.0, r.v[7] = 0.0, r.v[8] = -u;
  return {set.add(r), outward};
}

PlaneRef plane_at_z(PlaneSet& set, double z, int outward) {
  return axis_plane(set, 2, z, 0.0, outward);
}

// The plane of a sloped top (docs/plan-format.md, height_at_end): through the top at `from`
// and at `to`, rising by exactly height_at_end - height; above it is outside.
PlaneRef sloped_top_plane(PlaneSet& set, const WallFrame& f) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::sloped_top;
  r.v[0] = f.from.x, r.v[1] = f.from.y, r.v[2] = f.to.x, r.v[3] = f.to.y;
  r.v[4] = f.top, r.v[5] = f.heights[1], r.v[6] = f.heights[0];
  return {set.add(r), 1};
}

// The line in the wall's plane through two corners (s, t) of a shape, mapped to u = u0 + s *
// width along the wall and z = z0 + t * height; for corners in counter-clockwise order the
// shape is on its negative side.
PlaneRef shape_edge_plane(PlaneSet& set, const WallFrame& f, const Hole& h, Point2 a, Point2 b) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::frame_edge;
  r.v = {f.from.x, f.from.y, f.dir.x, f.dir.y, h.u0, h.width, a.x, a.y, b.x, b.y, h.z0, h.height};
  return {set.add(r), 1};
}

// The shape's convex parts, each counter-clockwise: the shape itself when it is convex, else
// CGAL's approximate convex partition (diagonals between its corners: no new points).
std::vector<Polygon> convex_parts(const Polygon& shape) {
  using Traits = CGAL::Partition_traits_2<CGAL::Epick>;
  std::vector<Traits::Point_2> points;
  for (const Point2& p : shape) points.emplace_back(p.x, p.y);
  Traits::Polygon_2 polygon(points.begin(), points.end());
  if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
  std::vector<Polygon> parts;
  auto to_part = [](const Traits::Polygon_2& q) {
    Polygon part;
    for (const auto& p : q.container()) part.push_back({p.x(), p.y()});
    return part;
  };
  if (polygon.is_convex()) return {to_part(polygon)};
  std::vector<Traits::Polygon_2> pieces;
  CGAL::approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(),
                                  std::back_inserter(pieces));
  for (const auto& q : pieces) parts.push_back(to_part(q));
  return parts;
}

// An explicit point with one coordinate replaced: its homogeneous coordinates too (W = 1),
// which the predicates against planes that are not axis planes read.
XPoint with_coordinate(XPoint p, int axis, double value) {
  p.approx[std::size_t(axis)] = p.hom[std::size_t(axis)] = Interval(value);
  return p;
}

// The prism over `base` (a convex polygon in plane C0, counter-clockwise seen from the side
// C1 lies on) between the outward caps c0 and c1. @pre the caps do not meet inside (parallel
// caps, base on the inner side of c1).
Primitive make_prism(const PlaneSet& set, const PlanePolygon& base, PlaneRef c0, PlaneRef c1) {
  const std::size_t k = base.lines.size();
  // Horizontal caps over vertical sides (walls): a corner of the base at explicit doubles has
  // its twin on the top at the same x and y.
  const bool vertical = simple_axis(set, c0.id).first == 2 && simple_axis(set, c1.id).first == 2;
  const double top_z = simple_axis(set, c1.id).second;
  Primitive p;
  std::vector<XPoint> a = base.vertices, b;
  b.reserve(k);
  for (std::size_t i = 0; i < k; ++i) {
    b.push_back(vertical && a[i].is_explicit()
                    ? with_coordinate(a[i], 2, top_z)
                    : make_point(set, c1.id, base.lines[i].id, base.lines[(i + 1) % k].id));
  }
  PlanePolygon bottom{c0, {}, {}}, top{c1, base.lines, b};
  for (std::size_t j = 0; j < k; ++j) {
    bottom.lines.push_back(base.lines[k - 1 - j]);
    bottom.vertices.push_back(a[(2 * k - 2 - j) % k]);
  }
  p.faces.push_back(std::move(bottom));
  p.faces.push_back(std::move(top));
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t prev = (i + k - 1) % k, next = (i + 1) % k;
    p.faces.push_back({base.lines[i],
                       {c0, base.lines[next], c1, base.lines[prev]},
                       {a[i], b[i], b[prev], a[prev]}});
  }
  p.vertices = std::move(a);
  p.vertices.insert(p.vertices.end(), b.begin(), b.end());
  p.box = box_of(p.vertices);
  return p;
}

// The convex polygon in `plane` on the negative side of every line, clipped from the box.
// @return nullopt when it has no area. @throws if it is unbounded (cannot happen for a wall).
std::optional<PlanePolygon> intersect_half_planes(const PlaneSet& set, const BoxPlanes& box,
                                                  PlaneRef plane,
                                                  const std::vector<PlaneRef>& lines,
                                                  const std::string& what) {
  PlanePolygon poly = box_polygon(set, box, plane);
  for (const PlaneRef& l : lines)
    if (!clip_polygon(set, poly, l)) return std::nullopt;
  for (const PlaneRef& l : poly.lines)
    for (std::size_t k = 0; k < 3; ++k)
      if (l.id == box.low[k] || l.id == box.high[k])
        throw PreconditionError(fmt::format("build_model: {} is not bounded by its sides", what),
                                Code::not_buildable);
  return poly;
}

// Whether each corner turns strictly left (the lines through consecutive corners exist).
bool is_strictly_convex(const PlaneSet& set, const std::array<Point2, 4>& c,
                        const std::vector<PlaneRef>& lines) {
  if (lines.size() != 4) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point2 q = c[(i + 2) % 4];
    if (side(set, lines[i], make_point(q.x, q.y, 0.0)) >= 0) return false;
  }
  return true;
}

// The wall's side planes oriented so that the wall's centre line is on their negative side.
// The corners' order does not say which when a mitre overshoots the other end (a "bow-tie"
// wall; exact_hole_footprint spans the same lines). @return nullopt for a wall thinner than
// the doubles (both side lines through its centre line): it holds no hole.
std::optional<std::array<PlaneRef, 2>> inward_sides(const PlaneSet& set, const WallFrame& f,
                                                    const std::array<PlaneRef, 4>& sides) {
  auto inward = [&](PlaneRef side_plane) -> std::optional<PlaneRef> {
    int s = side(set, side_plane, make_point(f.from.x, f.from.y, 0.0));
    if (s == 0) s = side(set, side_plane, make_point(f.to.x, f.to.y, 0.0));
    if (s == 0) return std::nullopt;
    return PlaneRef{side_plane.id, s < 0 ? side_plane.sign : -side_plane.sign};
  };
  const auto right = inward(sides[0]), left = inward(sides[2]);
  if (!right || !left) return std::nullopt;
  return std::array<PlaneRef, 2>{*right, *left};
}

// The planes of an opening's hole: its outline (one per convex part of a shaped opening) and
// the wall's sides it lies between (none: no hole).
struct HolePlanes {
  const Hole* hole = nullptr;
  std::vector<std::vector<PlaneRef>> outlines;
  bool at_end = false;  // a rectangle reaching an end's line: not a prism (add_hole)
  std::optional<std::array<PlaneRef, 2>> sides;
};

// The planes of one wall's primitives. They are made for every wall in plan order first, so
// plane ids are what one pass in that order gives, and then each wall's primitives are built
// from its planes alone, walls in parallel (predicates only read the set).
struct WallPlanes {
  std::array<PlaneRef, 4> sides{};
  std::vector<PlaneRef> lines;                      // the footprint's sides that exist
  std::vector<PlaneRef> sloped;                     // a sloped wall's sides, base and top
  std::optional<std::array<PlaneRef, 2>> base_top;  // a flat-topped wall with height: c0, c1
  std::vector<HolePlanes> holes;
};

// A rectangular opening's hole planes: its outline in the wall's plane, counter-clockwise
// seen along +normal from the right side plane (sides[0]) to the left one. A notch at a capped
// end takes the end's own plane (exact_hole_footprint does the same).
HolePlanes rectangle_hole_planes(PlaneSet& set, const WallFrame& f, const Hole& h,
                                 const std::array<PlaneRef, 4>& sides) {
  HolePlanes p{&h, {}, false, std::nullopt};
  if (!(h.u0 < h.u1) || !(h.z0 < h.z1)) return p;
  const bool from_cap = hole_reaches_end_line(f, h, 0), to_cap = hole_reaches_end_line(f, h, 1);
  p.outlines.push_back({plane_at_z(set, h.z0, -1),
                        from_cap ? sides[3] : plane_at_u(set, f, h.u0, -1),
                        plane_at_z(set, h.z1, 1), to_cap ? sides[1] : plane_at_u(set, f, h.u1, 1)});
  p.at_end = from_cap || to_cap;
  p.sides = inward_sides(set, f, sides);
  return p;
}

// A shaped opening's hole planes: each convex part of its outline, through the wall.
HolePlanes shaped_hole_planes(PlaneSet& set, const WallFrame& f, const Hole& h,
                              const std::array<PlaneRef, 4>& sides) {
  HolePlanes p{&h, {}, false, inward_sides(set, f, sides)};
  if (!p.sides) return p;
  for (const Polygon& part : convex_parts(h.shape)) {
    std::vector<PlaneRef>& outline = p.outlines.emplace_back();
    for (std::size_t i = 0; i < part.size(); ++i)
      if (part[i] != part[(i + 1) % part.size()])
        outline.push_back(shape_edge_plane(set, f, h, part[i], part[(i + 1) % part.size()]));
  }
  return p;
}

// @param shared_point  per WallEnd: the end is square, at the end point of another square end
WallPlanes wall_planes(PlaneSet& set, const WallFrame& f, std::array<bool, 2> shared_point) {
  WallPlanes p;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point2 a = f.footprint[i], b = f.footprint[(i + 1) % 4];
    if (a == b) continue;
    // Sides 1 and 3 are the to and from ends.
    const WallEnd end = i == 1 ? WallEnd::to : WallEnd::from;
    const bool square_end = (i == 1 || i == 3) && shared_point[std::size_t(end)];
    p.sides[i] = square_end ? square_end_plane(set, f, end) : plane_through(set, a, b);
    p.lines.push_back(p.sides[i]);
  }
  if (is_sloped(f)) {
    p.sloped = p.lines;
    p.sloped.push_back(plane_at_z(set, f.base, -1));
    p.sloped.push_back(sloped_top_plane(set, f));
  } else if (f.base < f.top) {
    const PlaneRef c0 = plane_at_z(set, f.base, -1);
    p.base_top = {c0, plane_at_z(set, f.top, 1)};
  }
  if (p.lines.size() < 4) return p;  // holds no hole (make_wall_frames refuses such a hole)
  for (const Hole& h : f.holes)
    p.holes.push_back(h.shape.empty() ? rectangle_hole_planes(set, f, h, p.sides)
                                      : shaped_hole_planes(set, f, h, p.sides));
  return p;
}

// The wall piece: its footprint between base and top.
std::optional<Primitive> make_wall_piece(const PlaneSet& set, const BoxPlanes& box,
                                         const WallFrame& f, const WallPlanes& planes,
                                         const std::string& name) {
  if (!planes.sloped.empty()) return make_convex(set, box, planes.sloped);
  if (!planes.base_top) return std::nullopt;
  const auto [c0, c1] = *planes.base_top;
  PlanePolygon base{{c0.id, -c0.sign}, {}, {}};
  if (is_strictly_convex(set, f.footprint, planes.lines)) {
    base.lines.assign(planes.sides.begin(), planes.sides.end());
    for (std::size_t i = 0; i < 4; ++i) {
      const Point2 q = f.footprint[(i + 1) % 4];
      // A square end's plane misses the rounded corners: the corners there are where it meets
      // the sides.
      const bool on_square_end =
          set.recipe(base.lines[i].id).kind == PlaneRecipe::Kind::square_end ||
          set.recipe(base.lines[(i + 1) % 4].id).kind == PlaneRecipe::Kind::square_end;
      base.vertices.push_back(on_square_end ? make_point(set, base.plane.id, base.lines[i].id,
                                                         base.lines[(i + 1) % 4].id)
                                            : make_point(q.x, q.y, f.base));
    }
  } else if (auto poly = intersect_half_planes(set, box, base.plane, planes.lines, name)) {
    base = std::move(*poly);
  } else {
    return std::nullopt;
  }
  return make_prism(set, base, c0, c1);
}

// The hole's primitives (a shaped opening's: one per convex part) appended to `out`.
void add_hole(const PlaneSet& set, const BoxPlanes& box, const HolePlanes& planes,
              const std::string& name, std::vector<Primitive>& out) {
  if (!planes.sides) return;
  const auto [c0, c1] = *planes.sides;
  for (const std::vector<PlaneRef>& outline : planes.outlines) {
    std::optional<Primitive> made;
    if (planes.at_end) {
      // An end's plane is not parallel to the jambs (its corners are rounded): over the
      // thickness it may cross the other jamb, so the hole is no prism between the sides.
      std::vector<PlaneRef> all = outline;
      all.push_back(c0), all.push_back(c1);
      made = make_convex(set, box, all);
    } else if (auto poly = intersect_half_planes(set, box, {c0.id, -c0.sign}, outline, name)) {
      made = make_prism(set, *poly, c0, c1);
    }
    if (!made) continue;
    made->kind = Primitive::Kind::hole;
    made->opening = planes.hole->opening;
    out.push_back(std::move(*made));
  }
}

// The wall's piece, then its holes' primitives.
std::vector<Primitive> wall_primitives(const PlaneSet& set, const BoxPlanes& box,
                                       const WallFrame& f, const WallPlanes& planes,
                                       std::size_t frame) {
  const std::string name = fmt::format("the footprint of wall '{}'", f.id);
  std::vector<Primitive> out;
  if (auto piece = make_wall_piece(set, box, f, planes, name)) out.push_back(std::move(*piece));
  for (const HolePlanes& hole : planes.holes) add_hole(set, box, hole, name, out);
  for (Primitive& p : out) p.frame = frame;
  return out;
}

}  // namespace

std::optional<Primitive> make_convex(const PlaneSet& set, const BoxPlanes& box,
                                     const std::vector<PlaneRef>& planes) {
  Primitive p;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    PlanePolygon face = box_polygon(set, box, planes[i]);
    bool kept = true;
    for (std::size_t j = 0; j < planes.size() && kept; ++j)
      if (j != i) kept = clip_polygon(set, face, planes[j]);
    if (!kept) continue;
    p.vertices.insert(p.vertices.end(), face.vertices.begin(), face.vertices.end());
    p.faces.push_back(std::move(face));
  }
  if (p.faces.size() < 4) return std::nullopt;  // no volume
  p.box = box_of(p.vertices);
  return p;
}

double largest_coordinate(std::span<const WallFrame* const> walls,
                          std::span<const SlabFrame* const> slabs) {
  double m = 0.0;
  for (const WallFrame* f : walls) {
    for (const Point2& p : f->footprint) m = std::max({m, std::abs(p.x), std::abs(p.y)});
    m = std::max({m, std::abs(f->base), std::abs(f->top_max)});
  }
  for (const SlabFrame* s : slabs)
    m = std::max({m, std::abs(s->min_x), std::abs(s->max_x), std::abs(s->min_y), std::abs(s->max_y),
                  std::abs(s->bottom), std::abs(s->top)});
  return m;
}

Box3 box_of(std::span<const XPoint> points) {
  Box3 b{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  for (const XPoint& p : points)
    for (std::size_t k = 0; k < 3; ++k) {
      b.low[k] = std::min(b.low[k], p.approx[k].inf());
      b.high[k] = std::max(b.high[k], p.approx[k].sup());
    }
  return b;
}

BoxPlanes add_box_planes(PlaneSet& set, double largest_coordinate) {
  const double m = std::ldexp(1.0, std::ilogb(4.0 * (largest_coordinate + 1.0)) + 1);
  BoxPlanes box;
  for (int k = 0; k < 3; ++k) {
    box.low[std::size_t(k)] = set.add_axis(k, -m);
    box.high[std::size_t(k)] = set.add_axis(k, m);
  }
  return box;
}

int dominant_axis(const PlaneSet& set, PlaneId plane) {
  const auto& c = set.approx(plane);
  int best = -1;
  double best_low = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Interval& x = c[std::size_t(k)];
    const double low = x.inf() > 0.0 ? x.inf() : x.sup() < 0.0 ? -x.sup() : 0.0;
    if (low > best_low) best = k, best_low = low;
  }
  if (best >= 0) return best;
  const auto& e = set.exact(plane);
  best = 0;
  for (int k = 1; k < 3; ++k)
    if (Mpzf_abscmp(e[std::size_t(k)], e[std::size_t(best)]) > 0) best = k;
  return best;
}

PlanePolygon box_polygon(const PlaneSet& set, const BoxPlanes& box, PlaneRef plane) {
  const int k = dominant_axis(set, plane.id);
  const auto i = std::size_t((k + 1) % 3), j = std::size_t((k + 2) % 3);
  PlanePolygon poly{
      plane, {{box.high[i], 1}, {box.high[j], 1}, {box.low[i], -1}, {box.low[j], -1}}, {}};
  if (orient_normals(set, plane, poly.lines[0], poly.lines[1]) < 0)
    std::reverse(poly.lines.begin(), poly.lines.end());
  for (std::size_t m = 0; m < 4; ++m)
    poly.vertices.push_back(
        make_point(set, plane.id, poly.lines[m].id, poly.lines[(m + 1) % 4].id));
  return poly;
}

bool clip_polygon(const PlaneSet& set, PlanePolygon& poly, PlaneRef h) {
  const std::size_t n = poly.lines.size();
  boost::container::small_vector<int, 32> s(n);  // on the stack: most calls clip nothing
  bool any_out = false, any_in = false;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = side(set, h, poly.vertices[i]);
    any_out = any_out || s[i] > 0;
    any_in = any_in || s[i] < 0;
  }
  if (!any_out) return true;
  if (!any_in) return false;
  // The outside vertices form one run a..b (cyclic); edges a+1..b lie outside. Edge i runs on
  // lines[i] from vertex i-1 to vertex i.
  std::size_t a = 0;
  while (!(s[a] > 0 && s[(a + n - 1) % n] <= 0)) ++a;
  std::size_t b = a;
  while (s[(b + 1) % n] > 0) b = (b + 1) % n;
  const std::size_t before = (a + n - 1) % n, after = (b + 1) % n;
  // The clipped polygon is made in this thread's scratch polygon, which then takes the old one's
  // storage: clipping a section by a primitive's faces, the hot loop, allocates nothing.
  thread_local PlanePolygon scratch;
  PlanePolygon& out = scratch;
  out.plane = poly.plane;
  out.lines.clear();
  out.vertices.clear();
  // Walk from `after` round to `before`, keeping lines and vertices, then close over h.
  const bool drop_first = s[after] == 0, drop_last = s[before] == 0;
  std::size_t i = drop_first ? (after + 1) % n : after;  // the first line to keep
  if (!drop_first) {
    out.lines.push_back(poly.lines[after]);
    out.vertices.push_back(poly.vertices[after]);
    i = (after + 1) % n;
  }
  for (; i != a; i = (i + 1) % n) {
    out.lines.push_back(poly.lines[i]);
    out.vertices.push_back(poly.vertices[i]);
  }
  // Line a runs from vertex `before` (kept) out to vertex a: it ends on h.
  if (!drop_last) {
    out.lines.push_back(poly.lines[a]);
    out.vertices.push_back(make_point(set, poly.plane.id, poly.lines[a].id, h.id));
  }
  // h runs to where line `after` (or the next kept one) starts.
  out.lines.push_back(h);
  out.vertices.push_back(drop_first ? poly.vertices[after]
                                    : make_point(set, poly.plane.id, h.id, poly.lines[after].id));
  std::swap(poly, out);
  return poly.lines.size() >= 3;
}

// A convex piece of a slab (counter-clockwise doubles, strictly convex) between its bottom and
// top.
Primitive make_slab_piece(PlaneSet& set, const SlabFrame& s, const Polygon& piece) {
  const PlaneRef c0 = plane_at_z(set, s.bottom, -1), c1 = plane_at_z(set, s.top, 1);
  PlanePolygon base{{c0.id, -c0.sign}, {}, {}};
  const std::size_t n = piece.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 q = piece[(i + 1) % n];
    base.lines.push_back(plane_through(set, piece[i], q));
    base.vertices.push_back(make_point(q.x, q.y, s.bottom));
  }
  return make_prism(set, base, c0, c1);
}

// Per wall end: whether it is a slanted wall's square end at a point where another square end
// is too (walls drawn over one another, running on from each other at another thickness, or
// ending at one point at other angles without a join). Those ends take square_end_plane, so
// that all of them pass through the point. An end along an axis needs none: its rounded
// corners are exact. O(n log n) for n walls.
std::vector<std::array<bool, 2>> square_ends_at_shared_points(
    const std::vector<const WallFrame*>& walls) {
  std::vector<std::array<bool, 2>> shared(walls.size(), {false, false});
  // Square ends, by their point's bits.
  std::vector<std::tuple<std::uint64_t, std::uint64_t, std::size_t, int>> ends;
  for (std::size_t w = 0; w < walls.size(); ++w)
    for (const int end : {0, 1}) {
      if (walls[w]->capless[std::size_t(end)]) continue;
      const Point2 p = end == 0 ? walls[w]->from : walls[w]->to;
      ends.emplace_back(std::bit_cast<std::uint64_t>(p.x + 0.0),
                        std::bit_cast<std::uint64_t>(p.y + 0.0), w, end);
    }
  std::sort(ends.begin(), ends.end());
  for (std::size_t i = 0; i < ends.size();) {
    std::size_t j = i;
    while (j < ends.size() && std::get<0>(ends[j]) == std::get<0>(ends[i]) &&
           std::get<1>(ends[j]) == std::get<1>(ends[i]))
      ++j;
    for (std::size_t k = i; j - i > 1 && k < j; ++k) {
      const WallFrame& f = *walls[std::get<2>(ends[k])];
      if (f.dir.x != 0.0 && f.dir.y != 0.0)
        shared[std::get<2>(ends[k])][std::size_t(std::get<3>(ends[k]))] = true;
    }
    i = j;
  }
  return shared;
}

std::vector<Primitive> make_primitives(PlaneSet& set, const BoxPlanes& box,
                                       const std::vector<const WallFrame*>& walls,
                                       const std::vector<const SlabFrame*>& slabs) {
  const std::vector<std::array<bool, 2>> shared = square_ends_at_shared_points(walls);
  std::vector<WallPlanes> planes;
  planes.reserve(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w)
    planes.push_back(wall_planes(set, *walls[w], shared[w]));
  // Each wall's primitives in its own slot, and the first failure in wall order rethrown, so
  // neither depends on the threads.
  std::vector<std::vector<Primitive>> of_wall(walls.size());
  std::vector<std::exception_ptr> failure(walls.size());
  tbb::parallel_for(std::size_t{0}, walls.size(), [&](std::size_t w) {
    try {
      of_wall[w] = wall_primitives(set, box, *walls[w], planes[w], w);
    } catch (...) {
      failure[w] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : failure)
    if (e) std::rethrow_exception(e);
  std::vector<Primitive> out;
  for (std::vector<Primitive>& prims : of_wall)
    std::move(prims.begin(), prims.end(), std::back_inserter(out));
  for (std::size_t s = 0; s < slabs.size(); ++s)
    for (const Polygon& piece : slabs[s]->pieces) {
      out.push_back(make_slab_piece(set, *slabs[s], piece));
      out.back().slab = s;
    }
  return out;
}

void use_plane_groups(std::vector<Primitive>& primitives, const std::vector<PlaneRef>& groups) {
  auto remap_ref = [&](PlaneRef& r) { r = {groups[r.id].id, r.sign * groups[r.id].sign}; };
  auto remap_point = [&](XPoint& p) {
    if (!p.is_explicit())
      for (PlaneId& id : p.planes) id = groups[id].id;
  };
  tbb::parallel_for(std::size_t{0}, primitives.size(), [&](std::size_t k) {
    Primitive& p = primitives[k];
    for (XPoint& v : p.vertices) remap_point(v);
    for (PlanePolygon& f : p.faces) {
      remap_ref(f.plane);
      for (PlaneRef& l : f.lines) remap_ref(l);
      for (XPoint& v : f.vertices) remap_point(v);
    }
  });
}

}  // namespace roomcad::detail
