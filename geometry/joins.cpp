// SPDX-License-Identifier: GPL-3.0-or-later
// find_joins: broad phase on grown centre-line boxes, then exact tests on the candidate pairs.
//
// End clusters. The tolerance makes "shared end point" non-transitive: ends A, B, C may have
// A~B and B~C within tolerance but A and C farther apart. We decide per end, not per
// cluster: wall w's end E is mitred to wall v's end F only if E is within tolerance of F,
// v is the ONLY other wall whose centre line comes within tolerance of E, w is the only other
// wall within tolerance of F, and the two centre lines do not overlap along a length. So any
// chain of three or more ends (or a third centre line through the corner) unites all of
// them, and a mitre pairs exactly two ends, both ways. This is the spec's "exactly two walls
// and touched by no third centre line", made symmetric.
//
// Reach. A mitre whose corners would lie farther than kMitreReach thicknesses (of the thicker
// wall) from the end point joins by union instead: square ends, overlapping. As two walls
// close to a hairpin, or as a straight run from one thickness to another bends by a hair,
// their side lines cross ever farther away (a fuzzed hairpin put a corner 7.7e18 m out; a
// 0.2 m wall running on as a 0.1 m wall with a 1 degree kink, 2.9 m out). At equal
// thicknesses the reach of 4 is a corner of 14.4 degrees (sin(angle / 2) = 1/8).
//
// Heights. The spec's junctions are drawn in plan; walls whose height ranges share no length
// (a storey standing on the one below) never meet, so they are not joined and do not count
// as touching ends either: a ground-floor corner stays mitred under the walls above it.
#include "geometry/joins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "geometry/broad_phase.h"
#include "geometry/exact_wall_lines.h"
#include "geometry/segment_predicates.h"

namespace roomcad {
namespace {

bool is_usable(const Wall& w) {
  return std::isfinite(w.from.x) && std::isfinite(w.from.y) && std::isfinite(w.to.x) &&
         std::isfinite(w.to.y) && w.from != w.to;
}

Point2 end_point(const Wall& w, int end) { return end == 0 ? w.from : w.to; }

/// What one wall end sees: how many other centre lines come within tolerance, the last such
/// wall, and which of its ends (if any) is within tolerance of this end.
struct EndNeighbours {
  int count = 0;
  std::size_t wall = 0;
  int matched_ends = 0;  ///< ends of `wall` within tolerance of this end
  int matched_end = 0;
};

/// What one end of a candidate pair's wall sees of the other wall's centre line.
struct EndTouch {
  bool near = false;     ///< the end lies within tolerance of the other centre line
  int matched_ends = 0;  ///< ends of the other wall within tolerance of this end
  int matched_end = 0;
};

/// A candidate pair's tests, made on their own (in parallel) and recorded in pair order.
struct PairTest {
  std::array<std::array<EndTouch, 2>, 2> ends{};  ///< [wall a or b][its end]
  bool meets = false;                             ///< an end touches, or the centre lines meet
  std::optional<Point2> point;                    ///< first end within tolerance of the other wall
};

/// Tests the four ends of a candidate pair against the other centre line. Exact.
PairTest test_pair(const Plan& plan, std::size_t a, std::size_t b, double tol) {
  PairTest test;
  const Wall& wa = plan.walls[a];
  const Wall& wb = plan.walls[b];
  if (!share_heights(wa, wb)) return test;  // one above the other: they cannot meet
  const Wall* walls[2] = {&wa, &wb};
  for (int k = 0; k < 2; ++k) {
    const Wall& w = *walls[k];
    const Wall& v = *walls[1 - k];
    for (int e = 0; e < 2; ++e) {
      const Point2 p = end_point(w, e);
      if (!is_near_segment(p, v.from, v.to, tol)) continue;
      if (!test.point) test.point = p;
      EndTouch& t = test.ends[std::size_t(k)][std::size_t(e)];
      t.near = true;
      for (int f = 0; f < 2; ++f)
        if (is_near_point(p, end_point(v, f), tol)) {
          ++t.matched_ends;
          t.matched_end = f;
        }
    }
  }
  test.meets = test.point.has_value() || segments_meet(wa.from, wa.to, wb.from, wb.to);
  return test;
}

/// Records what the pair's ends see in `ends`: the count of centre lines near each end, and
/// the last of them with its matched ends.
void record_ends(const PairTest& test, std::size_t a, std::size_t b,
                 std::vector<std::array<EndNeighbours, 2>>& ends) {
  const std::size_t walls[2] = {a, b};
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t e = 0; e < 2; ++e) {
      const EndTouch& t = test.ends[k][e];
      if (!t.near) continue;
      EndNeighbours& n = ends[walls[k]][e];
      ++n.count;
      n.wall = walls[1 - k];
      n.matched_ends = t.matched_ends;
      n.matched_end = t.matched_end;
    }
}

/// @return the crossing of two centre lines that meet (rounded; only for reports).
Point2 crossing_point(const Wall& a, const Wall& b) {
  const double dx1 = a.to.x - a.from.x, dy1 = a.to.y - a.from.y;
  const double dx2 = b.to.x - b.from.x, dy2 = b.to.y - b.from.y;
  const double denom = dx1 * dy2 - dy1 * dx2;
  if (denom == 0.0) return a.from;
  const double s = ((b.from.x - a.from.x) * dy2 - (b.from.y - a.from.y) * dx2) / denom;
  return {a.from.x + s * dx1, a.from.y + s * dy1};
}

/// Whether both corners of a's end `ea` mitred to b's end `eb` lie within kMitreReach
/// thicknesses of the thicker wall from a's end point. Exact.
bool is_within_reach(const Wall& a, int ea, const Wall& b, int eb) {
  const double reach = kMitreReach * std::max(a.thickness, b.thickness);
  if (!(reach > 0.0 && reach < INFINITY)) return false;  // no thickness to mitre by (--force)
  const auto within = [&](int side) {
    return exact::decide([&](auto tag) -> bool {
      using NT = decltype(tag);
      const exact::Pt<NT> d = exact::mitre_corner<NT>(a, WallEnd(ea), b, WallEnd(eb), side) -
                              exact::to_pt<NT>(end_point(a, ea));
      return exact::dot(d, d) <= NT(reach) * NT(reach);
    });
  };
  return within(-1) && within(1);
}

bool is_mitre_end(const Plan& plan, const std::vector<std::array<EndNeighbours, 2>>& ends,
                  std::size_t w, int e) {
  const EndNeighbours& mine = ends[w][e];
  if (mine.count != 1 || mine.matched_ends != 1) return false;
  const EndNeighbours& theirs = ends[mine.wall][mine.matched_end];
  if (theirs.count != 1 || theirs.matched_ends != 1 || theirs.wall != w || theirs.matched_end != e)
    return false;
  const Wall& a = plan.walls[w];
  const Wall& b = plan.walls[mine.wall];
  return !overlap_collinearly(a.from, a.to, b.from, b.to) &&
         is_within_reach(a, e, b, mine.matched_end);
}

// Each wall's centre line grown by the tolerance, between its base and top: walls that do not
// share_heights never meet, and a home's storeys stand on one another in plan.
std::vector<SpaceBox> centre_line_boxes(const Plan& plan, double tol) {
  std::vector<SpaceBox> boxes;
  boxes.reserve(plan.walls.size());
  for (std::size_t i = 0; i < plan.walls.size(); ++i) {
    const Wall& w = plan.walls[i];
    if (!is_usable(w)) continue;
    Box2 box = grown_segment_box(w.from.x, w.from.y, w.to.x, w.to.y, tol);
    box.index = i;
    boxes.push_back(space_box(box, w.base, w.base + w.height));
  }
  return boxes;
}

}  // namespace

Joins find_joins(const Plan& plan) {
  const double tol =
      std::isfinite(plan.site.tolerance) && plan.site.tolerance > 0 ? plan.site.tolerance : 0.0;
  Joins joins;
  joins.mitre.assign(plan.walls.size(), {});
  std::vector<std::array<EndNeighbours, 2>> ends(plan.walls.size());
  // The pairs' exact tests, in pair order: nearly all are decided in interval arithmetic, so
  // one thread does a home's in well under a millisecond.
  for (const auto& [a, b] : find_meeting_boxes(centre_line_boxes(plan, tol))) {
    const PairTest test = test_pair(plan, a, b, tol);
    record_ends(test, a, b, ends);
    if (test.meets)
      joins.pairs.push_back(
          Join{a, b, JoinKind::unite,
               test.point.value_or(crossing_point(plan.walls[a], plan.walls[b]))});
  }
  for (Join& j : joins.pairs)
    for (int e = 0; e < 2; ++e) {
      if (!is_mitre_end(plan, ends, j.a, e) || ends[j.a][e].wall != j.b) continue;
      j.kind = JoinKind::mitre;
      j.point = end_point(plan.walls[j.a], e);
      joins.mitre[j.a][e] = j.b;
      joins.mitre[j.b][ends[j.a][e].matched_end] = j.a;
    }
  return joins;
}

bool Joins::are_joined(std::size_t a, std::size_t b) const { return find(a, b) != nullptr; }

const Join* Joins::find(std::size_t a, std::size_t b) const {
  if (a > b) std::swap(a, b);
  const auto it =
      std::lower_bound(pairs.begin(), pairs.end(), std::pair{a, b},
                       [](const Join& j, const std::pair<std::size_t, std::size_t>& key) {
                         return std::pair{j.a, j.b} < key;
                       });
  return it != pairs.end() && it->a == a && it->b == b ? &*it : nullptr;
}

}  // namespace roomcad
