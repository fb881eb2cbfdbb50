// SPDX-License-Identifier: GPL-3.0-or-later
// Exact (CGAL Epeck) shapes of a wall and its holes, shared by the CGAL path and the
// analytic volume so that both compute the very same solid. Include only from the few
// translation units that use CGAL.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

using EK = CGAL::Epeck;

/// @return the convex polygon on the left of the lines through consecutive corners of `quad`
///         (counter-clockwise): the quad itself when it is strictly convex; otherwise (a
///         "bow-tie", whose ends cross) the part between its ends, possibly a triangle, or
///         nothing when that has no area. Cost: O(1) predicates; exact constructions only
///         when the quad is not convex. convex_pieces.h builds the same set, plane by plane.
inline std::vector<EK::Point_2> convex_part(const std::array<EK::Point_2, 4>& quad) {
  bool convex = true;
  for (std::size_t i = 0; i < 4 && convex; ++i)
    convex = CGAL::orientation(quad[i], quad[(i + 1) % 4], quad[(i + 2) % 4]) == CGAL::LEFT_TURN;
  if (convex) return {quad.begin(), quad.end()};
  // Clip a box around the quad by each side's left half-plane (Sutherland-Hodgman).
  EK::FT m = 1;
  for (const EK::Point_2& p : quad) m = CGAL::max(m, CGAL::max(CGAL::abs(p.x()), CGAL::abs(p.y())));
  m = 4 * m + 1;
  std::vector<EK::Point_2> poly{{-m, -m}, {m, -m}, {m, m}, {-m, m}};
  for (std::size_t i = 0; i < 4 && !poly.empty(); ++i) {
    if (quad[i] == quad[(i + 1) % 4]) continue;
    const EK::Line_2 line(quad[i], quad[(i + 1) % 4]);
    std::vector<EK::Point_2> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const EK::Point_2& a = poly[k];
      const EK::Point_2& b = poly[(k + 1) % poly.size()];
      const auto sa = line.oriented_side(a), sb = line.oriented_side(b);
      if (sa != CGAL::ON_NEGATIVE_SIDE) out.push_back(a);
      if ((sa == CGAL::ON_POSITIVE_SIDE && sb == CGAL::ON_NEGATIVE_SIDE) ||
          (sa == CGAL::ON_NEGATIVE_SIDE && sb == CGAL::ON_POSITIVE_SIDE)) {
        const auto x = CGAL::intersection(line, EK::Line_2(a, b));
        out.push_back(boost::get<EK::Point_2>(*x));
      }
    }
    poly.clear();
    for (const EK::Point_2& p : out)
      if (poly.empty() || p != poly.back()) poly.push_back(p);
    while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
  }
  if (poly.size() < 3 || CGAL::polygon_area_2(poly.begin(), poly.end(), EK()) <= 0) return {};
  return poly;
}

/// @return the wall's footprint: the convex part of the quad of wall_footprint's doubles.
inline std::vector<EK::Point_2> exact_footprint(const WallFrame& f) {
  std::array<EK::Point_2, 4> q;
  for (std::size_t k = 0; k < 4; ++k) q[k] = EK::Point_2(f.footprint[k].x, f.footprint[k].y);
  return convex_part(q);
}

/// @return the exact point of the side line a -> b where (p - from) . dir = u, with the
///         frame's rounded from and dir taken as exact values (so jambs are exactly square).
inline EK::Point_2 exact_side_point(const WallFrame& f, const Point2& a, const Point2& b,
                                    double u) {
  const EK::FT dx(f.dir.x), dy(f.dir.y);
  const EK::FT ax(a.x), ay(a.y), ex = EK::FT(b.x) - ax, ey = EK::FT(b.y) - ay;
  const EK::FT ua = (ax - f.from.x) * dx + (ay - f.from.y) * dy;
  const EK::FT t = (EK::FT(u) - ua) / (ex * dx + ey * dy);
  return EK::Point_2(ax + t * ex, ay + t * ey);
}

/// @return the footprint of a hole through the full thickness, counter-clockwise: its
///         corners lie exactly on the wall's side lines, at u0 and u1. A hole that reaches a
///         capped end (u0 = 0 or u1 = length: a notch), or runs on through a mitre there, takes
///         that end's corners instead (hole_reaches_end_line):
///         the cap's rounded corners lie at u = 0 (or length) only within rounding, so the
///         point at u0 could fall a hair inside the wall and leave a sliver that no mesh in
///         doubles can hold (random-plan finding S4). Cost: O(1) exact operations.
inline std::vector<EK::Point_2> exact_hole_footprint(const WallFrame& f, const Hole& h) {
  const auto& q = f.footprint;
  const bool from_cap = hole_reaches_end_line(f, h, 0), to_cap = hole_reaches_end_line(f, h, 1);
  auto exact = [](const Point2& p) { return EK::Point_2(p.x, p.y); };
  return convex_part({from_cap ? exact(q[0]) : exact_side_point(f, q[0], q[1], h.u0),
                      to_cap ? exact(q[1]) : exact_side_point(f, q[0], q[1], h.u1),
                      to_cap ? exact(q[2]) : exact_side_point(f, q[3], q[2], h.u1),
                      from_cap ? exact(q[3]) : exact_side_point(f, q[3], q[2], h.u0)});
}

/// @return x rounded to the nearest double (ties to even), so exact points are written as
///         the closest doubles. Cost: one exact evaluation.
inline double round_to_nearest(const EK::FT& x) {
  const auto& e = x.exact();
  using ET = std::decay_t<decltype(e)>;
  const std::pair<double, double> iv = CGAL::to_interval(e);
  if (iv.first == iv.second) return iv.first;
  const ET mid = (ET(iv.first) + ET(iv.second)) / 2;
  if (e < mid) return iv.first;
  if (mid < e) return iv.second;
  return (std::bit_cast<std::uint64_t>(iv.first) & 1u) == 0 ? iv.first : iv.second;
}

}  // namespace roomcad::detail
