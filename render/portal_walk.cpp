// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/portal_walk.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/scene_cells.h"

namespace roomcad {
namespace {

/// A rectangle of normalised device coordinates; empty when a low side passes its high.
struct ScreenRect {
  double x0 = 1.0, y0 = 1.0, x1 = -1.0, y1 = -1.0;
  [[nodiscard]] bool empty() const { return x0 > x1 || y0 > y1; }
  friend bool operator==(const ScreenRect&, const ScreenRect&) = default;
};

constexpr ScreenRect kWholeScreen{-1.0, -1.0, 1.0, 1.0};

ScreenRect united(const ScreenRect& a, const ScreenRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

ScreenRect intersected(const ScreenRect& a, const ScreenRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

/// The part of `within` where the convex hull of the points (world) can be seen: the box of
/// their projections, or all of `within` when some lie behind the eye and some before it.
template <class Points>
ScreenRect seen_through(const Points& world, const glm::dvec3& origin, const glm::dmat4& vp,
                        const ScreenRect& within) {
  ScreenRect r;
  bool behind = false, before = false;
  for (const Vec3& p : world) {
    const glm::dvec4 c = vp * glm::dvec4(p.x - origin.x, p.y - origin.y, p.z - origin.z, 1.0);
    if (c.w <= 1e-9) {
      behind = true;
      continue;
    }
    before = true;
    r = united(r, {c.x / c.w, c.y / c.w, c.x / c.w, c.y / c.w});
  }
  if (!before) return {};
  return intersected(behind ? within : r, within);
}

/// Whether a box (scene frame) lies wholly outside the view cone through `rect`: all its
/// corners outside one of the cone's planes.
bool is_outside(const Box3& b, const glm::dmat4& vp, const ScreenRect& rect) {
  unsigned all = 0x1f;
  for (int i = 0; i < 8 && all != 0; ++i) {
    const glm::dvec4 c =
        vp * glm::dvec4((i & 1) ? b.high[0] : b.low[0], (i & 2) ? b.high[1] : b.low[1],
                        (i & 4) ? b.high[2] : b.low[2], 1.0);
    unsigned out = 0;
    if (c.x < rect.x0 * c.w) out |= 1;
    if (c.x > rect.x1 * c.w) out |= 2;
    if (c.y < rect.y0 * c.w) out |= 4;
    if (c.y > rect.y1 * c.w) out |= 8;
    if (c.w <= 0.0) out |= 16;
    all &= out;
  }
  return all != 0;
}

double distance_to_segment(const Vec3& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/// Whether p lies inside the polygon, farther than `clearance` from its edges.
bool is_well_inside(const Polygon& polygon, const Vec3& p, double clearance) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if (distance_to_segment(p, a, b) <= clearance) return false;
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

bool is_well_outside(const Polygon& polygon, const Vec3& p, double clearance) {
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    if (distance_to_segment(p, polygon[i], polygon[j]) <= clearance) return false;
  return !is_well_inside(polygon, p, 0.0);
}

/// The cell the eye stands in with `clearance` to spare, or -1.
std::int64_t find_eye_cell(const Cells& cells, const Vec3& eye, double clearance) {
  for (std::size_t k = 0; k < cells.cells.size(); ++k) {
    const Cell& c = cells.cells[k];
    if (eye.z <= c.eye_low + clearance || eye.z >= c.eye_high - clearance) continue;
    if (eye.x <= c.bounds.low[0] || eye.x >= c.bounds.high[0] || eye.y <= c.bounds.low[1] ||
        eye.y >= c.bounds.high[1])
      continue;
    if (!is_well_inside(c.outline, eye, clearance)) continue;
    if (std::all_of(c.islands.begin(), c.islands.end(),
                    [&](const Polygon& island) { return is_well_outside(island, eye, clearance); }))
      return static_cast<std::int64_t>(k);
  }
  return -1;
}

/// A cell's outline at height z, as points.
std::vector<Vec3> outline_at(const Cell& c, double z) {
  std::vector<Vec3> out;
  out.reserve(c.outline.size());
  for (const Point2& p : c.outline) out.push_back({p.x, p.y, z});
  return out;
}

/// A view onto what no cell holds: a screen rectangle and the half-space beyond the portal it
/// passes (scene frame: what has a point p with dot(beyond, (p, 1)) > 0).
struct OpenView {
  ScreenRect rect;
  glm::dvec4 beyond{0.0, 0.0, 0.0, 1.0};
};

/// Views onto what no cell holds, one per plane: past this many, they merge into one rectangle
/// beyond no plane (every cluster is tested against each).
constexpr std::size_t kMostOpenViews = 32;

void add_open_view(std::vector<OpenView>& open, const OpenView& view) {
  for (OpenView& v : open)
    if (v.beyond == view.beyond) return void(v.rect = united(v.rect, view.rect));
  open.push_back(view);
  if (open.size() <= kMostOpenViews) return;
  ScreenRect all;
  for (const OpenView& v : open) all = united(all, v.rect);
  open = {{all, glm::dvec4(0.0, 0.0, 0.0, 1.0)}};
}

/// The half-space past a portal's hole, seen from the eye: beyond the face of its box (grown
/// already) nearest the eye; everything when the eye lies between the faces' planes.
glm::dvec4 beyond_portal(const Portal& p, const glm::dvec3& eye, const glm::dvec3& origin) {
  auto at = [&](int k) { return glm::dvec3(p.corners[k].x, p.corners[k].y, p.corners[k].z); };
  const glm::dvec3 across = at(2) - at(0);  // from one face of the wall to the other
  const double length = glm::length(across);
  if (!(length > 0.0)) return {0.0, 0.0, 0.0, 1.0};
  const glm::dvec3 n = across / length;
  const double near_face = glm::dot(n, at(0)), far_face = glm::dot(n, at(2)), e = glm::dot(n, eye);
  // the plane in the scene's frame: dot(m, p + origin) > d  <=>  dot(m, p) + dot(m, origin) - d
  if (e < near_face) return {n, glm::dot(n, origin) - near_face};
  if (e > far_face) return {-n, far_face - glm::dot(n, origin)};
  return {0.0, 0.0, 0.0, 1.0};
}

/// Visits every cell reachable from `start`; @return per cell the screen rectangle it is seen
/// through (empty: not reached).
std::vector<ScreenRect> walk_cells(const Scene& scene, const glm::dmat4& vp, std::size_t start,
                                   const glm::dvec3& eye, std::vector<OpenView>& open) {
  const glm::dvec3& o = scene.origin;
  const Cells& cells = scene.cells->cells;
  std::vector<ScreenRect> seen(cells.cells.size());
  std::vector<std::pair<std::uint32_t, ScreenRect>> pending{{start, kWholeScreen}};
  while (!pending.empty()) {
    const auto [k, rect] = pending.back();
    pending.pop_back();
    const ScreenRect grown = united(seen[k], rect);
    if (grown == seen[k]) continue;
    seen[k] = grown;
    const Cell& c = cells.cells[k];
    for (std::uint32_t p : c.portals) {
      const Portal& portal = cells.portals[p];
      const ScreenRect through = seen_through(portal.corners, scene.origin, vp, grown);
      if (through.empty()) continue;
      for (std::uint32_t next : portal.cells)
        if (next != k) pending.emplace_back(next, through);
      if (portal.to_outside) add_open_view(open, {through, beyond_portal(portal, eye, o)});
    }
    if (c.open_top) {
      const ScreenRect through = seen_through(outline_at(c, c.top_z), scene.origin, vp, grown);
      if (!through.empty()) {
        for (std::uint32_t next : c.cells_above) pending.emplace_back(next, through);
        if (c.top_outside)  // past an open top a ray only rises (see seen_openly)
          add_open_view(open, {through, {0.0, 0.0, 1.0, o.z - c.top_z - kPortalPlaneTolerance}});
      }
    }
    if (c.open_bottom) {
      const ScreenRect through = seen_through(outline_at(c, c.floor_z), scene.origin, vp, grown);
      if (!through.empty()) {
        for (std::uint32_t next : c.cells_below) pending.emplace_back(next, through);
        if (c.bottom_outside)
          add_open_view(open, {through, {0.0, 0.0, -1.0, c.floor_z - kPortalPlaneTolerance - o.z}});
      }
    }
  }
  return seen;
}

RunView view_of(const ScreenRect& r, const glm::dvec4& beyond = {0.0, 0.0, 0.0, 1.0}) {
  return {{float(r.x0), float(r.y0), float(r.x1), float(r.y1)}, glm::vec4(beyond)};
}

/// What sees both: the union of the rectangles, beyond a plane only if both are beyond it.
RunView united(const RunView& a, const RunView& b) {
  return {{std::min(a.scissor.x, b.scissor.x), std::min(a.scissor.y, b.scissor.y),
           std::max(a.scissor.z, b.scissor.z), std::max(a.scissor.w, b.scissor.w)},
          a.beyond == b.beyond ? a.beyond : glm::vec4(0.f, 0.f, 0.f, 1.f)};
}

/// How a cluster (scene frame) may be seen through the open views, or nullopt. Past an open top
/// (bottom) a ray only rises (falls): what lies within kPortalPlaneTolerance of that plane is
/// hit only next to the cell, where the cell's own runs hold it (cell_reach).
std::optional<RunView> seen_openly(const Cluster& cluster, const glm::dmat4& vp,
                                   const std::vector<OpenView>& open) {
  const Box3& b = cluster.bounds;
  std::optional<RunView> view;
  for (const OpenView& v : open) {
    double reach = -INFINITY;  // the box's farthest corner past the plane
    for (int i = 0; i < 8; ++i)
      reach = std::max(reach, glm::dot(v.beyond, glm::dvec4((i & 1) ? b.high[0] : b.low[0],
                                                            (i & 2) ? b.high[1] : b.low[1],
                                                            (i & 4) ? b.high[2] : b.low[2], 1.0)));
    if (reach <= 0.0 || is_outside(b, vp, v.rect)) continue;
    const RunView seen = view_of(v.rect, v.beyond);
    view = view ? united(*view, seen) : seen;
  }
  return view;
}

/// A run to draw and how it is seen.
struct SeenRun {
  Cluster run;
  RunView view;
};

/// Sorts runs into scene order and merges those that overlap (they lie in one cluster: the
/// merged run does too, seen as either saw it).
PortalWalk merged_runs(std::vector<SeenRun> seen, std::size_t cells_visited) {
  std::sort(seen.begin(), seen.end(),
            [](const SeenRun& a, const SeenRun& b) { return a.run.first < b.run.first; });
  PortalWalk walk{.runs = {}, .views = {}, .cells_visited = cells_visited};
  for (const SeenRun& s : seen) {
    if (!walk.runs.empty() && s.run.first < walk.runs.back().first + walk.runs.back().count) {
      Cluster& last = walk.runs.back();
      last.count = std::max(last.first + last.count, s.run.first + s.run.count) - last.first;
      add_point(last.bounds, s.run.bounds.low[0], s.run.bounds.low[1], s.run.bounds.low[2]);
      add_point(last.bounds, s.run.bounds.high[0], s.run.bounds.high[1], s.run.bounds.high[2]);
      walk.views.back() = united(walk.views.back(), s.view);
      continue;
    }
    walk.runs.push_back(s.run);
    walk.views.push_back(s.view);
  }
  return walk;
}

}  // namespace

std::optional<PortalWalk> walk_portals(const Scene& scene, const CameraMatrices& camera) {
  if (!scene.cells || scene.cells->cells.empty() || camera.orthographic) return std::nullopt;
  const glm::dmat4& p = camera.projection;
  // the near plane's farthest corner from the eye: what lies nearer may be cut away
  const double clearance =
      kPerspectiveNear * std::sqrt(1.0 + 1.0 / (p[0][0] * p[0][0]) + 1.0 / (p[1][1] * p[1][1])) +
      kPortalEyeClearance;
  const Vec3 eye{camera.eye.x + scene.origin.x, camera.eye.y + scene.origin.y,
                 camera.eye.z + scene.origin.z};
  const std::int64_t start = find_eye_cell(scene.cells->cells, eye, clearance);
  if (start < 0) return std::nullopt;
  const glm::dmat4& vp = camera.view_projection;
  std::vector<OpenView> open;
  const std::vector<ScreenRect> seen =
      walk_cells(scene, vp, std::size_t(start), {eye.x, eye.y, eye.z}, open);
  std::vector<SeenRun> runs;
  std::size_t cells_visited = 0;
  for (std::size_t k = 0; k < seen.size(); ++k) {
    if (seen[k].empty()) continue;
    ++cells_visited;
    for (const Cluster& run : scene.cells->runs[k])
      if ((run.passes & kColourPass) && !is_outside(run.bounds, vp, seen[k]))
        runs.push_back({run, view_of(seen[k])});
  }
  for (const Cluster& cluster : scene.clusters) {
    if (!(cluster.passes & kColourPass)) continue;
    if (cluster.first + cluster.count > scene.cells->indexed_triangles) {  // in no cell
      runs.push_back({cluster, RunView{}});
    } else if (!open.empty()) {
      if (const auto view = seen_openly(cluster, vp, open)) runs.push_back({cluster, *view});
    }
  }
  return merged_runs(std::move(runs), cells_visited);
}

}  // namespace roomcad
