// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/detail/shapes.h"

#include <cmath>
#include <limits>

namespace roomcad::detail {
namespace {

/// Exact corners reduced to enclosing intervals (for boxes when the fast path cannot decide).
Quad<exact::Approx> enclose(const Quad<exact::Exact>& q) {
  Quad<exact::Approx> out;
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = {exact::Approx(to_interval(q[i].x)), exact::Approx(to_interval(q[i].y))};
  return out;
}

}  // namespace

Box2 box_of(const Quad<exact::Approx>& q, std::size_t index) {
  Box2 box{q[0].x.inf(), q[0].y.inf(), q[0].x.sup(), q[0].y.sup(), index};
  for (const auto& p : q) {
    box.min_x = std::min(box.min_x, p.x.inf());
    box.min_y = std::min(box.min_y, p.y.inf());
    box.max_x = std::max(box.max_x, p.x.sup());
    box.max_y = std::max(box.max_y, p.y.sup());
  }
  return box;
}

Footprints::Footprints(const Plan& plan, const Joins& joins, const std::vector<bool>& usable)
    : plan_(plan), joins_(joins), approx_(plan.walls.size()) {
  for (std::size_t w = 0; w < plan.walls.size(); ++w) {
    if (!usable[w]) continue;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      try {
        approx_[w] = exact::wall_corners<exact::Approx>(plan, joins, w);
      } catch (const CGAL::Uncertain_conversion_exception&) {
        // A mitre whose walls are nearly parallel: the box comes from exact corners below.
      }
    }
    if (approx_[w]) {
      boxes_.push_back(box_of(*approx_[w], w));
    } else {
      const exact::Exact::Scope scope;
      boxes_.push_back(box_of(enclose(exact::wall_corners<exact::Exact>(plan, joins, w)), w));
    }
  }
}

std::array<Point2, 4> approximate_footprint(const Plan& plan, const Joins& joins, std::size_t w) {
  const Quad<double> q = exact::wall_corners<double>(plan, joins, w);
  return {Point2{q[0].x, q[0].y}, Point2{q[1].x, q[1].y}, Point2{q[2].x, q[2].y},
          Point2{q[3].x, q[3].y}};
}

std::pair<double, Point2> penetration(const std::array<Point2, 4>& p,
                                      const std::array<Point2, 4>& q) {
  double best = std::numeric_limits<double>::infinity();
  Point2 best_axis{1, 0};
  const auto project = [](Point2 axis, const std::array<Point2, 4>& s) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, mid = 0;
    for (const Point2& c : s) {
      const double t = axis.x * c.x + axis.y * c.y;
      lo = std::min(lo, t);
      hi = std::max(hi, t);
      mid += t / 4;
    }
    return std::array<double, 3>{lo, hi, mid};
  };
  for (const auto* shape : {&p, &q})
    for (std::size_t i = 0; i < 4; ++i) {
      const Point2 e{(*shape)[(i + 1) % 4].x - (*shape)[i].x,
                     (*shape)[(i + 1) % 4].y - (*shape)[i].y};
      const double len = std::hypot(e.x, e.y);
      if (len == 0) continue;
      Point2 axis{-e.y / len, e.x / len};
      const auto a = project(axis, p);
      const auto b = project(axis, q);
      const double overlap = std::min(a[1], b[1]) - std::max(a[0], b[0]);
      if (overlap >= best) continue;
      best = overlap;
      if (b[2] < a[2]) axis = {-axis.x, -axis.y};
      best_axis = axis;
    }
  return {std::max(best, 0.0), best_axis};
}

Box2 box_of_polygon(const Polygon& p, std::size_t index) {
  Box2 b{p[0].x, p[0].y, p[0].x, p[0].y, index};
  for (const Point2& c : p) {
    b.min_x = std::min(b.min_x, c.x), b.max_x = std::max(b.max_x, c.x);
    b.min_y = std::min(b.min_y, c.y), b.max_y = std::max(b.max_y, c.y);
  }
  return b;
}

}  // namespace roomcad::detail
