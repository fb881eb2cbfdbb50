// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_arcs.h"
#include "import/detail/sh3d_walls.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace roomcad::sh3d {
namespace {

constexpr int kMaxChords = 256;   // bounds the output for a tiny tolerance on a huge arc
constexpr double kMinGap = 1e-9;  // fractions of the sweep: closer cuts would make slivers

double distance(Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

/// Cuts (as fractions of the sweep) splitting (from, to] into equal chords of at most `step`.
void add_even_cuts(double from, double to, double step, std::vector<double>& cuts) {
  // Clamped as a double: a zero step (tolerance below the radius's rounding) gives infinity,
  // which no int can hold.
  const double wanted = std::ceil((to - from) / step);
  const int n = wanted < kMaxChords ? std::max(1, static_cast<int>(wanted)) : kMaxChords;
  for (int k = 1; k <= n; ++k) cuts.push_back(from + (to - from) * k / n);
}

/// Keep stretches clamped to [0, 1], sorted, overlapping ones merged.
std::vector<KeepWhole> normalised(std::vector<KeepWhole> keep) {
  for (KeepWhole& k : keep) k = {std::max(k.from, 0.0), std::min(k.to, 1.0)};
  std::erase_if(keep, [](const KeepWhole& k) { return k.to <= k.from; });
  std::ranges::sort(keep, {}, &KeepWhole::from);
  std::vector<KeepWhole> merged;
  for (const KeepWhole& k : keep) {
    if (!merged.empty() && k.from <= merged.back().to) merged.back().to = std::max(merged.back().to, k.to);
    else merged.push_back(k);
  }
  return merged;
}

}  // namespace

Arc arc_through(Point2 a, Point2 b, double extent) {
  const double chord = distance(a, b);
  const double sweep = std::min(std::abs(extent), 2 * std::numbers::pi);
  const double radius = chord / (2 * std::sin(sweep / 2));
  const double side = extent > 0 ? 1.0 : -1.0;
  // Centre: from the chord's midpoint, away from the bulge (toward it for arcs over 180°).
  const Point2 left{-(b.y - a.y) / chord, (b.x - a.x) / chord};
  const double to_centre = -side * radius * std::cos(sweep / 2);
  const Point2 centre{(a.x + b.x) / 2 + left.x * to_centre, (a.y + b.y) / 2 + left.y * to_centre};
  return {centre, radius, std::atan2(a.y - centre.y, a.x - centre.x), -side * sweep};
}

std::vector<KeepWhole> openings_on_arc(const WallRecord& wall, const Arc& arc,
                                       const std::vector<ItemRecord>& items, double margin) {
  std::vector<KeepWhole> keep;
  for (const ItemRecord& item : items) {
    if (item.level != wall.level) continue;
    const Point2 rel{item.centre.x - arc.centre.x, item.centre.y - arc.centre.y};
    if (std::abs(std::hypot(rel.x, rel.y) - arc.radius) > wall.thickness / 2 + item.depth / 2)
      continue;
    // Angle from the arc's start, measured the way the arc turns, in [0, 2 pi).
    double turned = (std::atan2(rel.y, rel.x) - arc.start_angle) * (arc.sweep > 0 ? 1 : -1);
    turned = std::fmod(std::fmod(turned, 2 * std::numbers::pi) + 2 * std::numbers::pi,
                       2 * std::numbers::pi);
    const double sweep = std::abs(arc.sweep);
    if (turned > sweep) continue;
    const double half = std::asin(std::min(1.0, (item.width / 2 + margin) / arc.radius));
    keep.push_back({(turned - half) / sweep, (turned + half) / sweep});
  }
  return keep;
}

std::vector<Point2> split_arc(Point2 a, Point2 b, double extent, double tolerance,
                              std::vector<KeepWhole> keep) {
  const Arc arc = arc_through(a, b, extent);
  // A chord spanning angle phi strays radius * (1 - cos(phi / 2)) from the arc.
  const double max_angle = 2 * std::acos(std::max(-1.0, 1 - tolerance / arc.radius));
  const double step = max_angle / std::abs(arc.sweep);  // as a fraction of the sweep
  std::vector<double> cuts;
  double done = 0.0;
  for (const KeepWhole& k : normalised(std::move(keep))) {
    if (k.from > done + kMinGap) add_even_cuts(done, k.from, step, cuts);
    if (k.to < 1 - kMinGap) cuts.push_back(k.to);
    done = k.to;
  }
  if (done < 1 - kMinGap) add_even_cuts(done, 1.0, step, cuts);
  std::vector<Point2> points{a};
  for (const double t : cuts) {
    if (t >= 1 - kMinGap) break;
    const double angle = arc.start_angle + arc.sweep * t;
    // On the dyadic grid like every other imported length: trigonometry leaves noise such as
    // 6e-16 m where a point should be 0, which exact geometry would then have to resolve.
    points.push_back({on_dyadic_grid(arc.centre.x + arc.radius * std::cos(angle)),
                      on_dyadic_grid(arc.centre.y + arc.radius * std::sin(angle))});
  }
  points.push_back(b);
  return points;
}

}  // namespace roomcad::sh3d
