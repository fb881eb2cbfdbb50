// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/detail/arrangement.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace roomcad::detail {
namespace {

/// Crossings and overlaps are constructed exactly (Epeck). Pieces that only meet at their
/// ends would need predicates alone, but a plan with errors (a wall drawn back over another)
/// has overlapping pieces, and inserting those as non-intersecting broke CGAL's preconditions
/// (found by the sanitizer build, which keeps CGAL's checks on).
using ExactTraits = CGAL::Arr_consolidated_curve_data_traits_2<
    CGAL::Arr_segment_traits_2<CGAL::Exact_predicates_exact_constructions_kernel>, std::size_t>;

template <class P>
Point2 to_point(const P& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

template <class Ccb>
double ccb_area(Ccb first) {
  double twice = 0;
  auto he = first;
  do {
    const Point2 a = to_point(he->source()->point());
    const Point2 b = to_point(he->target()->point());
    twice += a.x * b.y - a.y * b.x;
  } while (++he != first);
  return std::fabs(twice) / 2;
}

template <class FaceHandle>
Face face_of(const FaceHandle& f) {
  Face face;
  auto he = f->outer_ccb();
  const auto first = he;
  do {
    // Walls drawn twice overlap (an error); the lowest index stands for the piece.
    face.boundary.push_back({to_point(he->source()->point()), to_point(he->target()->point()),
                             *std::min_element(he->curve().data().begin(), he->curve().data().end())});
  } while (++he != first);
  for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole)
    face.hole_area += ccb_area(*hole);
  return face;
}

}  // namespace

std::vector<Face> find_bounded_faces(const std::vector<std::pair<Point2, Point2>>& segments) {
  using Traits = ExactTraits;
  using Arrangement = CGAL::Arrangement_2<Traits>;
  using Kernel_point = typename Traits::Point_2;
  Arrangement arrangement;
  std::vector<typename Traits::Curve_2> curves;
  curves.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& [a, b] = segments[i];
    curves.emplace_back(typename Traits::Base_curve_2(Kernel_point(a.x, a.y), Kernel_point(b.x, b.y)), i);
  }
  CGAL::insert(arrangement, curves.begin(), curves.end());
  std::vector<Face> faces;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f)
    if (!f->is_unbounded()) faces.push_back(face_of(f));
  return faces;
}

}  // namespace roomcad::detail
