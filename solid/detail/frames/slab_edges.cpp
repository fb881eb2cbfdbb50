// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/frames/slab_edges.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/broad_phase.h"
#include "plan/signed_area.h"

namespace roomcad::detail {
namespace {

// An edge of a wall's footprint (a side or an end): the segment a -> b, and the step into the
// wall, a quarter of its thickness (of its length, for a wall shorter than thick).
struct Face {
  Point2 a, b, step;
};

// Edge k of the footprint (counter-clockwise: from-right, to-right, to-left, from-left), or
// nullopt where a mitre leaves it no length.
std::optional<Face> face_of(const WallFrame& f, int k) {
  const Point2 a = f.footprint[std::size_t(k)], b = f.footprint[std::size_t(k + 1) % 4];
  const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
  if (!(length > 0.0)) return std::nullopt;
  const double s = std::min(f.half, f.length / 2.0) / 2.0 / length;
  return Face{a, b, {-dy * s, dx * s}};  // the left of a counter-clockwise edge is inward
}

// Whether the segment p -> q runs along the face: both ends within `tolerance` of its line,
// and sharing more than `tolerance` of its length.
bool runs_along(const Face& face, Point2 p, Point2 q, double tolerance) {
  const double dx = face.b.x - face.a.x, dy = face.b.y - face.a.y, length = std::hypot(dx, dy);
  auto along = [&](Point2 r) { return ((r.x - face.a.x) * dx + (r.y - face.a.y) * dy) / length; };
  auto off = [&](Point2 r) {
    return std::abs((r.x - face.a.x) * dy - (r.y - face.a.y) * dx) / length;
  };
  if (off(p) > tolerance || off(q) > tolerance) return false;
  const double lo = std::max(0.0, std::min(along(p), along(q))),
               hi = std::min(length, std::max(along(p), along(q)));
  return hi - lo > tolerance;
}

// Whether two steps point the same way (walls' normals are unit; a few degrees apart is a
// different side).
bool is_same_direction(Point2 s, Point2 t) {
  const double cross = s.x * t.y - s.y * t.x, dot = s.x * t.x + s.y * t.y;
  return dot > 0.0 && std::abs(cross) <= 1e-9 * dot;
}

// Lays the ring's edges into the walls they run along. `inside` is +1 when the slab's area lies
// left of the ring's edges (an outline drawn counter-clockwise, a hole clockwise), -1 otherwise.
void lay_ring(Polygon& ring, int inside, const std::vector<WallFrame>& walls,
              const std::vector<Box2>& boxes, double bottom, double top, double tolerance) {
  const std::size_t m = ring.size();
  std::vector<Box2> edges;
  for (std::size_t k = 0; k < m; ++k) {
    const Point2 p = ring[k], q = ring[(k + 1) % m];
    edges.push_back(grown_segment_box(p.x, p.y, q.x, q.y, tolerance));
    edges.back().index = k;
  }
  // Per corner, the steps it takes: one per direction, so that two edges along one face, or
  // a wall under the slab and one over it on the same line, move it once.
  std::vector<std::vector<Point2>> steps(m);
  for (const auto& [e, i] : find_meeting_boxes(edges, boxes)) {
    const WallFrame& f = walls[i];
    if (f.base > top || std::max(f.top, f.top_end) < bottom) continue;  // apart in height
    const bool covers = f.base <= bottom && std::min(f.top, f.top_end) >= top;
    const Point2 p = ring[e], q = ring[(e + 1) % m];
    for (int k = 0; k < 4; ++k) {
      const auto face = face_of(f, k);
      if (!face || !runs_along(*face, p, q, tolerance)) continue;
      // Where the wall only meets part of the slab's height (stands on it, hangs under it),
      // only a slab beside the wall is laid under it: one under the wall is left as drawn.
      const bool beside = inside * ((q.x - p.x) * face->step.y - (q.y - p.y) * face->step.x) < 0.0;
      if (!covers && !beside) continue;
      for (const std::size_t v : {e, (e + 1) % m})
        if (std::none_of(steps[v].begin(), steps[v].end(),
                         [&](Point2 s) { return is_same_direction(s, face->step); }))
          steps[v].push_back(face->step);
    }
  }
  for (std::size_t v = 0; v < m; ++v)
    for (const Point2 step : steps[v]) ring[v].x += step.x, ring[v].y += step.y;
}

}  // namespace

std::vector<Box2> wall_boxes_for_laying(const std::vector<WallFrame>& walls, double tolerance) {
  std::vector<Box2> boxes;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const auto& c = walls[i].footprint;
    if (!(signed_area(Polygon(c.begin(), c.end())) > 0.0))
      continue;  // a bow tie: no inside to lay into
    boxes.push_back(footprint_box(walls[i], tolerance));
    boxes.back().index = i;
  }
  return boxes;
}

void lay_slab_edges_into_walls(Slab& slab, const std::vector<WallFrame>& walls,
                               const std::vector<Box2>& boxes, double tolerance) {
  const double bottom = slab.top - slab.thickness;
  const int outline_turn = signed_area(slab.outline) > 0.0 ? 1 : -1;
  lay_ring(slab.outline, outline_turn, walls, boxes, bottom, slab.top, tolerance);
  for (Polygon& h : slab.holes)
    lay_ring(h, signed_area(h) > 0.0 ? -1 : 1, walls, boxes, bottom, slab.top, tolerance);
}

}  // namespace roomcad::detail
