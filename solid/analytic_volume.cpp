// SPDX-License-Identifier: GPL-3.0-or-later
// analytic_wall_volume: the solid's volume from the plan alone, independent of the builders'
// plane machinery (convex_pieces, exact_planes). The solid is (union U of walls and slabs)
// minus (union of holes); its volume is vol(U) - sum over clusters C of holes of
// vol(U near C n C), clusters being holes whose boxes overlap (so the clusters' parts are
// disjoint), and vol(U) = vol(flat ones) + sum over sloped walls s_i of
// vol(s_i - flat ones near it - s_j near it, j < i).
//
// Over z, the cross-section area A(z) of a polyhedron is a polynomial of degree <= 2 between
// the heights of its vertices (every vertex of the section moves linearly in z and the
// section's combinatorics do not change). Every vertex of the solid is where three face planes
// of its primitives meet: the events are the heights of every primitive's own corners, and of
// the points where a tilted plane (a sloped top, an edge of a shaped hole) meets two other
// planes inside all three faces' boxes. Between events Simpson's rule with exact (Epeck)
// areas at both ends and the midpoint is exact; where nothing moves one evaluation does.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

#include "geometry/exact_polygon_set.h"
#include "solid/analytic_volume.h"
#include "solid/detail/frames/buildable_plan.h"
#include "solid/detail/frames/exact_wall.h"
#include "solid/detail/frames/slab_frames.h"

namespace roomcad {
namespace {

using detail::EK;
using FT = EK::FT;
using Point = EK::Point_2;
using Polygon = detail::ExactPolygon;
using PolygonWithHoles = detail::ExactPolygonWithHoles;
using PolygonSet = detail::ExactPolygonSet;

struct Box {
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  void add(double x, double y, double z) {
    const std::array<double, 3> p{x, y, z};
    for (std::size_t k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  void add_xy(const Point& p, double z0, double z1) {
    add(CGAL::to_double(p.x()), CGAL::to_double(p.y()), z0);
    add(CGAL::to_double(p.x()), CGAL::to_double(p.y()), z1);
  }
  void add(const Box& b) {
    for (std::size_t k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], b.lo[k]), hi[k] = std::max(hi[k], b.hi[k]);
  }
  // Widened so that the doubles' rounding never drops what touches.
  Box widened() const {
    Box b = *this;
    for (std::size_t k = 0; k < 3; ++k) {
      b.lo[k] -= 1e-7 * (1.0 + std::abs(lo[k]));
      b.hi[k] += 1e-7 * (1.0 + std::abs(hi[k]));
    }
    return b;
  }
  bool overlaps(const Box& b) const {
    for (std::size_t k = 0; k < 3; ++k)
      if (hi[k] < b.lo[k] || b.hi[k] < lo[k]) return false;
    return true;
  }
};

// A face plane a x + b y + c z + d = 0 that is not horizontal, and a box holding its face.
struct Face {
  FT a, b, c, d;
  bool tilted = false;  // neither vertical nor horizontal
  Box box;
};

Face vertical_face(const Point& p, const Point& q, double z0, double z1) {
  Face f;
  f.a = q.y() - p.y(), f.b = p.x() - q.x(), f.c = 0, f.d = -(f.a * p.x() + f.b * p.y());
  f.box.add_xy(p, z0, z1), f.box.add_xy(q, z0, z1);
  f.box = f.box.widened();
  return f;
}

// One wall, slab or hole, with its cross-section as a function of z.
struct Prim {
  enum class Kind { prism, sloped, shaped, slab } kind = Kind::prism;
  FT zmin, zmax;  // present for z strictly between
  Box box;
  std::vector<Face> faces;              // its faces that are not horizontal
  std::vector<FT> heights;              // the heights of its corners
  std::vector<Point> outline;           // prism, sloped: the footprint (convex, counter-clockwise)
  std::vector<PolygonWithHoles> parts;  // slab: its outline minus its holes
  // sloped: the top is where k (p - from) . e = (z - top) l2
  FT fx, fy, ex, ey, k, top, l2, top_min;
  // shaped: u = (p - from) . dir on the side lines a0 -> b0 (right) and a1 -> b1 (left)
  std::array<Point, 2> side_a, side_b;
  std::array<FT, 2> side_ua, side_den;
  FT u0, width, z0, height;
  std::vector<std::array<FT, 2>> shape;  // (s, t) corners
  bool present(const FT& m) const { return zmin < m && m < zmax; }
};

FT top_at(const Prim& p, const Point& q) {
  return p.top + p.k * ((q.x() - p.fx) * p.ex + (q.y() - p.fy) * p.ey) / p.l2;
}

Point side_point(const Prim& p, int side, const FT& u) {
  const Point& a = p.side_a[std::size_t(side)];
  const Point& b = p.side_b[std::size_t(side)];
  const FT t = (u - p.side_ua[std::size_t(side)]) / p.side_den[std::size_t(side)];
  return {a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y())};
}

std::vector<Point> strip_quad(const Prim& p, const FT& ua, const FT& ub) {
  return detail::convex_part(
      {side_point(p, 0, ua), side_point(p, 0, ub), side_point(p, 1, ub), side_point(p, 1, ua)});
}

void add_polygon(std::vector<Point> q, std::vector<Polygon>& out) {
  std::vector<Point> clean;
  for (const Point& x : q)
    if (clean.empty() || x != clean.back()) clean.push_back(x);
  while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
  if (clean.size() < 3) return;
  Polygon poly(clean.begin(), clean.end());
  if (poly.area() > 0) out.push_back(std::move(poly));
}

// Whether the section changes with z while m is inside this interval.
bool moves(const Prim& p, const FT& m) {
  if (p.kind == Prim::Kind::sloped) return p.top_min < m;
  if (p.kind != Prim::Kind::shaped) return false;
  const FT t = (m - p.z0) / p.height;
  for (std::size_t i = 0; i < p.shape.size(); ++i) {
    const auto& a = p.shape[i];
    const auto& b = p.shape[(i + 1) % p.shape.size()];
    if (a[0] != b[0] && ((a[1] < t && t < b[1]) || (b[1] < t && t < a[1]))) return true;
  }
  return false;
}

// The section at z of a primitive present over the interval around m: the limit from inside
// the interval (its combinatorics are those at m, its vertices at z).
void add_section(const Prim& p, const FT& m, const FT& z, std::vector<Polygon>& polys,
                 std::vector<PolygonWithHoles>& with_holes) {
  switch (p.kind) {
    case Prim::Kind::prism: add_polygon(p.outline, polys); return;
    case Prim::Kind::slab:
      with_holes.insert(with_holes.end(), p.parts.begin(), p.parts.end());
      return;
    case Prim::Kind::sloped: {
      if (z <= p.top_min) return add_polygon(p.outline, polys);
      // Keep g >= 0, g(q) = k (q - from) . e - (z - top) l2 (Sutherland-Hodgman).
      const FT c = (z - p.top) * p.l2;
      auto g = [&](const Point& q) {
        return p.k * ((q.x() - p.fx) * p.ex + (q.y() - p.fy) * p.ey) - c;
      };
      std::vector<Point> out;
      const std::size_t n = p.outline.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Point& a = p.outline[i];
        const Point& b = p.outline[(i + 1) % n];
        const FT ga = g(a), gb = g(b);
        if (!CGAL::is_negative(ga)) out.push_back(a);
        if ((CGAL::is_positive(ga) && CGAL::is_negative(gb)) ||
            (CGAL::is_negative(ga) && CGAL::is_positive(gb))) {
          const FT t = ga / (ga - gb);
          out.emplace_back(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
        }
      }
      return add_polygon(std::move(out), polys);
    }
    case Prim::Kind::shaped: {
      const FT tm = (m - p.z0) / p.height, tz = (z - p.z0) / p.height;
      std::vector<std::pair<FT, FT>> cuts;  // s at m, s at z
      for (std::size_t i = 0; i < p.shape.size(); ++i) {
        const auto& a = p.shape[i];
        const auto& b = p.shape[(i + 1) % p.shape.size()];
        if (!((a[1] < tm && tm < b[1]) || (b[1] < tm && tm < a[1]))) continue;
        const FT slope = (b[0] - a[0]) / (b[1] - a[1]);
        cuts.emplace_back(a[0] + slope * (tm - a[1]), a[0] + slope * (tz - a[1]));
      }
      std::sort(cuts.begin(), cuts.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      for (std::size_t i = 0; i + 1 < cuts.size(); i += 2) {
        const FT ua = p.u0 + cuts[i].second * p.width, ub = p.u0 + cuts[i + 1].second * p.width;
        if (ua < ub) add_polygon(strip_quad(p, ua, ub), polys);
      }
      return;
    }
  }
}

PolygonSet union_at(const std::vector<const Prim*>& prims, const FT& m, const FT& z) {
  std::vector<Polygon> polys;
  std::vector<PolygonWithHoles> with_holes;
  for (const Prim* p : prims) add_section(*p, m, z, polys, with_holes);
  PolygonSet set;
  set.join(polys, with_holes);
  return set;
}

FT area_of(const PolygonSet& set) {
  FT area = 0;
  for (const auto& p : set.polygons_with_holes()) {
    area += p.outer_boundary().area();
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h)
      area += h->area();  // holes are clockwise
  }
  return area;
}

// What a group measures: the union of its solids, its part in the union of the others
// (holes), or its part outside them.
enum class Mode { unite, cut, minus };

// The area at z of the union of `solids` (with the union of `others` per `mode`).
FT area_at(const std::vector<const Prim*>& solids, const std::vector<const Prim*>& others,
           Mode mode, const FT& m, const FT& z) {
  PolygonSet set = union_at(solids, m, z);
  if (mode == Mode::cut && !set.is_empty()) set.intersection(union_at(others, m, z));
  if (mode == Mode::minus && !set.is_empty() && !others.empty())
    set.difference(union_at(others, m, z));
  return area_of(set);
}

FT det3(const std::array<FT, 3>& r0, const std::array<FT, 3>& r1, const std::array<FT, 3>& r2) {
  return r0[0] * (r1[1] * r2[2] - r1[2] * r2[1]) - r0[1] * (r1[0] * r2[2] - r1[2] * r2[0]) +
         r0[2] * (r1[0] * r2[1] - r1[1] * r2[0]);
}

// The height of the point where three planes meet, if they meet in one point that lies in
// all three faces' boxes (checked in doubles, with margin; an ill-conditioned triple is kept).
void add_triple_event(const Face& p, const Face& q, const Face& r, std::vector<FT>& events) {
  const std::array<const Face*, 3> f{&p, &q, &r};
  std::array<std::array<double, 4>, 3> a{};
  for (std::size_t i = 0; i < 3; ++i)
    a[i] = {CGAL::to_double(f[i]->a), CGAL::to_double(f[i]->b), CGAL::to_double(f[i]->c),
            CGAL::to_double(f[i]->d)};
  auto d3 = [](const std::array<double, 3>& x, const std::array<double, 3>& y,
               const std::array<double, 3>& z) {
    return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) +
           x[2] * (y[0] * z[1] - y[1] * z[0]);
  };
  std::array<std::array<double, 3>, 3> n{};
  double scale = 1.0;
  for (std::size_t i = 0; i < 3; ++i) {
    n[i] = {a[i][0], a[i][1], a[i][2]};
    scale *= std::hypot(a[i][0], a[i][1], a[i][2]);
  }
  const double det = d3(n[0], n[1], n[2]);
  if (std::abs(det) > 1e-9 * scale) {
    std::array<double, 3> x{};
    for (std::size_t k = 0; k < 3; ++k) {
      auto m = n;
      for (std::size_t i = 0; i < 3; ++i) m[i][k] = -a[i][3];
      x[k] = d3(m[0], m[1], m[2]) / det;
    }
    for (const Face* face : f)
      for (std::size_t k = 0; k < 3; ++k) {
        const double slack = 1e-6 * (1.0 + std::abs(x[k]));
        if (!(x[k] >= face->box.lo[k] - slack && x[k] <= face->box.hi[k] + slack)) return;
      }
  }
  const std::array<FT, 3> e0{p.a, p.b, p.c}, e1{q.a, q.b, q.c}, e2{r.a, r.b, r.c};
  const FT det_exact = det3(e0, e1, e2);
  if (CGAL::is_zero(det_exact)) return;
  events.push_back(det3({p.a, p.b, -p.d}, {q.a, q.b, -q.d}, {r.a, r.b, -r.d}) / det_exact);
}

// The volume of the union of `solids` (with the union of `holes` per `mode`) between zlo and
// zhi.
FT group_volume(const std::vector<const Prim*>& solids, const std::vector<const Prim*>& holes,
                Mode mode, const FT& zlo, const FT& zhi) {
  std::vector<FT> events{zlo, zhi};
  std::vector<const Face*> faces;
  for (const auto* list : {&solids, &holes})
    for (const Prim* p : *list) {
      events.insert(events.end(), p->heights.begin(), p->heights.end());
      for (const Face& f : p->faces) faces.push_back(&f);
    }
  // Triples with a tilted plane: each counted once, at its first tilted plane.
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (!faces[i]->tilted) continue;
    std::vector<std::size_t> near;
    for (std::size_t j = 0; j < faces.size(); ++j)
      if (j != i && !(faces[j]->tilted && j < i) && faces[i]->box.overlaps(faces[j]->box))
        near.push_back(j);
    for (std::size_t x = 0; x < near.size(); ++x)
      for (std::size_t y = x + 1; y < near.size(); ++y)
        if (faces[near[x]]->box.overlaps(faces[near[y]]->box))
          add_triple_event(*faces[i], *faces[near[x]], *faces[near[y]], events);
  }
  events.erase(
      std::remove_if(events.begin(), events.end(), [&](const FT& z) { return z < zlo || zhi < z; }),
      events.end());
  std::sort(events.begin(), events.end());
  events.erase(std::unique(events.begin(), events.end()), events.end());
  FT volume = 0;
  std::vector<const Prim*> s, h;
  for (std::size_t k = 0; k + 1 < events.size(); ++k) {
    const FT& a = events[k];
    const FT& b = events[k + 1];
    const FT m = (a + b) / 2;
    s.clear(), h.clear();
    for (const Prim* p : solids)
      if (p->present(m)) s.push_back(p);
    if (s.empty()) continue;
    if (mode != Mode::unite) {
      for (const Prim* p : holes)
        if (p->present(m)) h.push_back(p);
      if (h.empty() && mode == Mode::cut) continue;
    }
    const bool moving =
        std::any_of(s.begin(), s.end(), [&](const Prim* p) { return moves(*p, m); }) ||
        std::any_of(h.begin(), h.end(), [&](const Prim* p) { return moves(*p, m); });
    if (!moving) volume += area_at(s, h, mode, m, m) * (b - a);
    else
      volume +=
          (area_at(s, h, mode, m, a) + 4 * area_at(s, h, mode, m, m) + area_at(s, h, mode, m, b)) *
          (b - a) / 6;
  }
  return volume;
}

Prim wall_prim(const detail::WallFrame& f) {
  Prim p;
  p.outline = detail::exact_footprint(f);
  p.zmin = f.base;
  if (!detail::is_sloped(f)) {
    p.kind = Prim::Kind::prism;
    p.zmax = f.top;
    p.heights = {p.zmin, p.zmax};
    for (std::size_t i = 0; i < p.outline.size(); ++i)
      p.faces.push_back(
          vertical_face(p.outline[i], p.outline[(i + 1) % p.outline.size()], f.base, f.top));
  } else {
    p.kind = Prim::Kind::sloped;
    p.fx = f.from.x, p.fy = f.from.y, p.ex = FT(f.to.x) - f.from.x, p.ey = FT(f.to.y) - f.from.y;
    p.k = FT(f.heights[1]) - FT(f.heights[0]), p.top = f.top, p.l2 = p.ex * p.ex + p.ey * p.ey;
    p.heights = {p.zmin};
    bool first = true;
    for (const Point& q : p.outline) {
      const FT z = top_at(p, q);
      p.heights.push_back(z);
      if (first || p.zmax < z) p.zmax = z;
      if (first || z < p.top_min) p.top_min = z;
      first = false;
    }
    if (first) p.zmax = p.top_min = p.zmin;
    const double zlo = CGAL::to_double(p.top_min), zhi = CGAL::to_double(p.zmax);
    for (std::size_t i = 0; i < p.outline.size(); ++i)
      p.faces.push_back(
          vertical_face(p.outline[i], p.outline[(i + 1) % p.outline.size()], f.base, zhi));
    Face top;  // k (x - fx) ex + k (y - fy) ey - (z - top) l2 = 0
    top.a = p.k * p.ex, top.b = p.k * p.ey, top.c = -p.l2,
    top.d = p.top * p.l2 - p.k * (p.fx * p.ex + p.fy * p.ey);
    top.tilted = true;
    for (const Point& q : p.outline) top.box.add_xy(q, zlo, zhi);
    top.box = top.box.widened();
    p.faces.push_back(top);
  }
  for (const Point& q : p.outline) p.box.add_xy(q, f.base, CGAL::to_double(p.zmax));
  p.box = p.box.widened();
  return p;
}

Prim rect_hole_prim(const detail::WallFrame& f, const detail::Hole& h) {
  Prim p;
  p.kind = Prim::Kind::prism;
  p.outline = detail::exact_hole_footprint(f, h);
  p.zmin = h.z0, p.zmax = h.z1;
  p.heights = {p.zmin, p.zmax};
  for (std::size_t i = 0; i < p.outline.size(); ++i)
    p.faces.push_back(
        vertical_face(p.outline[i], p.outline[(i + 1) % p.outline.size()], h.z0, h.z1));
  for (const Point& q : p.outline) p.box.add_xy(q, h.z0, h.z1);
  p.box = p.box.widened();
  return p;
}

// A shaped hole: the shape mapped by u = u0 + s width, z = z0 + t height, between the wall's
// side lines (footprint corners 0 -> 1 and 3 -> 2).
Prim shaped_hole_prim(const detail::WallFrame& f, const detail::Hole& h) {
  Prim p;
  p.kind = Prim::Kind::shaped;
  p.u0 = h.u0, p.width = h.width, p.z0 = h.z0, p.height = h.height;
  const FT dx(f.dir.x), dy(f.dir.y), origin = FT(f.from.x) * dx + FT(f.from.y) * dy;
  const std::array<std::array<std::size_t, 2>, 2> corner{{{0, 1}, {3, 2}}};
  for (std::size_t s = 0; s < 2; ++s) {
    const Point2 a = f.footprint[corner[s][0]], b = f.footprint[corner[s][1]];
    p.side_a[s] = Point(a.x, a.y), p.side_b[s] = Point(b.x, b.y);
    p.side_ua[s] = (FT(a.x) - f.from.x) * dx + (FT(a.y) - f.from.y) * dy;
    p.side_den[s] = (FT(b.x) - a.x) * dx + (FT(b.y) - a.y) * dy;
  }
  bool first = true;
  for (const Point2& c : h.shape) {
    p.shape.push_back({FT(c.x), FT(c.y)});
    const FT z = p.z0 + FT(c.y) * p.height;
    p.heights.push_back(z);
    if (first || z < p.zmin) p.zmin = z;
    if (first || p.zmax < z) p.zmax = z;
    first = false;
  }
  const FT ub = p.u0 + p.width;
  const std::vector<Point> strip = strip_quad(p, p.u0, ub);
  const double zlo = CGAL::to_double(p.zmin), zhi = CGAL::to_double(p.zmax);
  for (const Point& q : strip) p.box.add_xy(q, zlo, zhi);
  p.box = p.box.widened();
  for (std::size_t s = 0; s < 2; ++s) {
    Face side = vertical_face(side_point(p, int(s), p.u0), side_point(p, int(s), ub), zlo, zhi);
    p.faces.push_back(side);
  }
  for (std::size_t i = 0; i < p.shape.size(); ++i) {
    const auto& a = p.shape[i];
    const auto& b = p.shape[(i + 1) % p.shape.size()];
    if (a[1] == b[1]) continue;  // horizontal: its height is an event
    const FT ua = p.u0 + a[0] * p.width, ubb = p.u0 + b[0] * p.width;
    const FT za = p.z0 + a[1] * p.height, zb = p.z0 + b[1] * p.height;
    const FT du = ubb - ua, dz = zb - za;
    Face e;  // dz (p . dir - origin - ua) - du (z - za) = 0
    e.a = dz * dx, e.b = dz * dy, e.c = -du, e.d = du * za - dz * (origin + ua);
    e.tilted = a[0] != b[0];
    const double za_d = CGAL::to_double(za), zb_d = CGAL::to_double(zb);
    const double lo = std::min(za_d, zb_d), hi = std::max(za_d, zb_d);
    for (const FT& u : {ua, ubb})
      for (int s = 0; s < 2; ++s) e.box.add_xy(side_point(p, s, u), lo, hi);
    e.box = e.box.widened();
    p.faces.push_back(e);
  }
  return p;
}

// A slab as the build takes it (slab_frames.h: its edges along walls laid into them, its bottom
// rounded once); its area from the outline and holes, not from the build's convex pieces.
Prim slab_prim(const detail::SlabFrame& slab) {
  Prim p;
  p.kind = Prim::Kind::slab;
  p.zmax = slab.top;
  p.zmin = slab.bottom;
  p.heights = {p.zmin, p.zmax};
  auto polygon = [](const roomcad::Polygon& q) {
    std::vector<Point> points;
    for (const Point2& c : q)
      if (points.empty() || points.back() != Point(c.x, c.y)) points.emplace_back(c.x, c.y);
    while (points.size() > 1 && points.front() == points.back()) points.pop_back();
    Polygon poly(points.begin(), points.end());
    if (poly.size() >= 3 && poly.is_clockwise_oriented()) poly.reverse_orientation();
    return poly;
  };
  const Polygon outline = polygon(slab.outline);
  if (outline.size() < 3 || !(outline.area() > 0)) return p;
  PolygonSet set(outline);
  for (const roomcad::Polygon& hole : slab.holes) {
    const Polygon h = polygon(hole);
    if (h.size() >= 3 && h.area() > 0) set.difference(PolygonSet(h));
  }
  p.parts = set.polygons_with_holes();
  const double zlo = slab.bottom, zhi = slab.top;
  auto add_faces = [&](const Polygon& poly) {
    for (auto e = poly.edges_begin(); e != poly.edges_end(); ++e)
      p.faces.push_back(vertical_face(e->source(), e->target(), zlo, zhi));
  };
  for (const PolygonWithHoles& part : p.parts) {
    add_faces(part.outer_boundary());
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h) add_faces(*h);
    for (const Point& q : part.outer_boundary()) p.box.add_xy(q, zlo, zhi);
  }
  p.box = p.box.widened();
  return p;
}

}  // namespace

double analytic_wall_volume(const Plan& input) {
  const detail::BuildablePlan buildable = detail::make_buildable(input);
  const Plan& plan = buildable.plan;
  const std::vector<detail::WallFrame> frames =
      detail::make_wall_frames(plan, find_joins(plan), buildable.through_mitre);
  std::vector<Prim> solids, holes;
  for (const detail::WallFrame& f : frames) {
    Prim w = wall_prim(f);
    if (w.outline.size() >= 3 && w.zmin < w.zmax) solids.push_back(std::move(w));
    for (const detail::Hole& h : f.holes) {
      Prim p = h.shape.size() >= 3 ? shaped_hole_prim(f, h) : rect_hole_prim(f, h);
      if (p.zmin < p.zmax && (p.kind == Prim::Kind::shaped || p.outline.size() >= 3))
        holes.push_back(std::move(p));
    }
  }
  for (const detail::SlabFrame& s : detail::make_slab_frames(plan, frames)) {
    Prim p = slab_prim(s);
    if (!p.parts.empty() && p.zmin < p.zmax) solids.push_back(std::move(p));
  }
  if (solids.empty()) return 0.0;
  // The union of the walls and slabs: that of the flat ones (their sections do not move, one
  // area per interval between their heights), then each sloped wall's part outside the flat
  // ones and the sloped walls before it near it (small groups: an arc's many chords do not
  // all meet at each of their corners' heights).
  std::vector<const Prim*> flat;
  for (const Prim& p : solids)
    if (p.kind != Prim::Kind::sloped) flat.push_back(&p);
  FT volume = 0;
  if (!flat.empty()) {
    FT zlo = flat[0]->zmin, zhi = flat[0]->zmax;
    for (const Prim* p : flat) zlo = CGAL::min(zlo, p->zmin), zhi = CGAL::max(zhi, p->zmax);
    volume = group_volume(flat, {}, Mode::unite, zlo, zhi);
  }
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const Prim& p = solids[i];
    if (p.kind != Prim::Kind::sloped) continue;
    std::vector<const Prim*> near;
    for (std::size_t j = 0; j < solids.size(); ++j)
      if ((solids[j].kind != Prim::Kind::sloped || j < i) && solids[j].box.overlaps(p.box))
        near.push_back(&solids[j]);
    volume += group_volume({&p}, near, Mode::minus, p.zmin, p.zmax);
  }
  // Holes in clusters of overlapping boxes: each cluster's part of the solid apart.
  std::vector<std::size_t> root(holes.size());
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (std::size_t i = 0; i < holes.size(); ++i)
    for (std::size_t j = i + 1; j < holes.size(); ++j)
      if (holes[i].box.overlaps(holes[j].box)) root[find(i)] = find(j);
  std::vector<std::vector<const Prim*>> clusters(holes.size());
  for (std::size_t i = 0; i < holes.size(); ++i) clusters[find(i)].push_back(&holes[i]);
  for (const auto& cluster : clusters) {
    if (cluster.empty()) continue;
    Box box;
    FT lo = cluster[0]->zmin, hi = cluster[0]->zmax;
    for (const Prim* h : cluster) {
      box.add(h->box);
      lo = CGAL::min(lo, h->zmin), hi = CGAL::max(hi, h->zmax);
    }
    std::vector<const Prim*> near;
    for (const Prim& s : solids)
      if (s.box.overlaps(box)) near.push_back(&s);
    if (!near.empty()) volume -= group_volume(near, cluster, Mode::cut, lo, hi);
  }
  return detail::round_to_nearest(volume);
}

}  // namespace roomcad
