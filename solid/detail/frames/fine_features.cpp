// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/frames/fine_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "geometry/segment_predicates.h"
#include "plan/plan_levels.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {
namespace {

bool is_fine(double metres) { return std::abs(metres) < kFinestFeature; }

bool is_far(Point2 p) { return std::max(std::abs(p.x), std::abs(p.y)) > kFarthestCoordinate; }

std::string far_point(Point2 p) {
  return fmt::format("({:.9g}, {:.9g}), {:.3g} m from the origin", p.x, p.y, std::hypot(p.x, p.y));
}

// A dimension of one object under kFinestFeature, or a corner past kFarthestCoordinate.
std::optional<std::string> fine_dimension(const Plan& plan) {
  for (const Wall& w : plan.walls) {
    const auto fine = [&](const char* what, double v) {
      return fmt::format("wall '{}' is {:.3g} m {}", w.id, v, what);
    };
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
    if (is_fine(length)) return fine("long", length);
    if (is_fine(w.thickness)) return fine("thick", w.thickness);
    if (is_fine(w.height)) return fine("high", w.height);
    if (w.height_at_end && is_fine(*w.height_at_end))
      return fine("high at its end", *w.height_at_end);
    for (const Point2 p : {w.from, w.to})
      if (is_far(p)) return fmt::format("wall '{}' reaches {}", w.id, far_point(p));
  }
  for (const Opening& o : plan.openings) {
    if (is_fine(o.width)) return fmt::format("opening '{}' is {:.3g} m wide", o.id, o.width);
    if (is_fine(o.height)) return fmt::format("opening '{}' is {:.3g} m high", o.id, o.height);
  }
  for (const Slab& s : plan.slabs) {
    if (is_fine(s.thickness)) return fmt::format("slab '{}' is {:.3g} m thick", s.id, s.thickness);
    for (const Point2 p : s.outline)
      if (is_far(p)) return fmt::format("slab '{}' reaches {}", s.id, far_point(p));
  }
  return std::nullopt;
}

// A step under kFinestFeature between two heights: a wall's base or top, an opening's sill or
// head, a slab's top or bottom, each absolute (its level's elevation added). Steps under the
// build's resolution (resolvable_size: a few ulps) do not count: sums of levels' elevations
// and heights meet an ulp or two apart in every multi-storey plan (the 504-wall tower, whose
// solid checks ok as written), and checking those would cost 8 times their build. The heights
// are sorted; only the two found are named (a 100,000-wall plan makes no strings). O(n log n).
std::optional<std::string> fine_step(const Plan& plan) {
  struct Height {
    double z;
    const char* what;  // "the base of wall": what the object's z is
    const std::string* id;
    bool operator<(const Height& o) const { return z < o.z; }
  };
  std::vector<Height> heights;
  std::unordered_map<std::string_view, double> base_of;  // wall id -> z of its base
  for (const Wall& w : plan.walls) {
    const double base = base_z(plan, w);
    base_of.emplace(w.id, base);
    heights.push_back({base, "the base of wall", &w.id});
    heights.push_back({base + w.height, "the top of wall", &w.id});
    if (w.height_at_end)
      heights.push_back({base + *w.height_at_end, "the top at the end of wall", &w.id});
  }
  for (const Opening& o : plan.openings) {
    const auto host = base_of.find(o.wall);
    if (host == base_of.end()) continue;
    heights.push_back({host->second + o.sill, "the sill of opening", &o.id});
    heights.push_back({host->second + o.sill + o.height, "the head of opening", &o.id});
  }
  for (const Slab& s : plan.slabs) {
    const double top = top_z(plan, s);
    heights.push_back({top, "the top of slab", &s.id});
    heights.push_back({top - s.thickness, "the bottom of slab", &s.id});
  }
  std::stable_sort(heights.begin(), heights.end());
  for (std::size_t k = 1; k < heights.size(); ++k) {
    const Height &low = heights[k - 1], &high = heights[k];
    const double step = high.z - low.z;
    if (step < kFinestFeature &&
        step >= resolvable_size(std::max(std::abs(low.z), std::abs(high.z))))
      return fmt::format("{} '{}' (z {} m) lies {:.3g} m above {} '{}' (z {} m)", high.what,
                         *high.id, high.z, step, low.what, *low.id, low.z);
  }
  return std::nullopt;
}

// The sine of the angle between two walls' directions, for messages: in long double, where
// the differences of the corners and their cross product keep the few ulps by which walls
// drawn along one line differ (their angles in doubles may round alike).
double sine_between(const Wall& a, const Wall& b) {
  using L = long double;
  const L ax = L(a.to.x) - L(a.from.x), ay = L(a.to.y) - L(a.from.y);
  const L bx = L(b.to.x) - L(b.from.x), by = L(b.to.y) - L(b.from.y);
  return double(std::abs(ax * by - ay * bx) / std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by)));
}

// A straight wall's line: its direction and where it lies.
struct Line {
  double angle, offset;  // direction in [0, pi); signed distance of the line from the origin
  const Wall* wall;
};

// Two ends of walls drawn along one line that lie under kFinestFeature apart, yet apart: a
// wall drawn over another that ends an ulp past it leaves a sliver an ulp long, which rounds
// into the faces around it (a fuzzed plan: crash-ulp-step-between-collinear-wall-ends). Each
// end's place along the line is measured along the first wall's direction, so that one point
// has one place. O(k log k) for k walls.
std::optional<std::string> fine_step_along_line(std::span<const Line> walls) {
  if (walls.size() < 2) return std::nullopt;
  const Wall& first = *walls.front().wall;
  const double dx = first.to.x - first.from.x, dy = first.to.y - first.from.y;
  const double length = std::hypot(dx, dy);
  struct End {
    double along;
    const Wall* wall;
    bool operator<(const End& o) const { return along < o.along; }
  };
  std::vector<End> ends;
  for (const Line& line : walls)
    for (const Point2 p : {line.wall->from, line.wall->to})
      ends.push_back({(p.x * dx + p.y * dy) / length, line.wall});
  std::stable_sort(ends.begin(), ends.end());
  for (std::size_t k = 1; k < ends.size(); ++k) {
    const double step = ends[k].along - ends[k - 1].along;
    if (step > 0.0 && step < kFinestFeature)
      return fmt::format(
          "an end of wall '{}' lies {:.3g} m along their line from an end of wall "
          "'{}'",
          ends[k].wall->id, step, ends[k - 1].wall->id);
  }
  return std::nullopt;
}

// How two walls, or a wall and an axis, may lie finer than kFinestFeature: their directions
// differ by under kFinestAngle (the sliver between them is under kFinestFeature wide across
// kFarthestCoordinate), or they are parallel on lines under kFinestFeature apart. Each
// candidate from doubles (angles sorted, then offsets of the nearly parallel sorted) is
// confirmed exactly (are_parallel), so walls drawn along one line or exactly parallel never
// count. O(n log n).
std::optional<std::string> fine_alignment(const Plan& plan) {
  constexpr double kFinestAngle = kFinestFeature / kFarthestCoordinate;
  std::vector<Line> lines;
  for (const Wall& w : plan.walls) {
    const double dx = w.to.x - w.from.x, dy = w.to.y - w.from.y;  // 0 exactly when equal
    if ((dx == 0.0 && dy == 0.0) || w.arc_extent.value_or(0.0) != 0.0) continue;  // arcs: no line
    if (dx != 0.0 && dy != 0.0 &&
        std::min(std::abs(dx), std::abs(dy)) < kFinestAngle * std::max(std::abs(dx), std::abs(dy)))
      return fmt::format(
          "wall '{}' runs {:.3g} rad off the {} axis", w.id,
          std::min(std::abs(dx), std::abs(dy)) / std::max(std::abs(dx), std::abs(dy)),
          std::abs(dx) > std::abs(dy) ? 'x' : 'y');
    // One direction per line: angle in [0, pi), (dx, dy) turned to it, so that walls drawn
    // either way along one line have one offset.
    double angle = std::atan2(dy, dx);
    const bool turn = angle < 0.0 || angle == std::numbers::pi;
    if (turn) angle = angle < 0.0 ? angle + std::numbers::pi : 0.0;
    const double ux = turn ? -dx : dx, uy = turn ? -dy : dy;
    lines.push_back({angle, (w.from.x * uy - w.from.y * ux) / std::hypot(dx, dy), &w});
  }
  std::sort(lines.begin(), lines.end(),
            [](const Line& a, const Line& b) { return a.angle < b.angle; });
  // Runs of nearly equal angles (across the wrap from pi to 0 too: such walls are nearly
  // parallel to the x axis, found above), each sorted by offset.
  for (std::size_t first = 0, last = 0; first < lines.size(); first = last) {
    for (last = first + 1;
         last < lines.size() && lines[last].angle - lines[last - 1].angle < kFinestAngle;)
      ++last;
    for (std::size_t k = first + 1; k < last; ++k) {
      const Wall &a = *lines[k - 1].wall, &b = *lines[k].wall;
      if (!are_parallel(a.from, a.to, b.from, b.to))
        return fmt::format("wall '{}' runs {:.3g} rad off wall '{}'", b.id, sine_between(a, b),
                           a.id);
    }
    std::sort(lines.begin() + std::ptrdiff_t(first), lines.begin() + std::ptrdiff_t(last),
              [](const Line& a, const Line& b) { return a.offset < b.offset; });
    for (std::size_t k = first + 1; k < last; ++k) {
      const Wall &a = *lines[k - 1].wall, &b = *lines[k].wall;
      if (lines[k].offset - lines[k - 1].offset < kFinestFeature &&
          !are_parallel(a.from, a.to, a.from, b.from))
        return fmt::format("wall '{}' runs parallel to wall '{}', {:.3g} m from its line", b.id,
                           a.id, lines[k].offset - lines[k - 1].offset);
    }
    // Walls closer than that are on one line (confirmed above): their ends along it.
    for (std::size_t begin = first, end = first; begin < last; begin = end) {
      for (end = begin + 1;
           end < last && lines[end].offset - lines[end - 1].offset < kFinestFeature;)
        ++end;
      if (auto step = fine_step_along_line(
              {lines.begin() + std::ptrdiff_t(begin), lines.begin() + std::ptrdiff_t(end)}))
        return step;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> fine_feature(const Plan& plan) {
  if (auto dimension = fine_dimension(plan)) return dimension;
  if (auto step = fine_step(plan)) return step;
  return fine_alignment(plan);
}

}  // namespace roomcad::detail
