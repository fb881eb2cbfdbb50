// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/detail/resolved_plan.h"

#include <algorithm>
#include <cmath>

#include "modeling/arc_chords.h"
#include "modeling/plan_levels.h"

namespace roomcad::detail {
namespace {

/// The chords of arc wall `w`, each with its share of the wall's (sloped) top.
std::vector<Wall> chords_of(const Wall& w, const std::vector<Point2>& line, double length) {
  std::vector<Wall> chords;
  const double rise = w.height_at_end.value_or(w.height) - w.height;
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

/// The u (along the wall) and v (up) extent of an opening's outline.
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

double highest_height(const Wall& w) { return std::max(w.height, w.height_at_end.value_or(w.height)); }

ResolvedPlan resolve_plan(const Plan& plan, const Usable& usable) {
  ResolvedPlan r;
  const Plan absolute = with_absolute_heights(plan);
  r.plan = absolute;
  r.plan.walls.clear();
  r.plan.openings.clear();
  r.usable.site = usable.site;
  r.usable.slabs = usable.slabs;
  // A level that is missing (an unknown_reference) or has a bad elevation (an invalid_value)
  // leaves its objects unplaced: nothing more is said about them.
  const auto placed_on = [&plan](const std::string& level) {
    return level.empty() || (find_level(plan, level) && std::isfinite(level_elevation(plan, level)));
  };
  for (std::size_t i = 0; i < absolute.slabs.size(); ++i)
    r.usable.slabs[i] = r.usable.slabs[i] && placed_on(plan.slabs[i].level) &&
                        std::isfinite(absolute.slabs[i].top);
  const double tolerance = chord_tolerance_of(plan.site);
  std::vector<std::size_t> first(plan.walls.size());
  std::vector<std::vector<double>> starts(plan.walls.size());  // chord starts along the arc
  for (std::size_t w = 0; w < plan.walls.size(); ++w) {
    const Wall& wall = absolute.walls[w];
    first[w] = r.plan.walls.size();
    const bool placed =
        usable.walls[w] && placed_on(plan.walls[w].level) && std::isfinite(wall.base);
    const bool arc = placed && wall.arc_extent.has_value();
    std::vector<Wall> pieces{wall};
    if (arc) {
      const std::vector<Point2> line = centre_polyline(wall, tolerance);
      pieces = chords_of(wall, line, polyline_length(line));
      double along = 0;
      for (const Wall& c : pieces) {
        starts[w].push_back(along);
        along += std::hypot(c.to.x - c.from.x, c.to.y - c.from.y);
      }
    }
    for (Wall& p : pieces) {
      r.plan.walls.push_back(std::move(p));
      r.usable.walls.push_back(placed);
      r.source_wall.push_back(w);
      r.is_chord.push_back(arc);
    }
  }
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    if (!usable.host[i] || !r.usable.walls[first[*usable.host[i]]]) {
      r.plan.openings.push_back(plan.openings[i]);
      r.usable.host.push_back(std::nullopt);
      continue;
    }
    const std::size_t w = *usable.host[i];
    if (starts[w].empty()) {
      r.plan.openings.push_back(plan.openings[i]);
      r.usable.host.push_back(first[w]);
      continue;
    }
    // An opening of an arc wall: a piece on each chord its outline's span crosses, as the
    // rectangle of that span (the outline's extent) on the chord.
    const Extent e = extent_of(plan.openings[i]);
    for (std::size_t k = 0; k < starts[w].size(); ++k) {
      const Wall& chord = r.plan.walls[first[w] + k];
      const double lo = starts[w][k];
      const double hi = lo + std::hypot(chord.to.x - chord.from.x, chord.to.y - chord.from.y);
      const double u0 = std::max(e.u0, lo), u1 = std::min(e.u1, hi);
      if (!(u0 < u1)) continue;
      Opening piece = plan.openings[i];
      piece.shape.clear();
      piece.offset = u0 - lo;
      piece.width = u1 - u0;
      piece.sill = e.v0;
      piece.height = e.v1 - e.v0;
      r.plan.openings.push_back(std::move(piece));
      r.usable.host.push_back(first[w] + k);
    }
  }
  return r;
}

}  // namespace roomcad::detail
