#include "validation/detail/arrangement.h"

#include <cmath>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace roomcad::detail {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, std::size_t>;
using Arrangement = CGAL::Arrangement_2<Traits>;

Point2 to_point(const Kernel::Point_2& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

double ccb_area(Arrangement::Ccb_halfedge_const_circulator first) {
  double twice = 0;
  auto he = first;
  do {
    const Point2 a = to_point(he->source()->point());
    const Point2 b = to_point(he->target()->point());
    twice += a.x * b.y - a.y * b.x;
  } while (++he != first);
  return std::fabs(twice) / 2;
}

Face face_of(const Arrangement::Face_const_handle& f) {
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
  std::vector<Traits::Curve_2> curves;
  curves.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& [a, b] = segments[i];
    curves.emplace_back(Kernel::Segment_2({a.x, a.y}, {b.x, b.y}), i);
  }
  Arrangement arrangement;
  CGAL::insert(arrangement, curves.begin(), curves.end());
  std::vector<Face> faces;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f)
    if (!f->is_unbounded()) faces.push_back(face_of(f));
  return faces;
}

}  // namespace roomcad::detail
