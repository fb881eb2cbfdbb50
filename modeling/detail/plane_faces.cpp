// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/detail/plane_faces.h"

#include <algorithm>
#include <bit>
#include <map>
#include <string>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "modeling/detail/bounds_grid.h"
#include "modeling/detail/plane_loops.h"

namespace roomcad::detail {
namespace {

// Bounds (bounds_grid.h) here are low i, low j, high i, high j in the plane's view axes.

struct Context {
  const PlaneSet& set;
  const BoxPlanes& box;
  PlaneRef plane;
  int i, j;  // the two coordinate axes the plane is seen along (dominant_axis dropped)
  const std::vector<Contribution>& contributions;
  const std::vector<Cut>& cuts;
  PointCache& points;  // every point of the plane, by index
};

// A polygon edge (or a cut line across the box): the segment of `line` where from_end <= 0
// and to_end <= 0, from `start` to `end` in direction n x n_line (the polygon on its left).
struct Edge {
  PlaneRef line, from_end, to_end;
  std::size_t start = 0, end = 0;  // point indices
  std::size_t source = 0;          // contribution index; contributions.size() + k for cut k
  Bounds bounds{};
  std::vector<std::size_t> splits;
};

// A piece of an edge no other boundary crosses; a -> b in the edge's direction.
struct Piece {
  std::size_t a = 0, b = 0;
  PlaneRef line;
  std::size_t source = 0;  // the edge's
  Bounds bounds{};
};

Bounds bounds_of(const Context& cx, std::size_t a, std::size_t b) {
  const XPoint& p = cx.points[a];
  const XPoint& q = cx.points[b];
  const auto pi = bounds(p, cx.i), pj = bounds(p, cx.j), qi = bounds(q, cx.i), qj = bounds(q, cx.j);
  return {std::min(pi.first, qi.first), std::min(pj.first, qj.first), std::max(pi.second, qi.second),
          std::max(pj.second, qj.second)};
}

// The cut line's segment across the box, directed along n x n_cut.
Edge make_cut_edge(const Context& cx, const Cut& cut, std::size_t source) {
  int b = cx.i;
  PlaneRef high{cx.box.high[std::size_t(b)], 1};
  int d = orient_normals(cx.set, cx.plane, cut.line, high);
  if (d == 0) {
    b = cx.j;
    high = {cx.box.high[std::size_t(b)], 1};
    d = orient_normals(cx.set, cx.plane, cut.line, high);
  }
  const PlaneRef low{cx.box.low[std::size_t(b)], -1};
  const std::size_t at_low = cx.points.add(make_point(cx.set, cx.plane.id, cut.line.id, low.id));
  const std::size_t at_high = cx.points.add(make_point(cx.set, cx.plane.id, cut.line.id, high.id));
  Edge e = d > 0 ? Edge{cut.line, low, high, at_low, at_high, source, {}, {}}
                 : Edge{cut.line, high, low, at_high, at_low, source, {}, {}};
  e.bounds = bounds_of(cx, e.start, e.end);
  return e;
}

std::vector<Edge> make_edges(const Context& cx) {
  std::vector<Edge> edges;
  for (std::size_t c = 0; c < cx.contributions.size(); ++c) {
    const PlanePolygon& poly = cx.contributions[c].polygon;
    const std::size_t n = poly.lines.size(), first = cx.points.size();
    for (const XPoint& v : poly.vertices) cx.points.add(v);
    for (std::size_t m = 0; m < n; ++m) {
      const std::size_t prev = (m + n - 1) % n;
      Edge e{poly.lines[m], poly.lines[prev], poly.lines[(m + 1) % n], first + prev, first + m, c, {}, {}};
      e.bounds = bounds_of(cx, e.start, e.end);
      edges.push_back(std::move(e));
    }
  }
  for (std::size_t k = 0; k < cx.cuts.size(); ++k)
    edges.push_back(make_cut_edge(cx, cx.cuts[k], cx.contributions.size() + k));
  return edges;
}

bool is_strictly_inside(const Context& cx, const Edge& e, std::size_t p) {
  return cx.points.side(e.from_end, p) < 0 && cx.points.side(e.to_end, p) < 0;
}

// Records where e and f cross or touch, on each of them: by the sides of each one's ends
// against the other's line (ends are often explicit doubles, cheap to decide exactly), so a
// new point is made only where the two cross properly, strictly inside both.
void split_pair(const Context& cx, Edge& e, Edge& f) {
  const int s1 = cx.points.side(f.line, e.start), s2 = cx.points.side(f.line, e.end);
  if (s1 * s2 > 0) return;
  const int s3 = cx.points.side(e.line, f.start), s4 = cx.points.side(e.line, f.end);
  if (s3 * s4 > 0) return;
  if (s1 == 0 && s2 == 0) {  // the same trace: each splits the other at its ends inside it
    for (const std::size_t q : {f.start, f.end})
      if (is_strictly_inside(cx, e, q)) e.splits.push_back(q);
    for (const std::size_t q : {e.start, e.end})
      if (is_strictly_inside(cx, f, q)) f.splits.push_back(q);
    return;
  }
  if (s1 != 0 && s2 != 0 && s3 != 0 && s4 != 0) {  // a proper crossing
    const std::size_t x = cx.points.add(make_point(cx.set, cx.plane.id, e.line.id, f.line.id));
    e.splits.push_back(x);
    f.splits.push_back(x);
    return;
  }
  // An end of one lies on the other's line: it splits the other if inside it.
  if (s1 == 0 && is_strictly_inside(cx, f, e.start)) f.splits.push_back(e.start);
  if (s2 == 0 && is_strictly_inside(cx, f, e.end)) f.splits.push_back(e.end);
  if (s3 == 0 && is_strictly_inside(cx, e, f.start)) e.splits.push_back(f.start);
  if (s4 == 0 && is_strictly_inside(cx, e, f.end)) e.splits.push_back(f.end);
}

// Sweeps the edges' bounds along the first view axis and splits every overlapping pair.
void split_edges(const Context& cx, std::vector<Edge>& edges) {
  std::vector<std::size_t> order(edges.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return edges[a].bounds[0] < edges[b].bounds[0] || (edges[a].bounds[0] == edges[b].bounds[0] && a < b);
  });
  std::vector<std::size_t> active;
  for (std::size_t idx : order) {
    Edge& e = edges[idx];
    active.erase(std::remove_if(active.begin(), active.end(),
                                [&](std::size_t a) { return edges[a].bounds[2] < e.bounds[0]; }),
                 active.end());
    for (std::size_t a : active) {
      Edge& f = edges[a];
      if (f.source != e.source && boxes_meet(e.bounds, f.bounds)) split_pair(cx, e, f);
    }
    active.push_back(idx);
  }
}

// The edge's pieces, its splits sorted along it.
void append_pieces(const Context& cx, Edge& e, std::vector<Piece>& pieces) {
  const XPoint& start = cx.points[e.start];
  const XPoint& end = cx.points[e.end];
  const double di = std::abs(bounds(end, cx.i).first - bounds(start, cx.i).first);
  const double dj = std::abs(bounds(end, cx.j).first - bounds(start, cx.j).first);
  int axis = di >= dj ? cx.i : cx.j;
  int dir = cx.points.compare(e.end, e.start, axis);
  if (dir == 0) {
    axis = axis == cx.i ? cx.j : cx.i;
    dir = cx.points.compare(e.end, e.start, axis);
  }
  auto& s = e.splits;
  std::sort(s.begin(), s.end(), [&](std::size_t p, std::size_t q) { return cx.points.compare(p, q, axis) * dir < 0; });
  s.erase(std::unique(s.begin(), s.end(), [&](std::size_t p, std::size_t q) { return cx.points.is_same(p, q); }),
          s.end());
  std::size_t from = e.start;
  for (const std::size_t p : s) {
    pieces.push_back({from, p, e.line, e.source, bounds_of(cx, from, p)});
    from = p;
  }
  pieces.push_back({from, e.end, e.line, e.source, bounds_of(cx, from, e.end)});
}

// Gives equal points one index (of the first of them): @return per point index its
// representative's. Points of the same representation (explicit doubles, or the same three
// planes) by hashing, then the others by a sweep over their bounds on the first axis.
std::vector<std::size_t> find_equal_points(const Context& cx) {
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::size_t((k[0] * 0x9E3779B97F4A7C15ull) ^ ((k[1] + 0x7F4A7C15ull) * 0xBF58476D1CE4E5B9ull) ^ k[2]);
    }
  };
  const std::size_t n = cx.points.size();
  std::unordered_map<Key, std::size_t, KeyHash> by_key;
  std::vector<std::size_t> rep(n), reps;
  for (std::size_t k = 0; k < n; ++k) {
    const XPoint& p = cx.points[k];
    Key key;
    if (p.is_explicit()) {
      for (std::size_t c = 0; c < 3; ++c) key[c] = std::bit_cast<std::uint64_t>(p.approx[c].inf() + 0.0);
    } else {
      auto ids = p.planes;
      std::sort(ids.begin(), ids.end());
      key = {ids[0] | (std::uint64_t(1) << 63), ids[1], ids[2]};
    }
    const auto [it, fresh] = by_key.try_emplace(key, k);
    if (fresh) reps.push_back(k);
    rep[k] = it->second;
  }
  std::sort(reps.begin(), reps.end(), [&](std::size_t a, std::size_t b) {
    const double la = bounds(cx.points[a], cx.i).first, lb = bounds(cx.points[b], cx.i).first;
    return la < lb || (la == lb && a < b);
  });
  std::vector<std::size_t> active;
  for (const std::size_t r : reps) {
    const double low = bounds(cx.points[r], cx.i).first;
    active.erase(std::remove_if(active.begin(), active.end(),
                                [&](std::size_t a) { return bounds(cx.points[a], cx.i).second < low; }),
                 active.end());
    for (const std::size_t a : active)
      if (cx.points.is_same(r, a)) {
        rep[r] = a;
        break;
      }
    if (rep[r] == r) active.push_back(r);
  }
  for (std::size_t k = 0; k < n; ++k) rep[k] = rep[rep[k]];
  return rep;
}

// The sides of a piece against line t: {its negative side, its positive side}, each -1 when
// inside t (t's negative side), +1 outside.
std::array<int, 2> side_signs(const Context& cx, PlaneRef t, const Piece& p) {
  int s = cx.points.side(t, p.a);
  if (s == 0) s = cx.points.side(t, p.b);
  if (s != 0) return {s, s};
  // t runs along the piece: its inside is the piece's negative side if they point alike.
  const int aligned = t.id == p.line.id ? t.sign * p.line.sign : dot_in_plane(cx.set, cx.plane, t, p.line);
  return aligned > 0 ? std::array<int, 2>{-1, 1} : std::array<int, 2>{1, -1};
}

// What lies on one side of a piece: the owners of the faces there (-1 none) and, per owner,
// on which side of its cuts the point is.
struct SideLabel {
  long up_owner = -1, down_owner = -1;  // faces looking along (+) and against (-) the normal
  std::string up_cells, down_cells;     // a character per cut of the owner (short: no allocation)
};

struct Presence {
  bool solid_above = false, solid_below = false, hole_above = false, hole_below = false;
  long solid_face_below = -1, solid_face_above = -1, hole_face_above = -1, hole_face_below = -1;
  void add(const Contribution& c) {
    auto lowest = [&](long& slot) { slot = slot < 0 ? long(c.primitive) : std::min(slot, long(c.primitive)); };
    (c.solid ? solid_above : hole_above) |= c.above;
    (c.solid ? solid_below : hole_below) |= c.below;
    if (c.below && !c.above) lowest(c.solid ? solid_face_below : hole_face_below);
    if (c.above && !c.below) lowest(c.solid ? solid_face_above : hole_face_above);
  }
};

std::string cells_of(const Context& cx, const Piece& p, long owner, int s) {
  std::string cells;
  if (owner < 0) return cells;
  for (const Cut& cut : cx.cuts)
    if (long(cut.owner) == owner) cells.push_back(side_signs(cx, cut.line, p)[std::size_t(s)] > 0 ? '+' : '-');
  return cells;
}

std::array<SideLabel, 2> classify(const Context& cx, const Piece& p, BoundsGrid& near) {
  std::array<Presence, 2> at;
  near.for_each_meeting(p.bounds, [&](std::size_t c) {
    std::array<bool, 2> inside{true, true};
    if (c == p.source) {
      inside[1] = false;  // the piece lies on its own polygon's edge, the polygon on its left
    } else for (const PlaneRef& t : cx.contributions[c].polygon.lines) {
      const auto s = side_signs(cx, t, p);
      inside[0] = inside[0] && s[0] < 0;
      inside[1] = inside[1] && s[1] < 0;
      if (!inside[0] && !inside[1]) break;
    }
    for (std::size_t s = 0; s < 2; ++s)
      if (inside[s]) at[s].add(cx.contributions[c]);
  });
  std::array<SideLabel, 2> out;
  for (std::size_t s = 0; s < 2; ++s) {
    const Presence& a = at[s];
    const bool below = a.solid_below && !a.hole_below, above = a.solid_above && !a.hole_above;
    if (below && !above) out[s].up_owner = a.solid_above ? a.hole_face_above : a.solid_face_below;
    if (above && !below) out[s].down_owner = a.solid_below ? a.hole_face_below : a.solid_face_above;
    out[s].up_cells = cells_of(cx, p, out[s].up_owner, int(s));
    out[s].down_cells = cells_of(cx, p, out[s].down_owner, int(s));
  }
  return out;
}

using GroupKey = std::tuple<int, long, std::string>;  // side, owner, cut cells

void add_boundary(std::map<GroupKey, std::vector<DirectedPiece>>& groups, const Piece& p, std::size_t a,
                  std::size_t b, const std::array<SideLabel, 2>& l) {
  // The negative side lies on the left of a -> b seen from the plane's positive side.
  if (l[0].up_owner != l[1].up_owner || l[0].up_cells != l[1].up_cells) {
    if (l[0].up_owner >= 0) groups[{1, l[0].up_owner, l[0].up_cells}].push_back({a, b, p.line, 1});
    if (l[1].up_owner >= 0) groups[{1, l[1].up_owner, l[1].up_cells}].push_back({b, a, p.line, -1});
  }
  if (l[0].down_owner != l[1].down_owner || l[0].down_cells != l[1].down_cells) {
    if (l[0].down_owner >= 0) groups[{-1, l[0].down_owner, l[0].down_cells}].push_back({b, a, p.line, -1});
    if (l[1].down_owner >= 0) groups[{-1, l[1].down_owner, l[1].down_cells}].push_back({a, b, p.line, 1});
  }
}

}  // namespace

PlaneFaces build_plane_faces(const PlaneSet& set, const BoxPlanes& box, PlaneRef plane,
                             const std::vector<Contribution>& contributions, const std::vector<Cut>& cuts) {
  const IntervalScope intervals;
  const int k = dominant_axis(set, plane.id);
  PointCache points(set);
  const Context cx{set, box, plane, (k + 1) % 3, (k + 2) % 3, contributions, cuts, points};
  std::vector<Edge> edges = make_edges(cx);
  split_edges(cx, edges);
  std::vector<Piece> pieces;
  for (Edge& e : edges) append_pieces(cx, e, pieces);
  const std::vector<std::size_t> rep = find_equal_points(cx);
  std::vector<Bounds> cbounds;
  for (const Contribution& c : contributions) {
    Bounds b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const XPoint& v : c.polygon.vertices) {
      const auto vi = bounds(v, cx.i), vj = bounds(v, cx.j);
      b = {std::min(b[0], vi.first), std::min(b[1], vj.first), std::max(b[2], vi.second), std::max(b[3], vj.second)};
    }
    cbounds.push_back(b);
  }
  BoundsGrid near(cbounds);
  std::map<GroupKey, std::vector<DirectedPiece>> groups;
  for (const Piece& p : pieces) add_boundary(groups, p, rep[p.a], rep[p.b], classify(cx, p, near));
  PlaneFaces out;
  for (auto& [key, directed] : groups) {
    std::sort(directed.begin(), directed.end(), [](const DirectedPiece& x, const DirectedPiece& y) {
      return std::tie(x.from, x.to) < std::tie(y.from, y.to);
    });
    directed.erase(std::unique(directed.begin(), directed.end(), [](const DirectedPiece& x, const DirectedPiece& y) {
                     return x.from == y.from && x.to == y.to;
                   }),
                   directed.end());
    const auto& [side_of, owner, cells] = key;
    for (PieceLoop& loop : link_loops(plane, side_of, std::move(directed), points)) {
      PlaneFace face{side_of, std::size_t(owner), {}, {}, {}};
      for (const DirectedPiece& p : loop.pieces) {
        face.vertices.push_back(points[p.from]);
        face.lines.push_back(p.line);
      }
      if (loop.is_hole) {
        out.holes.emplace_back(std::size_t(owner), std::move(face.vertices));
        continue;
      }
      // Rounded here, where the exact coordinates found on the way are at hand (and planes
      // run in parallel).
      for (const DirectedPiece& p : loop.pieces) face.rounded.push_back(points.round(p.from));
      out.faces.push_back(std::move(face));
    }
  }
  return out;
}

}  // namespace roomcad::detail
