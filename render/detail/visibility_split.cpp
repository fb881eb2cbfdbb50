// SPDX-License-Identifier: GPL-3.0-or-later
// Makarov & Safin's recursive split: contours as runs of the face seen, the depth order carried
// along each splitting line from crossing to crossing.
#include "render/detail/visibility_split.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <tbb/parallel_invoke.h>

namespace roomcad::detail {
namespace {

/// Triangles reach this far beyond their edges (samples): covers the rasteriser's float
/// vertices and fixed-point rounding, so that no sample it draws is missed.
constexpr double kCoverSlack = 1e-3;
/// Regions with fewer candidates than this are split on one thread.
constexpr std::size_t kParallelGrain = 256;

/// A stretch [from, to] of a contour side and the face seen along it (-1: none).
struct Run {
  double from = 0.0, to = 0.0;
  std::int64_t face = -1;
};
using Side = std::vector<Run>;

struct Region {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  ///< on sample centres
  Side top, bottom, left, right;          ///< y = y0, y = y1 (along x); x = x0, x = x1 (along y)
  std::vector<std::uint32_t> candidates;  ///< triangles whose box meets the region
};

struct Context {
  const std::vector<FlatTriangle>& triangles;
  SampleGrid grid;
  std::vector<std::atomic<std::uint8_t>>& visible;
  SplitCounters& counters;
};

/// The interval of the line {along = t, across = c} (horizontal when `horizontal`) inside a
/// triangle widened by kCoverSlack. @return false if the line misses it.
bool line_interval(const FlatTriangle& t, bool horizontal, double c, double& lo, double& hi) {
  lo = -1e300, hi = 1e300;
  double area2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Point2 a = t.p[i], b = t.p[(i + 1) % 3];
    area2 += a.x * b.y - a.y * b.x;
  }
  const double orient = area2 > 0.0 ? 1.0 : -1.0;
  for (int i = 0; i < 3; ++i) {
    const Point2 a = t.p[i], b = t.p[(i + 1) % 3];
    // inside: orient * cross(b - a, q - a) >= -slack * |b - a|, with q = (t, c) or (c, t)
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double slack = kCoverSlack * std::hypot(ex, ey);
    const double k = orient * (horizontal ? -ey : ex);  // coefficient of t
    const double m =
        orient * (horizontal ? ex * (c - a.y) + ey * a.x : -ey * (c - a.x) - ex * a.y) + slack;
    // inside when k * t + m >= 0 (m holds the terms without t)
    if (k == 0.0) {
      if (m < 0.0) return false;
    } else if (k > 0.0) {
      lo = std::max(lo, -m / k);
    } else {
      hi = std::min(hi, -m / k);
    }
  }
  return lo <= hi;
}

/// The nearest of the active triangles at a point by their depth planes: the face a contour
/// sees there (used to decide where splitting stops, never to mark). @return it, or -1.
std::int64_t front_face(const Context& cx, const std::vector<std::uint32_t>& active, double x,
                        double y) {
  double best = -1e300;
  std::int64_t face = -1;
  for (const std::uint32_t i : active) {
    const double d = cx.triangles[i].depth_at(x, y);
    if (d > best) best = d, face = i;
  }
  return face;
}

/// Decides sample (px, py) as the z-buffer does and marks the triangle it shows: the nearest
/// depth_at_pixel above the far plane, ties to the first drawn (the lowest index).
/// @param[in] covering  a superset of the triangles covering the sample
/// @return the index of the triangle shown, or -1. O(|covering|).
std::int64_t mark_sample(const Context& cx, const std::vector<std::uint32_t>& covering, int px,
                         int py) {
  const int ts = cx.grid.tile_size;
  const int x0 = px / ts * ts, y0 = py / ts * ts;
  float best = 0.f;  // the cleared depth buffer: far
  std::int64_t face = -1;
  for (const std::uint32_t i : covering) {
    const std::optional<float> d = depth_at_pixel(cx.triangles[i].screen, px, py, x0, y0);
    if (d && (*d > best || (*d == best && face >= 0 && i < face))) best = *d, face = i;
  }
  if (face >= 0) cx.visible[cx.triangles[face].id].store(1, std::memory_order_relaxed);
  return face;
}

/// Marks what the z-buffer shows at the sample centres k + 0.5 in [from, to) of a line.
void mark_line_samples(const Context& cx, const std::vector<std::uint32_t>& active, bool horizontal,
                       double across, double from, double to) {
  const int c = static_cast<int>(std::floor(across));
  for (int k = static_cast<int>(std::ceil(from - 0.5)); k + 0.5 < to; ++k) {
    if (horizontal) mark_sample(cx, active, k, c);
    else mark_sample(cx, active, c, k);
  }
}

/// Sweeps a splitting line from `from` to `to` at `across`: crossings sorted, the covering set
/// carried from stretch to stretch (enter at a triangle's first crossing, leave at its second).
Side sweep(const Context& cx, const std::vector<std::uint32_t>& candidates, bool horizontal,
           double across, double from, double to) {
  struct Event {
    double at;
    int enter;  // 1 enter, 0 leave: leaving first at equal positions
    std::uint32_t tri;
    bool operator<(const Event& o) const {
      return at != o.at ? at < o.at : enter != o.enter ? enter < o.enter : tri < o.tri;
    }
  };
  std::vector<Event> events;
  std::vector<std::uint32_t> active;
  for (const std::uint32_t i : candidates) {
    double lo = 0.0, hi = 0.0;
    if (!line_interval(cx.triangles[i], horizontal, across, lo, hi) || hi < from || lo > to)
      continue;
    if (lo <= from) active.push_back(i);
    else events.push_back({lo, 1, i});
    if (hi < to) events.push_back({hi, 0, i});
  }
  cx.counters.crossings.fetch_add(events.size(), std::memory_order_relaxed);
  std::sort(events.begin(), events.end());
  Side side;
  double start = from;
  const auto close = [&](double end, bool last) {
    mark_line_samples(cx, active, horizontal, across, start, last ? end + 0.5 : end);
    const double mid = 0.5 * (start + end);
    const std::int64_t face =
        horizontal ? front_face(cx, active, mid, across) : front_face(cx, active, across, mid);
    if (!side.empty() && side.back().face == face) side.back().to = end;
    else side.push_back({start, end, face});
    start = end;
  };
  for (const Event& e : events) {
    if (e.at > start) close(e.at, false);
    if (e.enter) active.push_back(e.tri);
    else std::erase(active, e.tri);
  }
  close(to, true);  // the line's last sample centre, `to`, too
  return side;
}

Side clip_side(const Side& side, double from, double to) {
  Side out;
  for (const Run& r : side) {
    if (r.to < from || r.from > to) continue;
    out.push_back({std::max(r.from, from), std::min(r.to, to), r.face});
  }
  return out;
}

bool sees_one_face(const Region& r) {
  std::int64_t face = r.top.empty() ? -2 : r.top.front().face;
  for (const Side* s : {&r.top, &r.bottom, &r.left, &r.right})
    for (const Run& run : *s)
      if (run.face != face) return false;
  return true;
}

/// @return the coplanar group every run of the contour sees, or -1 if runs see none or several.
std::int64_t contour_group(const Context& cx, const Region& r) {
  std::int64_t group = -2;
  for (const Side* s : {&r.top, &r.bottom, &r.left, &r.right})
    for (const Run& run : *s) {
      const std::int64_t g = run.face < 0 ? -1 : cx.triangles[run.face].group;
      if (g < 0 || (group != -2 && g != group)) return -1;
      group = g;
    }
  return group < 0 ? -1 : group;
}

/// @return whether a segment meets the rectangle's interior (shrunk by 1e-6: an edge lying on
/// the contour is seen by the contour's sweeps). Liang-Barsky.
bool meets_interior(Point2 a, Point2 b, double x0, double y0, double x1, double y1) {
  constexpr double kIn = 1e-6;
  double t0 = 0.0, t1 = 1.0;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - (x0 + kIn), (x1 - kIn) - a.x, a.y - (y0 + kIn), (y1 - kIn) - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
    } else if (p[i] < 0.0) {
      t0 = std::max(t0, q[i] / p[i]);
    } else {
      t1 = std::min(t1, q[i] / p[i]);
    }
  }
  return t0 < t1;
}

/// Whether an edge that bounds its plane's group crosses the region: only then can what is
/// seen inside differ from what the contour sees.
bool has_boundary_inside(const Context& cx, const Region& r) {
  return std::any_of(r.candidates.begin(), r.candidates.end(), [&](std::uint32_t i) {
    const FlatTriangle& t = cx.triangles[i];
    for (int e = 0; e < 3; ++e) {
      if (t.boundary[e] && meets_interior(t.p[e], t.p[(e + 1) % 3], r.x0, r.y0, r.x1, r.y1))
        return true;
    }
    return false;
  });
}

bool has_triangle_inside(const Context& cx, const Region& r) {
  return std::any_of(r.candidates.begin(), r.candidates.end(), [&](std::uint32_t i) {
    const Box2& b = cx.triangles[i].box;
    return b.min_x > r.x0 && b.max_x < r.x1 && b.min_y > r.y0 && b.max_y < r.y1;
  });
}

/// Separating-axis test of a triangle (widened by kCoverSlack) against a closed rectangle:
/// the boxes overlap and no edge line has the whole rectangle on its outer side.
bool meets_rectangle(const FlatTriangle& t, double x0, double y0, double x1, double y1) {
  const Box2& b = t.box;
  if (b.max_x < x0 - kCoverSlack || b.min_x > x1 + kCoverSlack || b.max_y < y0 - kCoverSlack ||
      b.min_y > y1 + kCoverSlack) {
    return false;
  }
  const Point2 &p0 = t.p[0], &p1 = t.p[1], &p2 = t.p[2];
  const double orient =
      (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x) > 0.0 ? 1.0 : -1.0;
  for (int i = 0; i < 3; ++i) {
    const Point2 a = t.p[i], e{t.p[(i + 1) % 3].x - a.x, t.p[(i + 1) % 3].y - a.y};
    // The rectangle's corner farthest inside this edge: if even it is outside, they are apart.
    const double nx = -orient * e.y, ny = orient * e.x;  // inward normal
    const double cx = nx > 0.0 ? x1 : x0, cy = ny > 0.0 ? y1 : y0;
    if (nx * (cx - a.x) + ny * (cy - a.y) < -kCoverSlack * std::hypot(e.x, e.y)) return false;
  }
  return true;
}

std::vector<std::uint32_t> overlapping(const Context& cx, const std::vector<std::uint32_t>& from,
                                       double x0, double y0, double x1, double y1) {
  std::vector<std::uint32_t> out;
  for (const std::uint32_t i : from) {
    if (meets_rectangle(cx.triangles[i], x0, y0, x1, y1)) out.push_back(i);
  }
  return out;
}

/// @return the sample-centre coordinate nearest the middle strictly inside (lo, hi), or NaN.
double split_at(double lo, double hi) {
  double c = std::floor(0.5 * (lo + hi)) + 0.5;
  if (c <= lo) c += 1.0;
  return c < hi ? c : NAN;
}

void split_region(const Context& cx, Region r);

/// Splits the region by the line x = c (`vertical`) or y = c: sweeps the line once, gives
/// each half its part of the contour and of the candidates, and recurses into both.
void split_in_two(const Context& cx, Region& r, bool vertical, double c) {
  Region a, b;  // the low and the high half
  if (vertical) {
    const Side line = sweep(cx, r.candidates, false, c, r.y0, r.y1);
    a = {r.x0,
         r.y0,
         c,
         r.y1,
         clip_side(r.top, r.x0, c),
         clip_side(r.bottom, r.x0, c),
         std::move(r.left),
         line,
         {}};
    b = {c,
         r.y0,
         r.x1,
         r.y1,
         clip_side(r.top, c, r.x1),
         clip_side(r.bottom, c, r.x1),
         line,
         std::move(r.right),
         {}};
  } else {
    const Side line = sweep(cx, r.candidates, true, c, r.x0, r.x1);
    a = {r.x0,
         r.y0,
         r.x1,
         c,
         std::move(r.top),
         line,
         clip_side(r.left, r.y0, c),
         clip_side(r.right, r.y0, c),
         {}};
    b = {r.x0,
         c,
         r.x1,
         r.y1,
         line,
         std::move(r.bottom),
         clip_side(r.left, c, r.y1),
         clip_side(r.right, c, r.y1),
         {}};
  }
  a.candidates = overlapping(cx, r.candidates, a.x0, a.y0, a.x1, a.y1);
  b.candidates = overlapping(cx, r.candidates, b.x0, b.y0, b.x1, b.y1);
  const bool parallel = r.candidates.size() >= kParallelGrain;
  r.candidates = {};
  if (parallel) {
    tbb::parallel_invoke([&] { split_region(cx, std::move(a)); },
                         [&] { split_region(cx, std::move(b)); });
  } else {
    split_region(cx, std::move(a));
    split_region(cx, std::move(b));
  }
}

/// Decides the sample centres of the region (`inside`: only those strictly inside) that
/// candidate i's box holds, until i's scene triangle is seen. O(samples scanned * candidates).
void scan_for(const Context& cx, const Region& r, std::uint32_t i, bool inside) {
  const FlatTriangle& t = cx.triangles[i];
  const int in = inside ? 1 : 0;
  const auto first = [](double lo) { return static_cast<int>(std::ceil(lo - 0.5)); };
  const auto last = [](double hi) { return static_cast<int>(std::floor(hi - 0.5)); };
  const int px0 = std::max(static_cast<int>(r.x0) + in, first(t.box.min_x));
  const int px1 = std::min(static_cast<int>(r.x1) - in, last(t.box.max_x));
  const int py0 = std::max(static_cast<int>(r.y0) + in, first(t.box.min_y));
  const int py1 = std::min(static_cast<int>(r.y1) - in, last(t.box.max_y));
  for (int py = py0; py <= py1; ++py)
    for (int px = px0; px <= px1; ++px) {
      if (cx.visible[t.id].load(std::memory_order_relaxed)) return;
      mark_sample(cx, r.candidates, px, py);
    }
}

/// Where splitting stops with one plane seen all round, any triangle of that plane may show at
/// the centres inside: decide those of the triangles not yet seen.
void mark_plane_inside(const Context& cx, const Region& r, std::int64_t group) {
  for (const std::uint32_t i : r.candidates) {
    if (cx.triangles[i].group == group) scan_for(cx, r, i, true);
  }
}

/// The recursion: stop when the contour sees one face and nothing lies wholly inside, or when
/// no sample centre is left strictly inside; else split the longer side at a sample centre.
/// Every sample centre is on a swept line or decided where splitting stops.
void split_region(const Context& cx, Region r) {
  cx.counters.regions.fetch_add(1, std::memory_order_relaxed);
  if (r.candidates.empty()) return;
  // One face (a triangle is convex) or one plane with no boundary of any face crossing the
  // region: the covering planes and their order are the same all over it.
  const bool one_face = sees_one_face(r);
  const std::int64_t group = one_face ? -1 : contour_group(cx, r);
  const double sx = split_at(r.x0, r.x1), sy = split_at(r.y0, r.y1);
  if ((one_face || group >= 0) && !has_triangle_inside(cx, r) &&
      (one_face || !has_boundary_inside(cx, r))) {
    // the face seen all round shows inside too: decide one centre inside, so it is marked
    // only if the z-buffer shows it in this region
    if (one_face && !std::isnan(sx) && !std::isnan(sy))
      mark_sample(cx, r.candidates, static_cast<int>(sx), static_cast<int>(sy));
    if (group >= 0) mark_plane_inside(cx, r, group);
    return;
  }
  if (r.candidates.size() == 1) {  // nothing can hide it here: seen if it covers a sample
    scan_for(cx, r, r.candidates.front(), false);
    return;
  }
  const bool vertical = !std::isnan(sx) && (std::isnan(sy) || r.x1 - r.x0 >= r.y1 - r.y0);
  if (vertical) split_in_two(cx, r, true, sx);
  else if (!std::isnan(sy)) split_in_two(cx, r, false, sy);
}

}  // namespace

void split_picture(const std::vector<FlatTriangle>& triangles, const SampleGrid& grid,
                   std::vector<std::atomic<std::uint8_t>>& visible, SplitCounters& counters) {
  const Context cx{triangles, grid, visible, counters};
  const int width = grid.width, height = grid.height;
  Region r{0.5, 0.5, width - 0.5, height - 0.5, {}, {}, {}, {}, {}};
  std::vector<std::uint32_t> all(triangles.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  r.candidates = overlapping(cx, all, r.x0, r.y0, r.x1, r.y1);
  r.top = sweep(cx, r.candidates, true, r.y0, r.x0, r.x1);
  r.bottom = sweep(cx, r.candidates, true, r.y1, r.x0, r.x1);
  r.left = sweep(cx, r.candidates, false, r.x0, r.y0, r.y1);
  r.right = sweep(cx, r.candidates, false, r.x1, r.y0, r.y1);
  split_region(cx, std::move(r));
}

}  // namespace roomcad::detail
