// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/detail/plane_faces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>

#include "modeling/detail/bounds_grid.h"
#include "modeling/flat_index.h"
#include "modeling/detail/plane_loops.h"

namespace roomcad::detail {
namespace {

// Bounds (bounds_grid.h) here are low i, low j, high i, high j in the plane's view axes.

struct Context {
  const PlaneSet& set;
  PlaneRef plane;
  int i, j;  // the two coordinate axes the plane is seen along (dominant_axis dropped)
  const std::vector<Contribution>& contributions;
  const std::vector<Cut>& cuts;
  const std::vector<std::pair<std::size_t, std::size_t>>& cuts_by_owner;  // (owner, cut), sorted
  PointCache& points;  // every point of the plane, by index
};

// A polygon edge (or a cut): the segment of `line` where from_end <= 0
// and to_end <= 0, from `start` to `end` in direction n x n_line (the polygon on its left).
struct Edge {
  PlaneRef line, from_end, to_end;
  std::size_t start = 0, end = 0;  // point indices
  std::size_t source = 0;          // contribution index; contributions.size() + k for cut k
  Bounds bounds{};
  // Where other edges split it: (point, the splitting edge's source), in no order.
  std::vector<std::pair<std::size_t, std::size_t>> splits;

  void split_at(std::size_t point, const Edge& by) { splits.emplace_back(point, by.source); }
};

// A piece of an edge no other boundary crosses; a -> b in the edge's direction.
struct Piece {
  std::size_t a = 0, b = 0;
  PlaneRef line;
  std::size_t source = 0;  // the edge's
  std::size_t edge = 0;    // the edge's index
  Bounds bounds{};
};

Bounds bounds_of(const Context& cx, std::size_t a, std::size_t b) {
  const XPoint& p = cx.points[a];
  const XPoint& q = cx.points[b];
  const auto pi = bounds(p, cx.i), pj = bounds(p, cx.j), qi = bounds(q, cx.i), qj = bounds(q, cx.j);
  return {std::min(pi.first, qi.first), std::min(pj.first, qj.first), std::max(pi.second, qi.second),
          std::max(pj.second, qj.second)};
}

// The cut's segment, directed along n x n_cut.
Edge make_cut_edge(const Context& cx, const Cut& cut, std::size_t source) {
  const PlaneRef high{cut.high, 1}, low{cut.low, -1};
  const int d = orient_normals(cx.set, cx.plane, cut.line, high);
  const std::size_t at_low = cx.points.add(make_point(cx.set, cx.plane.id, cut.line.id, low.id));
  const std::size_t at_high = cx.points.add(make_point(cx.set, cx.plane.id, cut.line.id, high.id));
  Edge e = d > 0 ? Edge{cut.line, low, high, at_low, at_high, source, {}, {}}
                 : Edge{cut.line, high, low, at_high, at_low, source, {}, {}};
  e.bounds = bounds_of(cx, e.start, e.end);
  return e;
}

// The contributions' edges.
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
      if (is_strictly_inside(cx, e, q)) e.split_at(q, f);
    for (const std::size_t q : {e.start, e.end})
      if (is_strictly_inside(cx, f, q)) f.split_at(q, e);
    return;
  }
  if (s1 != 0 && s2 != 0 && s3 != 0 && s4 != 0) {  // a proper crossing
    const std::size_t x = cx.points.add(make_point(cx.set, cx.plane.id, e.line.id, f.line.id));
    e.split_at(x, f);
    f.split_at(x, e);
    return;
  }
  // An end of one lies on the other's line: it splits the other if inside it.
  if (s1 == 0 && is_strictly_inside(cx, f, e.start)) f.split_at(e.start, e);
  if (s2 == 0 && is_strictly_inside(cx, f, e.end)) f.split_at(e.end, e);
  if (s3 == 0 && is_strictly_inside(cx, e, f.start)) e.split_at(f.start, f);
  if (s4 == 0 && is_strictly_inside(cx, e, f.end)) e.split_at(f.end, f);
}

// Sweeps the edges' bounds along the first view axis and splits every overlapping pair.
void split_edges(const Context& cx, std::vector<Edge>& edges) {
  // (low bound, edge), sorted by their values: not through the edges, which are far apart.
  std::vector<std::pair<double, std::size_t>> order(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) order[k] = {edges[k].bounds[0], k};
  // The comparison the edges had: NaN bounds fall where they did.
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && a.second < b.second);
  });
  std::vector<std::size_t> active;
  for (const auto& [low, idx] : order) {
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

// The edge's pieces, its split points in order along it (equal points once), appended to
// `pieces`. Piece k of the edge starts where the edges of sources[first_source[k]] ..
// sources[first_source[k + 1] - 1] split it off from piece k - 1 (none for the first).
void append_pieces(const Context& cx, std::size_t index, Edge& e, std::vector<Piece>& pieces,
                   std::vector<std::size_t>& sources, std::vector<std::size_t>& first_source) {
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
  std::sort(s.begin(), s.end(), [&](const auto& p, const auto& q) { return cx.points.compare(p.first, q.first, axis) * dir < 0; });
  sources.clear();
  first_source.assign(1, 0);
  std::size_t from = e.start;
  for (std::size_t k = 0; k < s.size();) {
    const std::size_t p = s[k].first;
    pieces.push_back({from, p, e.line, e.source, index, bounds_of(cx, from, p)});
    first_source.push_back(sources.size());
    for (; k < s.size() && cx.points.is_same(s[k].first, p); ++k) sources.push_back(s[k].second);
    from = p;
  }
  pieces.push_back({from, e.end, e.line, e.source, index, bounds_of(cx, from, e.end)});
  first_source.push_back(sources.size());
}

// Calls f(cell) for each cell of a fine square grid in the view axes (side `cell`) that point
// p's bounds cover, at most four, and returns true; false (no calls) when they cover more or
// are not finite. Equal points have overlapping bounds, so they share a cell: rounded
// division and floor are monotone, so the cell of the higher of the two low bounds is in both.
template <class F>
bool for_each_fine_cell(const Context& cx, const XPoint& p, double cell, F&& f) {
  const auto [li, hi] = bounds(p, cx.i);
  const auto [lj, hj] = bounds(p, cx.j);
  const double i0 = std::floor(li / cell), i1 = std::floor(hi / cell);
  const double j0 = std::floor(lj / cell), j1 = std::floor(hj / cell);
  if (!(i1 - i0 <= 1.0 && j1 - j0 <= 1.0)) return false;  // NaN and infinite bounds too
  for (double ci = i0; ci <= i1; ++ci)
    for (double cj = j0; cj <= j1; ++cj)
      f(std::array<std::uint64_t, 2>{std::uint64_t(std::int64_t(ci)), std::uint64_t(std::int64_t(cj))});
  return true;
}

// Gives equal points one index: @return per point index its representative's, the first of
// its equals in order of their low bounds on the first view axis (then index). Points are
// tested exactly where their bounds share a cell of a fine grid (2^-24 of the largest
// coordinate: far wider than a point's bounds, far narrower than a plan's features), and
// points whose bounds are wider than two cells (corners of nearly parallel planes) against
// all. O(n) expected hashing plus the exact tests of near points (most are repeats of one
// representation, decided without arithmetic).
std::vector<std::size_t> find_equal_points(const Context& cx) {
  const std::size_t n = cx.points.size();
  double largest = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    for (const int axis : {cx.i, cx.j})
      for (const double v : {bounds(cx.points[k], axis).first, bounds(cx.points[k], axis).second})
        if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  const double cell = std::max(largest * 0x1p-24, std::numeric_limits<double>::min());
  // Equal points united (a union-find forest), cell by cell.
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  const auto unite_if_same = [&](std::size_t a, std::size_t b) {
    const std::size_t ra = root(a), rb = root(b);
    if (ra != rb && cx.points.is_same(a, b)) parent[std::max(ra, rb)] = std::min(ra, rb);
  };
  using CellKey = std::array<std::uint64_t, 2>;
  FlatIndex<CellKey> cell_of(n);
  std::vector<std::uint32_t> last_in_cell;                  // per cell, its last filed entry
  std::vector<std::pair<std::size_t, std::uint32_t>> filed;  // (point, the cell's entry before it)
  std::vector<std::size_t> wide;
  for (std::size_t k = 0; k < n; ++k) {
    const bool fine = for_each_fine_cell(cx, cx.points[k], cell, [&](const CellKey& key) {
      const auto [c, added] = cell_of.try_emplace(key, std::uint32_t(last_in_cell.size()));
      if (added) last_in_cell.push_back(FlatIndex<CellKey>::kNone);
      for (std::uint32_t e = last_in_cell[c]; e != FlatIndex<CellKey>::kNone; e = filed[e].second)
        unite_if_same(k, filed[e].first);
      filed.emplace_back(k, last_in_cell[c]);
      last_in_cell[c] = std::uint32_t(filed.size() - 1);
    });
    if (!fine) wide.push_back(k);
  }
  for (const std::size_t w : wide)
    for (std::size_t k = 0; k < n; ++k)
      if (k != w) unite_if_same(w, k);
  // Each group's representative: its first point in order of low bound, then index.
  const auto earlier = [&](std::size_t a, std::size_t b) {
    const double la = bounds(cx.points[a], cx.i).first, lb = bounds(cx.points[b], cx.i).first;
    return la < lb || (la == lb && a < b);
  };
  std::vector<std::size_t> first_of_group(n, n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t& first = first_of_group[root(k)];
    if (first == n || earlier(k, first)) first = k;
  }
  std::vector<std::size_t> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = first_of_group[root(k)];
  return out;
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

// On which side of each of the owner's cuts side s of the piece lies: a character per cut
// (short: no allocation).
std::string cells_of(const Context& cx, const Piece& p, long owner, int s) {
  std::string cells;
  if (owner < 0) return cells;
  const auto& by_owner = cx.cuts_by_owner;
  const auto first = std::lower_bound(by_owner.begin(), by_owner.end(),
                                      std::pair{std::size_t(owner), std::size_t{0}});
  for (auto at = first; at != by_owner.end() && at->first == std::size_t(owner); ++at)
    cells.push_back(side_signs(cx, cx.cuts[at->second].line, p)[std::size_t(s)] > 0 ? '+' : '-');
  return cells;
}

// Which sides of piece p lie inside polygon c (not p's own).
std::array<bool, 2> inside_sides(const Context& cx, std::size_t c, const Piece& p) {
  std::array<bool, 2> inside{true, true};
  for (const PlaneRef& t : cx.contributions[c].polygon.lines) {
    const auto s = side_signs(cx, t, p);
    inside[0] = inside[0] && s[0] < 0;
    inside[1] = inside[1] && s[1] < 0;
    if (!inside[0] && !inside[1]) break;
  }
  return inside;
}

// A polygon with a piece inside it on one side or both.
struct Inside {
  std::size_t polygon = 0;
  std::array<bool, 2> sides{};
};

// The faces on the two sides of a piece: their owners, and whether the solid's material on
// the side away from each face is pinched along the piece (see `pinched`).
struct PieceFaces {
  std::array<FaceOwners, 2> owners;
  bool up_pinched = false, down_pinched = false;
};

// The line of convex polygon c that runs along piece p (c covers one side of p only, so its
// boundary does), or nothing. O(lines) predicates.
std::optional<PlaneRef> line_along(const Context& cx, std::size_t c, const Piece& p) {
  if (c == p.source) return p.line;
  for (const PlaneRef& t : cx.contributions[c].polygon.lines)
    if (cx.points.side(t, p.a) == 0 && cx.points.side(t, p.b) == 0) return t;
  return std::nullopt;
}

// Whether the solid just below the plane (`below`; else just above) near piece p is two parts
// that touch only along it, where the face of the plane runs on across the piece (the same
// owner both sides): then the face must end there (wedges_apart). No polygon may cover both
// sides; each side's are wedges along the piece, and every pair across it must leave a gap
// (then so do the widest two). Exact; O(k^2) for k polygons along the piece, usually none.
bool pinched(const Context& cx, const Piece& p, PlaneRef across, const std::vector<Inside>& inside,
             bool below) {
  std::vector<PlaneRef> side0, side1;
  for (const Inside& in : inside) {
    const Contribution& c = cx.contributions[in.polygon];
    if (!c.solid || !(below ? c.below : c.above)) continue;
    if (in.sides[0] && in.sides[1]) return false;
    const auto t = line_along(cx, in.polygon, p);
    if (!t) return false;
    (in.sides[0] ? side0 : side1).push_back(*t);
  }
  if (side0.empty() || side1.empty()) return false;
  for (const PlaneRef& m0 : side0)
    for (const PlaneRef& m1 : side1)
      if (!wedges_apart(cx.set, cx.plane, m0, m1, across, below)) return false;
  return true;
}

PieceFaces faces_of(const Context& cx, const Piece& p, PlaneRef across,
                    const std::vector<Inside>& inside) {
  std::array<Presence, 2> at;
  for (const Inside& in : inside)
    for (std::size_t s = 0; s < 2; ++s)
      if (in.sides[s]) at[s].add(cx.contributions[in.polygon]);
  PieceFaces out{{at[0].owners(), at[1].owners()}};
  if (p.source >= cx.contributions.size()) return out;  // a cut's piece
  const auto& o = out.owners;
  out.up_pinched = o[0].up >= 0 && o[0].up == o[1].up && pinched(cx, p, across, inside, true);
  out.down_pinched =
      o[0].down >= 0 && o[0].down == o[1].down && pinched(cx, p, across, inside, false);
  return out;
}

// The faces on the two sides of each piece of one edge, walking along it: the first piece is
// tested against every polygon near it, each next piece only against the polygons whose edges
// split it off from the one before (append_pieces' sources), as no other polygon's boundary
// passes between them. `across` is a plane crossing the edge; `inside` is scratch space.
void classify_edge(const Context& cx, std::span<const Piece> pieces, PlaneRef across,
                   const std::vector<std::size_t>& sources,
                   const std::vector<std::size_t>& first_source, BoundsGrid& near,
                   std::vector<Inside>& inside, std::span<PieceFaces> out) {
  const Piece& first = pieces.front();
  inside.clear();
  near.for_each_meeting(first.bounds, [&](std::size_t c) {
    // The piece lies on its own polygon's edge, the polygon on its left.
    const std::array<bool, 2> sides = c == first.source ? std::array<bool, 2>{true, false} : inside_sides(cx, c, first);
    if (sides[0] || sides[1]) inside.push_back({c, sides});
  });
  out[0] = faces_of(cx, first, across, inside);
  for (std::size_t k = 1; k < pieces.size(); ++k) {
    for (std::size_t at = first_source[k]; at < first_source[k + 1]; ++at) {
      const std::size_t c = sources[at];
      if (c >= cx.contributions.size()) continue;  // a cut: no polygon
      if (std::find(sources.begin() + std::ptrdiff_t(first_source[k]), sources.begin() + std::ptrdiff_t(at), c) !=
          sources.begin() + std::ptrdiff_t(at))
        continue;  // its polygon is done
      const std::array<bool, 2> sides = inside_sides(cx, c, pieces[k]);
      const auto it = std::find_if(inside.begin(), inside.end(), [&](const Inside& in) { return in.polygon == c; });
      if (!sides[0] && !sides[1]) {
        if (it != inside.end()) inside.erase(it);
      } else if (it != inside.end()) {
        it->sides = sides;
      } else {
        inside.push_back({c, sides});
      }
    }
    out[k] = faces_of(cx, pieces[k], across, inside);
  }
}

using GroupKey = std::tuple<int, long, std::string>;  // side, owner, cut cells

// The pieces bounding the faces of each group (side, owner, cut cells), each group's in the
// order they were filed. A hash of the key finds the group (a plane files tens of thousands
// of pieces in a few dozen groups); the groups are read in order of their keys.
class FaceGroups {
 public:
  void add(int side, long owner, const std::string& cells, const DirectedPiece& piece) {
    const std::size_t name = cell_names_.try_emplace(cells, cell_names_.size()).first->second;
    const std::array<std::uint64_t, 2> key{(std::uint64_t(owner) << 1) | (side > 0 ? 1u : 0u), name};
    const auto [group, added] = index_.try_emplace(key, std::uint32_t(keys_.size()));
    if (added) {
      keys_.emplace_back(side, owner, cells);
      pieces_.emplace_back();
    }
    pieces_[group].push_back(piece);
  }
  /// @return the groups' indices in order of their keys.
  [[nodiscard]] std::vector<std::size_t> in_key_order() const {
    std::vector<std::size_t> order(keys_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys_[a] < keys_[b]; });
    return order;
  }
  [[nodiscard]] const GroupKey& key(std::size_t group) const { return keys_[group]; }
  [[nodiscard]] std::vector<DirectedPiece>& pieces(std::size_t group) { return pieces_[group]; }

 private:
  // The distinct cut cells filed, numbered in order of first use: a plane cut a hundred times
  // has about as many cells.
  std::unordered_map<std::string, std::size_t> cell_names_;
  FlatIndex<std::array<std::uint64_t, 2>> index_;  // (owner and side, cells' name) -> group
  std::vector<GroupKey> keys_;
  std::vector<std::vector<DirectedPiece>> pieces_;
};

// Files the piece with the faces it bounds: where an owner, or its cut cell, differs between
// its sides.
void add_boundary(const Context& cx, FaceGroups& groups, const Piece& p, std::size_t a,
                  std::size_t b, const PieceFaces& faces) {
  const auto& o = faces.owners;
  // Most pieces lie inside a face, one owner on both sides: without cuts, nothing to file.
  if (cx.cuts.empty() && o[0].up == o[1].up && o[0].down == o[1].down && !faces.up_pinched &&
      !faces.down_pinched)
    return;
  // The negative side lies on the left of a -> b seen from the plane's positive side.
  const std::array<std::string, 2> up{cells_of(cx, p, o[0].up, 0), cells_of(cx, p, o[1].up, 1)};
  if (o[0].up != o[1].up || up[0] != up[1] || faces.up_pinched) {
    if (o[0].up >= 0) groups.add(1, o[0].up, up[0], {a, b, p.line, 1});
    if (o[1].up >= 0) groups.add(1, o[1].up, up[1], {b, a, p.line, -1});
  }
  const std::array<std::string, 2> down{cells_of(cx, p, o[0].down, 0), cells_of(cx, p, o[1].down, 1)};
  if (o[0].down != o[1].down || down[0] != down[1] || faces.down_pinched) {
    if (o[0].down >= 0) groups.add(-1, o[0].down, down[0], {b, a, p.line, -1});
    if (o[1].down >= 0) groups.add(-1, o[1].down, down[1], {a, b, p.line, 1});
  }
}

// The contributions whose flag in `dropped` is 0, in their order.
std::vector<Contribution> without_dropped(std::vector<Contribution> contributions, const std::vector<char>& dropped) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < contributions.size(); ++k)
    if (!dropped[k]) {
      if (n != k) contributions[n] = std::move(contributions[k]);
      ++n;
    }
  contributions.resize(n);
  return contributions;
}

// The contributions with equal polygons of one kind (solid or hole, above, below) made one: the
// first of them, owned by the lowest-numbered primitive among them (the owner classify picks
// where they lie). They would only repeat each other's edges and pieces: walls drawn over one
// another give many. O(n log n) plus the corners of polygons of one hash.
std::vector<Contribution> without_duplicates(std::vector<Contribution> contributions) {
  using Corners = std::vector<std::array<std::uint64_t, 3>>;
  std::vector<Corners> corners(contributions.size());
  std::vector<std::pair<std::uint64_t, std::size_t>> by_hash;  // (hash, contribution)
  by_hash.reserve(contributions.size());
  for (std::size_t k = 0; k < contributions.size(); ++k) {
    const Contribution& c = contributions[k];
    Corners& key = corners[k];
    for (const XPoint& v : c.polygon.vertices) key.push_back(representation_key(v));
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    std::uint64_t hash = (c.solid ? 1 : 0) | (c.above ? 2 : 0) | (c.below ? 4 : 0);
    for (const auto& corner : key) hash = mix_bits(hash ^ BitsHash{}(corner));
    by_hash.emplace_back(hash, k);
  }
  std::sort(by_hash.begin(), by_hash.end());
  std::vector<char> dropped(contributions.size(), 0);
  for (std::size_t a = 0; a < by_hash.size(); ++a) {
    const std::size_t first = by_hash[a].second;
    if (dropped[first]) continue;
    Contribution& kept = contributions[first];
    for (std::size_t b = a + 1; b < by_hash.size() && by_hash[b].first == by_hash[a].first; ++b) {
      Contribution& other = contributions[by_hash[b].second];
      if (dropped[by_hash[b].second] || corners[by_hash[b].second] != corners[first] || other.solid != kept.solid ||
          other.above != kept.above || other.below != kept.below)
        continue;
      kept.primitive = std::min(kept.primitive, other.primitive);
      dropped[by_hash[b].second] = 1;
    }
  }
  return without_dropped(std::move(contributions), dropped);
}

// Whether point v lies in convex polygon `polygon` (closed). Exact.
bool holds_point(const PlaneSet& set, const PlanePolygon& polygon, const XPoint& v) {
  return std::none_of(polygon.lines.begin(), polygon.lines.end(), [&](PlaneRef t) { return side(set, t, v) > 0; });
}

// Whether convex polygon `inner` lies in convex polygon `outer` (both closed). Exact.
bool lies_in(const PlaneSet& set, const PlanePolygon& inner, const PlanePolygon& outer) {
  return std::all_of(inner.vertices.begin(), inner.vertices.end(),
                     [&](const XPoint& v) { return holds_point(set, outer, v); });
}

// Whether convex polygon `face` lies in the union of the convex polygons `covers` (of its
// plane): nothing is left of it once each cover is taken away (a convex polygon minus a convex
// one is at most one convex piece per line of the latter). A corner in no cover says no at
// once, before any piece is made: most faces that are not covered have one. Gives up (false)
// past 64 pieces. Exact.
bool lies_in_union(const PlaneSet& set, const PlanePolygon& face, const std::vector<const PlanePolygon*>& covers) {
  const auto in_a_cover = [&](const XPoint& v) {
    return std::any_of(covers.begin(), covers.end(), [&](const PlanePolygon* c) { return holds_point(set, *c, v); });
  };
  if (!std::all_of(face.vertices.begin(), face.vertices.end(), in_a_cover)) return false;
  constexpr std::size_t kMostPieces = 64;
  std::vector<PlanePolygon> left{face}, next;
  for (const PlanePolygon* cover : covers) {
    next.clear();
    for (PlanePolygon& piece : left)
      for (const PlaneRef& t : cover->lines) {
        PlanePolygon outside = piece;  // the part beyond t, inside the lines before it
        if (clip_polygon(set, outside, {t.id, -t.sign})) next.push_back(std::move(outside));
        if (!clip_polygon(set, piece, t)) break;  // none of it within t
      }
    if (next.size() > kMostPieces) return false;
    left.swap(next);
    if (left.empty()) return true;
  }
  return false;
}

// Each contribution's polygon's box, in their order.
std::vector<Box3> boxes_of(const std::vector<Contribution>& contributions) {
  std::vector<Box3> boxes;
  boxes.reserve(contributions.size());
  for (const Contribution& c : contributions) boxes.push_back(box_of(c.polygon.vertices));
  return boxes;
}

// The contributions without those lying in a section that makes them irrelevant: in a solid
// section every solid polygon (solid lies above and below there whatever they say), in a hole
// section every polygon (holes take both sides away). Where a face lies inside a solid
// section, only holes make it and own it. Walls drawn over one another give many: a lower
// storey's wall top inside the section of a wall across it. O(n s) box tests for s sections,
// plus the side tests of containment where boxes meet; each polygon is tested against the
// kept sections.
std::vector<Contribution> without_covered(const PlaneSet& set, std::vector<Contribution> contributions) {
  std::vector<std::size_t> sections;
  for (std::size_t s = 0; s < contributions.size(); ++s)
    if (contributions[s].above && contributions[s].below) sections.push_back(s);
  if (sections.empty()) return contributions;
  const std::vector<Box3> boxes = boxes_of(contributions);
  std::vector<char> dropped(contributions.size(), 0);
  for (std::size_t p = 0; p < contributions.size(); ++p)
    for (const std::size_t s : sections) {
      const Contribution& section = contributions[s];
      if (s == p || dropped[s] || (section.solid && !contributions[p].solid) ||
          !boxes_meet(boxes[p], boxes[s]) ||
          !lies_in(set, contributions[p].polygon, section.polygon))
        continue;
      dropped[p] = 1;
      break;
    }
  return without_dropped(std::move(contributions), dropped);
}

// A point near the middle of convex polygon `polygon`: the mean of its corners' interval
// midpoints, as explicit doubles (so up to a rounding off the polygon's plane); none where
// those are not finite. A guess, for ordering and a shortcut whose false is allowed to be
// wrong, never for a verdict.
std::optional<XPoint> middle_of(const PlanePolygon& polygon) {
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  for (const XPoint& v : polygon.vertices)
    for (std::size_t k = 0; k < 3; ++k) sum[k] += v.approx[k].inf() / 2.0 + v.approx[k].sup() / 2.0;
  const auto n = double(polygon.vertices.size());
  for (double& x : sum) {
    x /= n;
    if (!std::isfinite(x)) return std::nullopt;
  }
  return make_point(sum[0], sum[1], sum[2]);
}

}  // namespace

bool wedges_apart(const PlaneSet& set, PlaneRef plane, PlaneRef m0, PlaneRef m1, PlaneRef across,
                  bool below) {
  if (m0.id == m1.id) return false;
  const int frame = orient_normals(set, m0, plane, across) * (below ? 1 : -1);
  return frame * orient_normals(set, m0, m1, across) < 0;
}

bool has_no_faces(const PlaneSet& set, const std::vector<Contribution>& contributions) {
  const IntervalScope intervals;
  const std::vector<Box3> boxes = boxes_of(contributions);
  std::vector<const PlanePolygon*> covers;
  const PlanePolygon* last = nullptr;  // the cover that held the last face: often the next too
  for (std::size_t f = 0; f < contributions.size(); ++f) {
    const Contribution& face = contributions[f];
    if (face.above == face.below) continue;  // a section
    if (!face.solid) return false;
    // The solid polygons on the face's other side, near it: usually one holds it whole.
    covers.clear();
    for (std::size_t g = 0; g < contributions.size(); ++g) {
      const Contribution& other = contributions[g];
      if (other.solid && (face.below ? other.above : other.below) && boxes_meet(boxes[f], boxes[g]))
        covers.push_back(&other.polygon);
    }
    if (last && std::find(covers.begin(), covers.end(), last) != covers.end() &&
        lies_in(set, face.polygon, *last))
      continue;
    // A face whose middle no cover holds is (nearly surely) not covered: false at once, before
    // the exact tests of containment. Otherwise the covers holding the middle go first.
    if (const auto middle = middle_of(face.polygon)) {
      const auto holders = std::stable_partition(
          covers.begin(), covers.end(),
          [&](const PlanePolygon* c) { return holds_point(set, *c, *middle); });
      if (holders == covers.begin()) return false;
    }
    const auto holder = std::find_if(covers.begin(), covers.end(), [&](const PlanePolygon* c) {
      return lies_in(set, face.polygon, *c);
    });
    if (holder != covers.end()) {
      last = *holder;
      continue;
    }
    if (!lies_in_union(set, face.polygon, covers)) return false;
  }
  return true;
}

struct PlaneBoolean::State {
  const PlaneSet& set;
  PlaneRef plane;
  int i, j;  // the view axes: dominant_axis dropped
  std::vector<Contribution> contributions;
  std::vector<Cut> cuts;
  std::vector<std::pair<std::size_t, std::size_t>> cuts_by_owner;  // (owner, cut index), sorted
  PointCache points;
  std::vector<Edge> edges;
  std::vector<Bounds> polygon_bounds;  // per contribution
  BoundsGrid near;                     // of polygon_bounds
  // Every edge's pieces with the faces on their two sides.
  std::vector<Piece> pieces;
  std::vector<PieceFaces> owners;

  State(const PlaneSet& s, PlaneRef p, std::vector<Contribution> c)
      : set(s), plane(p), i((dominant_axis(s, p.id) + 1) % 3), j((i + 1) % 3),
        contributions(without_covered(s, without_duplicates(std::move(c)))), points(s),
        polygon_bounds(bounds_of_polygons()), near(polygon_bounds) {}
  [[nodiscard]] Context context() {
    return {set, plane, i, j, contributions, cuts, cuts_by_owner, points};
  }

  [[nodiscard]] std::vector<Bounds> bounds_of_polygons() const {
    std::vector<Bounds> out;
    out.reserve(contributions.size());
    for (const Contribution& c : contributions) {
      Bounds b{INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (const XPoint& v : c.polygon.vertices) {
        const auto vi = bounds(v, i), vj = bounds(v, j);
        b = {std::min(b[0], vi.first), std::min(b[1], vj.first), std::max(b[2], vi.second), std::max(b[3], vj.second)};
      }
      out.push_back(b);
    }
    return out;
  }

  // Appends the pieces of the given edges, with the owners on their sides.
  void add_pieces(const Context& cx, const std::vector<std::size_t>& of_edges) {
    std::vector<std::size_t> sources, first_source;
    std::vector<Inside> inside;
    for (const std::size_t e : of_edges) {
      const std::size_t first = pieces.size();
      append_pieces(cx, e, edges[e], pieces, sources, first_source);
      owners.resize(pieces.size());
      classify_edge(cx, std::span(pieces).subspan(first), edges[e].from_end, sources, first_source,
                    near, inside, std::span(owners).subspan(first));
    }
  }
};

PlaneBoolean::PlaneBoolean(const PlaneSet& set, PlaneRef plane, std::vector<Contribution> contributions)
    : state_(std::make_unique<State>(set, plane, std::move(contributions))) {
  const IntervalScope intervals;
  State& st = *state_;
  const Context cx = st.context();
  st.edges = make_edges(cx);
  split_edges(cx, st.edges);
  std::vector<std::size_t> all(st.edges.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  st.add_pieces(cx, all);
}

PlaneBoolean::~PlaneBoolean() = default;
PlaneBoolean::PlaneBoolean(PlaneBoolean&&) noexcept = default;
PlaneBoolean& PlaneBoolean::operator=(PlaneBoolean&&) noexcept = default;

void PlaneBoolean::add_cuts(std::span<const Cut> cuts) {
  const IntervalScope intervals;
  State& st = *state_;
  const std::size_t old_edges = st.edges.size();
  for (const Cut& cut : cuts) {
    st.cuts_by_owner.emplace_back(cut.owner, st.cuts.size());
    st.cuts.push_back(cut);
  }
  std::sort(st.cuts_by_owner.begin(), st.cuts_by_owner.end());
  const Context cx = st.context();
  for (std::size_t k = st.cuts.size() - cuts.size(); k < st.cuts.size(); ++k)
    st.edges.push_back(make_cut_edge(cx, st.cuts[k], st.contributions.size() + k));
  // Each new cut against every edge before it; an edge it splits is cut into pieces again.
  std::vector<char> split_again(old_edges, 0);
  for (std::size_t c = old_edges; c < st.edges.size(); ++c)
    for (std::size_t e = 0; e < c; ++e) {
      Edge& f = st.edges[e];
      if (f.source == st.edges[c].source || !boxes_meet(f.bounds, st.edges[c].bounds)) continue;
      const std::size_t before = f.splits.size();
      split_pair(cx, st.edges[c], f);
      if (e < old_edges && f.splits.size() != before) split_again[e] = 1;
    }
  // The pieces of the edges no cut meets stay as they are.
  std::size_t kept = 0;
  for (std::size_t k = 0; k < st.pieces.size(); ++k)
    if (!split_again[st.pieces[k].edge]) {
      st.pieces[kept] = st.pieces[k];
      st.owners[kept++] = st.owners[k];
    }
  st.pieces.resize(kept);
  st.owners.resize(kept);
  std::vector<std::size_t> again;
  for (std::size_t e = 0; e < st.edges.size(); ++e)
    if (e >= old_edges || split_again[e]) again.push_back(e);
  st.add_pieces(cx, again);
}

PlaneFaces PlaneBoolean::faces() {
  const IntervalScope intervals;
  State& st = *state_;
  const Context cx = st.context();
  const std::vector<std::size_t> rep = find_equal_points(cx);
  FaceGroups groups;
  for (std::size_t k = 0; k < st.pieces.size(); ++k)
    add_boundary(cx, groups, st.pieces[k], rep[st.pieces[k].a], rep[st.pieces[k].b], st.owners[k]);
  // Every group's loops first: where some are holes, the plane is cut and run again, so its
  // faces are not made (nor their corners rounded) this time.
  PlaneFaces out;
  std::vector<std::pair<std::size_t, std::vector<PieceLoop>>> loops_of_group;
  for (const std::size_t group : groups.in_key_order()) {
    std::vector<DirectedPiece>& directed = groups.pieces(group);
    std::sort(directed.begin(), directed.end(), [](const DirectedPiece& x, const DirectedPiece& y) {
      return std::tie(x.from, x.to) < std::tie(y.from, y.to);
    });
    directed.erase(std::unique(directed.begin(), directed.end(), [](const DirectedPiece& x, const DirectedPiece& y) {
                     return x.from == y.from && x.to == y.to;
                   }),
                   directed.end());
    const auto& [side_of, owner, cells] = groups.key(group);
    std::vector<PieceLoop> loops = link_loops(st.plane, side_of, std::move(directed), st.points);
    for (const PieceLoop& loop : loops) {
      if (!loop.is_hole) continue;
      std::vector<XPoint>& hole = out.holes.emplace_back(std::size_t(owner), std::vector<XPoint>{}).second;
      for (const DirectedPiece& p : loop.pieces) hole.push_back(st.points[p.from]);
    }
    loops_of_group.emplace_back(group, std::move(loops));
  }
  if (!out.holes.empty()) return out;
  for (const auto& [group, loops] : loops_of_group) {
    const auto& [side_of, owner, cells] = groups.key(group);
    for (const PieceLoop& loop : loops) {
      SolidFace face{{st.plane.id, side_of}, std::size_t(owner), {}, {}, {}};
      for (const DirectedPiece& p : loop.pieces) {
        face.vertices.push_back(st.points[p.from]);
        face.lines.push_back(p.line);
        // Rounded here, where the exact coordinates found on the way are at hand (and planes
        // run in parallel).
        face.rounded.push_back(st.points.round(p.from));
      }
      out.faces.push_back(std::move(face));
    }
  }
  return out;
}

}  // namespace roomcad::detail
