// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/arc_chords.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace roomcad {

int chord_count(double radius, double theta, double tolerance) {
  const double half = std::abs(theta) / 2;
  const auto sagitta = [&](int n) { return radius * (1 - std::cos(half / n)); };
  // The closed form, then corrected by a step either way for its rounding: the smallest n.
  const double ratio = std::clamp(1 - tolerance / radius, -1.0, 1.0);
  const double wanted = std::ceil(half / std::acos(ratio));
  int n = std::isfinite(wanted) && wanted < kMaxArcChords ? std::max(1, static_cast<int>(wanted))
                                                          : kMaxArcChords;
  while (n < kMaxArcChords && sagitta(n) > tolerance) ++n;
  while (n > 1 && sagitta(n - 1) <= tolerance) --n;
  return n;
}

double arc_radius(Point2 from, Point2 to, double extent_deg) {
  const double theta = std::abs(extent_deg) * std::numbers::pi / 180;
  return std::hypot(to.x - from.x, to.y - from.y) / (2 * std::sin(theta / 2));
}

std::vector<Point2> centre_polyline(const Wall& wall, double chord_tolerance) {
  if (!wall.arc_extent) return {wall.from, wall.to};
  const double theta = *wall.arc_extent * std::numbers::pi / 180;  // signed, ccw positive
  const Point2 a = wall.from, b = wall.to;
  const double chord = std::hypot(b.x - a.x, b.y - a.y);
  const double radius = arc_radius(a, b, *wall.arc_extent);
  // The centre lies on the chord's perpendicular bisector, to the left of a -> b for a
  // counter-clockwise arc, radius * cos(theta / 2) from the chord (behind it past 180 degrees).
  const Point2 left{-(b.y - a.y) / chord, (b.x - a.x) / chord};
  const double side = theta > 0 ? 1.0 : -1.0;
  const double to_centre = side * radius * std::cos(theta / 2);
  const Point2 centre{(a.x + b.x) / 2 + left.x * to_centre, (a.y + b.y) / 2 + left.y * to_centre};
  const double start = std::atan2(a.y - centre.y, a.x - centre.x);
  const int n = chord_count(radius, theta, chord_tolerance);
  std::vector<Point2> points{a};
  for (int k = 1; k < n; ++k) {
    const double angle = start + theta * k / n;
    points.push_back({centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)});
  }
  points.push_back(b);
  return points;
}

double chord_tolerance_of(const Site& site) {
  return site.chord_tolerance.value_or(kDefaultChordTolerance);
}

double polyline_length(const std::vector<Point2>& points) {
  double length = 0;
  for (std::size_t k = 1; k < points.size(); ++k)
    length += std::hypot(points[k].x - points[k - 1].x, points[k].y - points[k - 1].y);
  return length;
}

}  // namespace roomcad
