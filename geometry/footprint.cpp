// SPDX-License-Identifier: GPL-3.0-or-later
// wall_footprint: mitred corners constructed exactly, then rounded to nearest: at once where
// they are doubles, from 128-bit intervals where those tell the nearest double, else in
// exact::Radical.
#include <cmath>
#include <limits>
#include <optional>

#include "exact/precise_interval.h"
#include "geometry/exact_wall_lines.h"
#include "geometry/joins.h"

namespace roomcad {
namespace {

/// Corners that interval arithmetic pins to single doubles (axis-aligned walls, mostly) are
/// exact already; @return them, or nothing when any interval has width.
std::optional<std::array<Point2, 4>> find_exact_corners_fast(const Plan& plan, const Joins& joins,
                                                             std::size_t wall) {
  CGAL::Protect_FPU_rounding<true> upward;
  try {
    const auto corners = exact::wall_corners<exact::Approx>(plan, joins, wall);
    std::array<Point2, 4> out;
    for (std::size_t i = 0; i < 4; ++i) {
      if (!corners[i].x.is_point() || !corners[i].y.is_point()) return std::nullopt;
      out[i] = {corners[i].x.inf(), corners[i].y.inf()};
    }
    return out;
  } catch (const CGAL::Uncertain_conversion_exception&) {
    return std::nullopt;
  }
}

/// Corners held by 128-bit intervals (a skewed wall's: the square roots of the walls' squared
/// lengths) whose nearest doubles the intervals tell; @return them, or nothing when a corner
/// lies too near a midpoint between doubles (a tie) or a parallel mitre cannot be told.
std::optional<std::array<Point2, 4>> find_corners_precisely(const Plan& plan, const Joins& joins,
                                                            std::size_t wall) {
  try {
    const auto corners = exact::wall_corners<exact::PreciseInterval>(plan, joins, wall);
    std::array<Point2, 4> out;
    for (std::size_t i = 0; i < 4; ++i) {
      const std::optional<double> x = corners[i].x.nearest_double(),
                                  y = corners[i].y.nearest_double();
      if (!x || !y) return std::nullopt;
      out[i] = {*x, *y};
    }
    return out;
  } catch (const exact::UndecidedComparison&) {
    return std::nullopt;
  }
}

// a + b rounded to the nearest double, ties to the lower one (as exact::round_to_nearest
// rounds: a mitre's shared corner must come out the same from either wall, whichever way
// each wall's corners are found). IEEE addition rounds ties to even: the tie is undone.
double add_ties_down(double a, double b) {
  const double s = a + b, bb = s - a;
  const double e = (a - (s - bb)) + (b - bb);  // a + b = s + e exactly (TwoSum)
  if (e >= 0.0) return s;                      // s is the lower neighbour already (or exact)
  const double below = std::nextafter(s, -INFINITY);
  return below - s == 2.0 * e ? below : s;  // a tie (the exact sum halfway): take the lower
}

// The side line of an axis-aligned wall: x[axis] = (the end point's coordinate) + offset,
// offset +-half the thickness (exact: a double's sign flipped, halved).
struct AxisSide {
  int axis = 0;     // the coordinate the line fixes: 1 for a wall along x, 0 along y
  double at = 0.0;  // the end point's coordinate on that axis
  double offset = 0.0;
  double value() const { return add_ties_down(at, offset); }  // the exact sum, rounded
};

// Wall w along an axis (-1 if it is not): 0 along x, 1 along y.
int axis_of(const Wall& w) {
  if (w.from.y == w.to.y && w.from.x != w.to.x) return 0;
  if (w.from.x == w.to.x && w.from.y != w.to.y) return 1;
  return -1;
}

// The side (+1 left of from -> to, -1 right) of an axis-aligned wall through its end.
AxisSide axis_side(const Wall& w, WallEnd end, int side) {
  const Point2& p = end == WallEnd::from ? w.from : w.to;
  const double half = w.thickness / 2.0;
  if (axis_of(w) == 0)
    return {1, p.y, side * (w.to.x > w.from.x ? half : -half)};  // left normal (0, sx)
  return {0, p.x, side * (w.to.y > w.from.y ? -half : half)};    // left normal (-sy, 0)
}

/// An axis-aligned wall mitred only to axis-aligned walls has corners whose coordinates are
/// each an end point's coordinate or the sum of one and +-half a thickness: the nearest
/// doubles are those sums rounded (what wall_corners<Radical> rounded by round_to_nearest
/// gives, bit for bit, at a thousandth of its cost). @return them, or nothing otherwise.
std::optional<std::array<Point2, 4>> find_axis_aligned_corners(const Plan& plan, const Joins& joins,
                                                               std::size_t wall) {
  const Wall& w = plan.walls[wall];
  const int axis = axis_of(w);
  if (axis < 0 || !(w.thickness > 0.0) || !std::isfinite(w.thickness)) return std::nullopt;
  auto corner = [&](WallEnd end, int side) -> std::optional<Point2> {
    const AxisSide mine = axis_side(w, end, side);
    const Point2& p = end == WallEnd::from ? w.from : w.to;
    double along = axis == 0 ? p.x : p.y;
    if (const auto partner = joins.mitre[wall][static_cast<int>(end)]) {
      const Wall& v = plan.walls[*partner];
      const int other_axis = axis_of(v);
      if (other_axis < 0) return std::nullopt;
      if (other_axis != axis) {  // perpendicular: the corner is where the two side lines cross
        const WallEnd other_end = joins.mitre[*partner][0] == wall ? WallEnd::from : WallEnd::to;
        const int other_side =
            side * (end == WallEnd::from ? -1 : 1) * (other_end == WallEnd::to ? -1 : 1);
        along = axis_side(v, other_end, other_side).value();
      }  // parallel: a square end, as wall_corners makes it
    }
    return axis == 0 ? Point2{along, mine.value()} : Point2{mine.value(), along};
  };
  std::array<Point2, 4> out;
  const std::array<std::pair<WallEnd, int>, 4> order{
      {{WallEnd::from, -1}, {WallEnd::to, -1}, {WallEnd::to, 1}, {WallEnd::from, 1}}};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto c = corner(order[i].first, order[i].second);
    if (!c) return std::nullopt;
    out[i] = *c;
  }
  return out;
}

}  // namespace

std::array<Point2, 4> wall_footprint(const Plan& plan, const Joins& joins, std::size_t wall) {
  if (const auto axis_aligned = find_axis_aligned_corners(plan, joins, wall)) return *axis_aligned;
  if (const auto fast = find_exact_corners_fast(plan, joins, wall)) return *fast;
  if (const auto precise = find_corners_precisely(plan, joins, wall)) return *precise;
  const exact::Exact::Scope scope;
  const std::array<exact::Pt<exact::Exact>, 4> corners =
      exact::wall_corners<exact::Exact>(plan, joins, wall);
  std::array<Point2, 4> out;
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = {exact::round_to_nearest(corners[i].x), exact::round_to_nearest(corners[i].y)};
  return out;
}

}  // namespace roomcad
