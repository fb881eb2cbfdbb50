// SPDX-License-Identifier: GPL-3.0-or-later
// Exact segment predicates: CGAL's filtered Epick predicates and exact::decide.
#include "geometry/segment_predicates.h"

#include <algorithm>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "geometry/exact_wall_lines.h"

namespace roomcad {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_2 to_cgal(Point2 p) { return {p.x, p.y}; }

}  // namespace

bool segments_meet(Point2 a, Point2 b, Point2 c, Point2 d) {
  return CGAL::do_intersect(K::Segment_2(to_cgal(a), to_cgal(b)),
                            K::Segment_2(to_cgal(c), to_cgal(d)));
}

bool is_near_segment(Point2 p, Point2 a, Point2 b, double tol) {
  return exact::decide([&](auto tag) -> bool {
    using NT = decltype(tag);
    const exact::Pt<NT> pa = exact::to_pt<NT>(p) - exact::to_pt<NT>(a);
    const exact::Pt<NT> ba = exact::to_pt<NT>(b) - exact::to_pt<NT>(a);
    const NT t2 = NT(tol) * NT(tol);
    const NT length2 = exact::dot(ba, ba);
    // The distance to the line (|cross| / |b - a|, squared and multiplied out) bounds the
    // distance to the segment from below: far from the line decides without asking where
    // along it p lies (which is uncertain when p is abreast of an end).
    const NT c = exact::cross(ba, pa);
    if (!(c * c <= t2 * length2)) return false;
    // Before the start or past the end the nearest point is an end point; between, the
    // line's distance is the segment's. "Past the end" is measured from b (dot(p - b, b - a),
    // which is dot(pa, ba) - length2): at p == b it is an exact 0, which double intervals
    // decide, where the difference of two rounded equal products would straddle it.
    if (exact::dot(pa, ba) <= NT(0)) return exact::dot(pa, pa) <= t2;
    const exact::Pt<NT> pb = exact::to_pt<NT>(p) - exact::to_pt<NT>(b);
    if (exact::dot(pb, ba) >= NT(0)) return exact::dot(pb, pb) <= t2;
    return true;
  });
}

bool share_heights(const Wall& a, const Wall& b) {
  return exact::decide([&](auto tag) -> bool {
    using NT = decltype(tag);
    return NT(a.base) < NT(b.base) + NT(b.height) && NT(b.base) < NT(a.base) + NT(a.height);
  });
}

bool is_near_point(Point2 p, Point2 q, double tol) {
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    const exact::Pt<NT> d = exact::to_pt<NT>(p) - exact::to_pt<NT>(q);
    return exact::dot(d, d) <= NT(tol) * NT(tol);
  });
}

bool overlap_collinearly(Point2 a, Point2 b, Point2 c, Point2 d) {
  if (!CGAL::collinear(to_cgal(a), to_cgal(b), to_cgal(c)) ||
      !CGAL::collinear(to_cgal(a), to_cgal(b), to_cgal(d)))
    return false;
  // On one line, compare along an axis the line is not perpendicular to.
  const bool use_x = a.x != b.x;
  const auto coord = [use_x](Point2 p) { return use_x ? p.x : p.y; };
  const double lo = std::max(std::min(coord(a), coord(b)), std::min(coord(c), coord(d)));
  const double hi = std::min(std::max(coord(a), coord(b)), std::max(coord(c), coord(d)));
  return lo < hi;
}

bool are_parallel(Point2 a, Point2 b, Point2 c, Point2 d) {
  return exact::decide([&](auto tag) {
    using NT = decltype(tag);
    const exact::Pt<NT> u = exact::to_pt<NT>(b) - exact::to_pt<NT>(a);
    const exact::Pt<NT> v = exact::to_pt<NT>(d) - exact::to_pt<NT>(c);
    return exact::cross(u, v) == NT(0);
  });
}

}  // namespace roomcad
