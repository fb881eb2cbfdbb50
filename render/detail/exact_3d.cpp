// SPDX-License-Identifier: GPL-3.0-or-later
// The exact 3D predicates of drawings, with CGAL's filtered kernel.
#include "render/detail/exact_3d.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <cmath>

namespace roomcad::detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using E = CGAL::Exact_predicates_exact_constructions_kernel;
using P3 = K::Point_3;

/// The sine of the angle between two faces below which they count as one plane (rounding).
constexpr double kFlatSine = 1e-9;

P3 to_point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

}  // namespace

bool segment_meets_triangle(const glm::dvec3& a, const glm::dvec3& b, const Triangle3& t) {
  const P3 p0 = to_point(t[0]), p1 = to_point(t[1]), p2 = to_point(t[2]);
  const K::Segment_3 s(to_point(a), to_point(b));
  if (!CGAL::collinear(p0, p1, p2)) return CGAL::do_intersect(s, K::Triangle_3(p0, p1, p2));
  // Degenerate: the triangle is its longest side (or a point).
  const K::Segment_3 sides[] = {{p0, p1}, {p1, p2}, {p2, p0}};
  for (const K::Segment_3& side : sides) {
    if (side.is_degenerate() ? s.has_on(side.source()) : CGAL::do_intersect(s, side)) return true;
  }
  return false;
}

bool is_crease(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r0, const glm::dvec3& r1,
               bool same_facing) {
  const P3 a = to_point(p), b = to_point(q), c = to_point(r0), d = to_point(r1);
  if (CGAL::collinear(a, b, c) || CGAL::collinear(a, b, d)) return true;
  if (!same_facing) return true;
  if (CGAL::orientation(a, b, c, d) == CGAL::COPLANAR) return false;
  // Not exactly one plane: a plane the model's exact constructions rounded to doubles (a
  // turned wall's face split in several) bends by ~1e-15 rad, a real crease by far more. The
  // angle, not the distance, decides: a sliver face along a crease is near both planes.
  const glm::dvec3 e = q - p;
  const glm::dvec3 n = glm::cross(e, r0 - p);
  const double off_plane = std::abs(glm::dot(n, r1 - p)) / glm::length(n);
  const double off_line = glm::length(glm::cross(e, r1 - p)) / glm::length(e);
  return off_plane > kFlatSine * off_line;
}

bool is_edge_on(const Triangle3& t, const glm::dvec3& eye, const glm::dvec3& forward,
                bool perspective) {
  const P3 p0 = to_point(t[0]), p1 = to_point(t[1]), p2 = to_point(t[2]);
  if (CGAL::collinear(p0, p1, p2)) return true;
  if (perspective) return CGAL::orientation(p0, p1, p2, to_point(eye)) == CGAL::COPLANAR;
  // Differences of doubles round, so the edge vectors are built in the lazy exact kernel.
  const auto e = [](const glm::dvec3& v) { return E::Point_3(v.x, v.y, v.z); };
  const E::Point_3 e0 = e(t[0]);
  return CGAL::orientation(e(t[1]) - e0, e(t[2]) - e0,
                           E::Vector_3(forward.x, forward.y, forward.z)) == CGAL::COPLANAR;
}

bool is_collinear(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
  return CGAL::collinear(to_point(p), to_point(q), to_point(r));
}

}  // namespace roomcad::detail
