// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/detail/slab_edges.h"

#include <algorithm>
#include <cmath>

#include "modeling/broad_phase.h"

namespace roomcad::detail {
namespace {

// A side of a wall's footprint: the segment a -> b, and the step a quarter of the thickness
// from it toward the centre line.
struct Side {
  Point2 a, b, step;
};

// Side k of a footprint: 0 the right one (corners 0 -> 1), 1 the left one (corners 2 -> 3).
Side side_of(const WallFrame& f, int k) {
  const double s = (k == 0 ? 1.0 : -1.0) * f.half / 2.0;
  return k == 0 ? Side{f.footprint[0], f.footprint[1], {f.normal.x * s, f.normal.y * s}}
                : Side{f.footprint[2], f.footprint[3], {f.normal.x * s, f.normal.y * s}};
}

// Whether r lies within `tolerance` of the side's segment.
bool is_on(const Side& side, Point2 r, double tolerance) {
  const double dx = side.b.x - side.a.x, dy = side.b.y - side.a.y, length2 = dx * dx + dy * dy;
  if (length2 == 0.0) return false;
  const double t = std::clamp(((r.x - side.a.x) * dx + (r.y - side.a.y) * dy) / length2, 0.0, 1.0);
  return std::hypot(r.x - (side.a.x + t * dx), r.y - (side.a.y + t * dy)) <= tolerance;
}

void lay_ring(Polygon& ring, const std::vector<WallFrame>& walls, const std::vector<Box2>& boxes, double bottom,
              double top, double tolerance) {
  const std::size_t m = ring.size();
  std::vector<Box2> edges;
  for (std::size_t k = 0; k < m; ++k) {
    const Point2 p = ring[k], q = ring[(k + 1) % m];
    edges.push_back(grown_segment_box(p.x, p.y, q.x, q.y, tolerance));
    edges.back().index = k;
  }
  // Per corner, the sides it moves from (each once: two edges along one side move it once).
  std::vector<std::vector<std::pair<std::size_t, int>>> from(m);
  for (const auto& [e, i] : find_meeting_boxes(edges, boxes)) {
    const WallFrame& f = walls[i];
    if (f.base > bottom || std::min(f.top, f.top_end) < top) continue;  // not over the slab's height
    for (const int k : {0, 1}) {
      const Side side = side_of(f, k);
      if (!is_on(side, ring[e], tolerance) || !is_on(side, ring[(e + 1) % m], tolerance)) continue;
      for (const std::size_t v : {e, (e + 1) % m})
        if (std::find(from[v].begin(), from[v].end(), std::pair{i, k}) == from[v].end()) from[v].emplace_back(i, k);
    }
  }
  for (std::size_t v = 0; v < m; ++v)
    for (const auto& [i, k] : from[v]) {
      const Point2 step = side_of(walls[i], k).step;
      ring[v].x += step.x, ring[v].y += step.y;
    }
}

}  // namespace

void lay_slab_edges_into_walls(Slab& slab, const std::vector<WallFrame>& walls, double tolerance) {
  std::vector<Box2> boxes;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    Box2 b{INFINITY, INFINITY, -INFINITY, -INFINITY, i};
    for (const Point2& p : walls[i].footprint) {
      b.min_x = std::min(b.min_x, p.x - tolerance), b.max_x = std::max(b.max_x, p.x + tolerance);
      b.min_y = std::min(b.min_y, p.y - tolerance), b.max_y = std::max(b.max_y, p.y + tolerance);
    }
    boxes.push_back(b);
  }
  const double bottom = slab.top - slab.thickness;
  lay_ring(slab.outline, walls, boxes, bottom, slab.top, tolerance);
  for (Polygon& h : slab.holes) lay_ring(h, walls, boxes, bottom, slab.top, tolerance);
}

}  // namespace roomcad::detail
