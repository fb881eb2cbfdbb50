// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/detail/centre_lines.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "geometry/segment_predicates.h"

namespace roomcad::detail {
namespace {

/// The range validation accepts for lengths and coordinates (see value_checks.cpp).
bool is_computable(double v) {
  const double m = std::fabs(v);
  return m == 0 || (m >= 1e-15 && m <= 1e15);
}

bool is_drawable(const Wall& w) {
  for (const double v : {w.from.x, w.from.y, w.to.x, w.to.y, w.thickness})
    if (!is_computable(v)) return false;  // NaN and infinities fail too
  return w.from != w.to && w.thickness > 0;
}

bool shares_an_end(const Wall& a, const Wall& b) {
  return a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to;
}

/// Records where the ends of `a` stand exactly on `b` (not at b's ends). @return how many.
int add_splits(const Wall& a, const Wall& b, std::vector<Point2>& splits_of_b) {
  int found = 0;
  for (const Point2 p : {a.from, a.to})
    if (p != b.from && p != b.to && is_near_segment(p, b.from, b.to, 0.0)) {
      splits_of_b.push_back(p);
      ++found;
    }
  return found;
}

/// @return the split points of every wall, or nothing if some join is not exact.
std::optional<std::vector<std::vector<Point2>>> find_splits(const Plan& plan, const Joins& joins) {
  std::vector<std::vector<Point2>> splits(plan.walls.size());
  for (const Join& j : joins.pairs) {
    const Wall& a = plan.walls[j.a];
    const Wall& b = plan.walls[j.b];
    if (!is_drawable(a) || !is_drawable(b)) continue;
    if (overlap_collinearly(a.from, a.to, b.from, b.to)) return std::nullopt;
    const int on_walls = add_splits(a, b, splits[j.b]) + add_splits(b, a, splits[j.a]);
    if (on_walls == 0 && !shares_an_end(a, b)) return std::nullopt;  // a crossing, or a gap
  }
  return splits;
}

/// Cuts wall w at its split points, in order along it (lexicographic order of points on a
/// segment is its order along the segment, one way or the other: no arithmetic needed).
void add_pieces(const Wall& w, std::size_t index, std::vector<Point2>& cuts, CentreLines& out) {
  const auto lex = [](Point2 p, Point2 q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); };
  std::sort(cuts.begin(), cuts.end(), lex);
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  if (!lex(w.from, w.to)) std::reverse(cuts.begin(), cuts.end());
  Point2 start = w.from;
  for (const Point2& c : cuts) {
    out.segments.emplace_back(start, c);
    out.walls.push_back(index);
    start = c;
  }
  out.segments.emplace_back(start, w.to);
  out.walls.push_back(index);
}

CentreLines snapped_centre_lines(const Plan& plan, const Joins& joins) {
  CentreLines out;
  for (std::size_t w = 0; w < plan.walls.size(); ++w) {
    if (!is_drawable(plan.walls[w])) continue;
    Point2 ends[2] = {plan.walls[w].from, plan.walls[w].to};
    for (int e = 0; e < 2; ++e) {
      const auto partner = joins.mitre[w][e];
      if (!partner || *partner > w) continue;
      const Wall& v = plan.walls[*partner];
      ends[e] = joins.mitre[*partner][0] == w ? v.from : v.to;
    }
    if (ends[0] == ends[1]) continue;  // a wall shorter than the tolerance, snapped to a point
    out.segments.emplace_back(ends[0], ends[1]);
    out.walls.push_back(w);
  }
  return out;
}

}  // namespace

CentreLines build_centre_lines(const Plan& plan, const Joins& joins) {
  std::optional<std::vector<std::vector<Point2>>> splits = find_splits(plan, joins);
  if (!splits) return snapped_centre_lines(plan, joins);
  CentreLines out;
  for (std::size_t w = 0; w < plan.walls.size(); ++w)
    if (is_drawable(plan.walls[w])) add_pieces(plan.walls[w], w, (*splits)[w], out);
  return out;
}

}  // namespace roomcad::detail
