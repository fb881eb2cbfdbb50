// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's box intersection behind the plain interface of modeling/broad_phase.h.
#include "modeling/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <CGAL/box_intersection_d.h>

namespace roomcad {
namespace {

template <int Dimensions>
using CgalBox = CGAL::Box_intersection_d::Box_with_info_d<double, Dimensions, std::size_t>;

// The info is the caller's index shifted left once, its low bit telling which sequence a box
// came from, so that pairs of two sequences come out in (left, right) order whatever order
// the callback receives them in.
CgalBox<2> to_cgal(const Box2& b, std::size_t side) {
  double lo[2] = {b.min_x, b.min_y};
  double hi[2] = {b.max_x, b.max_y};
  return {lo, hi, (b.index << 1) | side};
}

CgalBox<3> to_cgal(const SpaceBox& b, std::size_t side) {
  double lo[3] = {b.plan.min_x, b.plan.min_y, b.min_z};
  double hi[3] = {b.plan.max_x, b.plan.max_y, b.max_z};
  return {lo, hi, (b.plan.index << 1) | side};
}

template <class Box>
auto to_cgal(const std::vector<Box>& boxes, std::size_t side) {
  std::vector<decltype(to_cgal(Box{}, side))> out;
  out.reserve(boxes.size());
  for (const Box& b : boxes) out.push_back(to_cgal(b, side));
  return out;
}

void sort_unique(IndexPairs& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

template <class Box>
IndexPairs meeting_pairs(const std::vector<Box>& boxes) {
  auto cgal = to_cgal(boxes, 0);
  IndexPairs pairs;
  CGAL::box_self_intersection_d(cgal.begin(), cgal.end(), [&](const auto& a, const auto& b) {
    const std::size_t i = a.info() >> 1;
    const std::size_t j = b.info() >> 1;
    pairs.emplace_back(std::min(i, j), std::max(i, j));
  });
  sort_unique(pairs);
  return pairs;
}

template <class Box>
IndexPairs meeting_pairs(const std::vector<Box>& left, const std::vector<Box>& right) {
  auto a = to_cgal(left, 0);
  auto b = to_cgal(right, 1);
  IndexPairs pairs;
  CGAL::box_intersection_d(
      a.begin(), a.end(), b.begin(), b.end(), [&](const auto& x, const auto& y) {
        const bool x_left = (x.info() & 1) == 0;
        pairs.emplace_back((x_left ? x : y).info() >> 1, (x_left ? y : x).info() >> 1);
      });
  sort_unique(pairs);
  return pairs;
}

}  // namespace

IndexPairs find_meeting_boxes(const std::vector<Box2>& boxes) { return meeting_pairs(boxes); }

IndexPairs find_meeting_boxes(const std::vector<Box2>& left, const std::vector<Box2>& right) {
  return meeting_pairs(left, right);
}

IndexPairs find_meeting_boxes(const std::vector<SpaceBox>& boxes) { return meeting_pairs(boxes); }

IndexPairs find_meeting_boxes(const std::vector<SpaceBox>& left,
                              const std::vector<SpaceBox>& right) {
  return meeting_pairs(left, right);
}

Box2 grown_segment_box(double ax, double ay, double bx, double by, double margin) {
  // One step outward after each rounded sum keeps the box conservative.
  const double inf = std::numeric_limits<double>::infinity();
  return Box2{std::nextafter(std::min(ax, bx) - margin, -inf),
              std::nextafter(std::min(ay, by) - margin, -inf),
              std::nextafter(std::max(ax, bx) + margin, inf),
              std::nextafter(std::max(ay, by) + margin, inf), 0};
}

SpaceBox space_box(const Box2& plan, double z0, double z1) {
  const double most = std::numeric_limits<double>::max();
  if (!std::isfinite(z0) || !std::isfinite(z1)) return {plan, -most, most};
  const double inf = std::numeric_limits<double>::infinity();
  return {plan, std::max(std::nextafter(std::min(z0, z1), -inf), -most),
          std::min(std::nextafter(std::max(z0, z1), inf), most)};
}

}  // namespace roomcad
