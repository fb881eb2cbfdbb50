// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/arc_chords.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

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

bool is_buildable_arc(const Wall& w) {
  if (!w.arc_extent) return false;
  const double e = *w.arc_extent;
  return std::isfinite(e) && e != 0 && std::abs(e) < 360 && std::isfinite(w.from.x) &&
         std::isfinite(w.from.y) && std::isfinite(w.to.x) && std::isfinite(w.to.y) &&
         !(w.from == w.to);
}

namespace {

/// The chords of arc wall `w` (polyline `line`), each with its share of the (sloped) top.
std::vector<Wall> chords_of(const Wall& w, const std::vector<Point2>& line) {
  const double length = polyline_length(line);
  const double rise = w.height_at_end.value_or(w.height) - w.height;
  std::vector<Wall> chords;
  double along = 0;
  for (std::size_t k = 1; k < line.size(); ++k) {
    Wall chord = w;
    chord.arc_extent.reset();
    chord.from = line[k - 1];
    chord.to = line[k];
    const double next = along + std::hypot(line[k].x - line[k - 1].x, line[k].y - line[k - 1].y);
    chord.height = w.height + rise * along / length;
    if (w.height_at_end) chord.height_at_end = w.height + rise * next / length;
    chords.push_back(std::move(chord));
    along = next;
  }
  return chords;
}

/// The extent of an opening's outline: along the wall [u0, u1], up [v0, v1].
struct Extent {
  double u0, u1, v0, v1;
};

Extent extent_of(const Opening& o) {
  if (o.shape.empty()) return {o.offset, o.offset + o.width, o.sill, o.sill + o.height};
  double lo_x = 1, hi_x = 0, lo_y = 1, hi_y = 0;
  for (const Point2& p : o.shape) {
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  return {o.offset + lo_x * o.width, o.offset + hi_x * o.width, o.sill + lo_y * o.height,
          o.sill + hi_y * o.height};
}

}  // namespace

ChordPlan with_arcs_as_chords(const Plan& plan) {
  ChordPlan out;
  out.plan = plan;
  out.plan.walls.clear();
  out.plan.openings.clear();
  const double tolerance = chord_tolerance_of(plan.site);
  std::map<std::string, std::pair<std::size_t, std::vector<double>>, std::less<>> arcs;
  for (std::size_t w = 0; w < plan.walls.size(); ++w) {
    const Wall& wall = plan.walls[w];
    if (!is_buildable_arc(wall)) {
      out.plan.walls.push_back(wall);
      out.source_wall.push_back(w);
      continue;
    }
    auto& [first, starts] = arcs[wall.id];
    first = out.plan.walls.size();
    double along = 0;
    for (Wall& chord : chords_of(wall, centre_polyline(wall, tolerance))) {
      starts.push_back(along);
      along += std::hypot(chord.to.x - chord.from.x, chord.to.y - chord.from.y);
      out.plan.walls.push_back(std::move(chord));
      out.source_wall.push_back(w);
    }
  }
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    const Opening& o = plan.openings[i];
    const auto arc = arcs.find(o.wall);
    if (arc == arcs.end()) {
      out.plan.openings.push_back(o);
      out.source_opening.push_back(i);
      out.chord.push_back(kNoChord);
      continue;
    }
    const auto& [first, starts] = arc->second;
    const Extent e = extent_of(o);
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const Wall& chord = out.plan.walls[first + k];
      const double lo = starts[k];
      const double hi = lo + std::hypot(chord.to.x - chord.from.x, chord.to.y - chord.from.y);
      const double u0 = std::max(e.u0, lo), u1 = std::min(e.u1, hi);
      if (!(u0 < u1)) continue;
      Opening piece = o;
      piece.shape.clear();
      piece.offset = u0 - lo;
      piece.width = u1 - u0;
      piece.sill = e.v0;
      piece.height = e.v1 - e.v0;
      out.plan.openings.push_back(std::move(piece));
      out.source_opening.push_back(i);
      out.chord.push_back(first + k);
    }
  }
  return out;
}

}  // namespace roomcad
