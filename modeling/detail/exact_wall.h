// Exact (CGAL Epeck) shapes of a wall and its holes, shared by the CGAL path and the
// analytic volume so that both compute the very same solid. Include only from the few
// translation units that use CGAL.
#pragma once

#include <array>
#include <bit>
#include <cstdint>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "modeling/detail/wall_frame.h"

namespace roomcad::detail {

using EK = CGAL::Epeck;

/// @return the wall's footprint (wall_footprint's doubles, exactly), counter-clockwise.
inline std::array<EK::Point_2, 4> exact_footprint(const WallFrame& f) {
  std::array<EK::Point_2, 4> q;
  for (std::size_t k = 0; k < 4; ++k) q[k] = EK::Point_2(f.footprint[k].x, f.footprint[k].y);
  return q;
}

/// @return the exact point of the side line a -> b where (p - from) . dir = u, with the
///         frame's rounded from and dir taken as exact values (so jambs are exactly square).
inline EK::Point_2 exact_side_point(const WallFrame& f, const Point2& a, const Point2& b, double u) {
  const EK::FT dx(f.dir.x), dy(f.dir.y);
  const EK::FT ax(a.x), ay(a.y), ex = EK::FT(b.x) - ax, ey = EK::FT(b.y) - ay;
  const EK::FT ua = (ax - f.from.x) * dx + (ay - f.from.y) * dy;
  const EK::FT t = (EK::FT(u) - ua) / (ex * dx + ey * dy);
  return EK::Point_2(ax + t * ex, ay + t * ey);
}

/// @return the footprint of a hole through the full thickness, counter-clockwise: its
///         corners lie exactly on the wall's side lines, at u0 and u1. A hole that reaches a
///         capped end (u0 = 0 or u1 = length: a notch) takes that end's cap corners instead:
///         the cap's rounded corners lie at u = 0 (or length) only within rounding, so the
///         point at u0 could fall a hair inside the wall and leave a sliver that no mesh in
///         doubles can hold (random-plan finding S4). Cost: O(1) exact operations.
inline std::array<EK::Point_2, 4> exact_hole_footprint(const WallFrame& f, const Hole& h) {
  const auto& q = f.footprint;
  const bool from_cap = !f.capless[0] && h.u0 <= 0.0, to_cap = !f.capless[1] && h.u1 >= f.length;
  auto exact = [](const Point2& p) { return EK::Point_2(p.x, p.y); };
  return {from_cap ? exact(q[0]) : exact_side_point(f, q[0], q[1], h.u0),
          to_cap ? exact(q[1]) : exact_side_point(f, q[0], q[1], h.u1),
          to_cap ? exact(q[2]) : exact_side_point(f, q[3], q[2], h.u1),
          from_cap ? exact(q[3]) : exact_side_point(f, q[3], q[2], h.u0)};
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
