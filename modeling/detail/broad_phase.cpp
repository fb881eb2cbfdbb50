// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's box intersection behind the plain interface of modeling/broad_phase.h.
#include "modeling/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <CGAL/box_intersection_d.h>

namespace roomcad {
namespace {

using CgalBox = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

// The info is the caller's index shifted left once, its low bit telling which sequence a box
// came from, so that pairs of two sequences come out in (left, right) order whatever order
// the callback receives them in.
std::vector<CgalBox> to_cgal(const std::vector<Box2>& boxes, std::size_t side) {
  std::vector<CgalBox> out;
  out.reserve(boxes.size());
  for (const Box2& b : boxes) {
    double lo[2] = {b.min_x, b.min_y};
    double hi[2] = {b.max_x, b.max_y};
    out.emplace_back(lo, hi, (b.index << 1) | side);
  }
  return out;
}

void sort_unique(IndexPairs& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

}  // namespace

IndexPairs find_meeting_boxes(const std::vector<Box2>& boxes) {
  std::vector<CgalBox> cgal = to_cgal(boxes, 0);
  IndexPairs pairs;
  CGAL::box_self_intersection_d(cgal.begin(), cgal.end(), [&](const CgalBox& a, const CgalBox& b) {
    const std::size_t i = a.info() >> 1;
    const std::size_t j = b.info() >> 1;
    pairs.emplace_back(std::min(i, j), std::max(i, j));
  });
  sort_unique(pairs);
  return pairs;
}

IndexPairs find_meeting_boxes(const std::vector<Box2>& left, const std::vector<Box2>& right) {
  std::vector<CgalBox> a = to_cgal(left, 0);
  std::vector<CgalBox> b = to_cgal(right, 1);
  IndexPairs pairs;
  CGAL::box_intersection_d(a.begin(), a.end(), b.begin(), b.end(),
                           [&](const CgalBox& x, const CgalBox& y) {
                             const bool x_left = (x.info() & 1) == 0;
                             pairs.emplace_back((x_left ? x : y).info() >> 1,
                                                (x_left ? y : x).info() >> 1);
                           });
  sort_unique(pairs);
  return pairs;
}

Box2 grown_segment_box(double ax, double ay, double bx, double by, double margin) {
  // One step outward after each rounded sum keeps the box conservative.
  const double inf = std::numeric_limits<double>::infinity();
  return Box2{std::nextafter(std::min(ax, bx) - margin, -inf),
              std::nextafter(std::min(ay, by) - margin, -inf),
              std::nextafter(std::max(ax, bx) + margin, inf),
              std::nextafter(std::max(ay, by) + margin, inf), 0};
}

}  // namespace roomcad
