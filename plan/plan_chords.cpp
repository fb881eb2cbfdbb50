// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan_chords.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "plan/arc_chords.h"

namespace roomcad {

double polyline_length(const std::vector<Point2>& points) {
  double length = 0;
  for (std::size_t k = 1; k < points.size(); ++k)
    length += std::hypot(points[k].x - points[k - 1].x, points[k].y - points[k - 1].y);
  return length;
}

bool is_buildable_arc(const Wall& w, double chord_tolerance) {
  if (!w.arc_extent) return false;
  const double e = *w.arc_extent;
  const double span = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
  return std::isfinite(e) && e != 0 && std::abs(e) < 360 && std::isfinite(span) && span > 0 &&
         chord_tolerance > 0 && chord_count(span, e, chord_tolerance) <= kMaxChords;
}

std::vector<Wall> chord_walls(const Wall& w, const std::vector<Point2>& line) {
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
    // The ends of the polyline keep the wall's own heights (no rounding through the ratio).
    chord.height = k == 1 ? w.height : w.height + rise * along / length;
    if (w.height_at_end)
      chord.height_at_end =
          k + 1 == line.size() ? *w.height_at_end : w.height + rise * next / length;
    chords.push_back(std::move(chord));
    along = next;
  }
  return chords;
}

namespace {

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
    if (!is_buildable_arc(wall, tolerance)) {
      out.plan.walls.push_back(wall);
      out.source_wall.push_back(w);
      continue;
    }
    auto& [first, starts] = arcs[wall.id];
    first = out.plan.walls.size();
    double along = 0;
    for (Wall& chord : chord_walls(wall, chord_polyline(wall, tolerance))) {
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
