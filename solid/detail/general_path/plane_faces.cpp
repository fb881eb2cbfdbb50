// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/plane_faces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>

#include "core/flat_index.h"
#include "geometry/box_grid.h"
#include "solid/detail/general_path/equal_points.h"
#include "solid/detail/general_path/plane_contributions.h"
#include "solid/detail/general_path/plane_loops.h"
#include "solid/detail/general_path/wedges_apart.h"

namespace roomcad::detail {
namespace {

// Boxes (core/box.h) here are in the plane's view axes: x is axis i, y is axis j.

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
  Box2 bounds{};
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
  Box2 bounds{};
};

Box2 bounds_of(const Context& cx, std::size_t a, std::size_t b) {
  const XPoint& p = cx.points[a];
  const XPoint& q = cx.points[b];
  const auto pi = bounds(p, cx.i), pj = bounds(p, cx.j), qi = bounds(q, cx.i), qj = bounds(q, cx.j);
  return {std::min(pi.first, qi.first), std::min(pj.first, qj.first),
          std::max(pi.second, qi.second), std::max(pj.second, qj.second), 0};
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
      Edge e{poly.lines[m],
             poly.lines[prev],
             poly.lines[(m + 1) % n],
             first + prev,
             first + m,
             c,
             {},
             {}};
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
  for (std::size_t k = 0; k < edges.size(); ++k) order[k] = {edges[k].bounds.min_x, k};
  // The comparison the edges had: NaN bounds fall where they did.
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && a.second < b.second);
  });
  std::vector<std::size_t> active;
  for (const auto& [low, idx] : order) {
    Edge& e = edges[idx];
    active.erase(
        std::remove_if(active.begin(), active.end(),
                       [&](std::size_t a) { return edges[a].bounds.max_x < e.bounds.min_x; }),
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
  std::sort(s.begin(), s.end(), [&](const auto& p, const auto& q) {
    return cx.points.compare(p.first, q.first, axis) * dir < 0;
  });
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

// The sides of a piece against line t: {its negative side, its positive side}, each -1 when
// inside t (t's negative side), +1 outside.
std::array<int, 2> side_signs(const Context& cx, PlaneRef t, const Piece& p) {
  int s = cx.points.side(t, p.a);
  if (s == 0) s = cx.points.side(t, p.b);
  if (s != 0) return {s, s};
  // t runs along the piece: its inside is the piece's negative side if they point alike.
  const int aligned =
      t.id == p.line.id ? t.sign * p.line.sign : dot_in_plane(cx.set, cx.plane, t, p.line);
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
                   const std::vector<std::size_t>& first_source, BoxGrid& near,
                   std::vector<Inside>& inside, std::span<PieceFaces> out) {
  const Piece& first = pieces.front();
  inside.clear();
  near.for_each_meeting(first.bounds, [&](std::size_t c) {
    // The piece lies on its own polygon's edge, the polygon on its left.
    const std::array<bool, 2> sides =
        c == first.source ? std::array<bool, 2>{true, false} : inside_sides(cx, c, first);
    if (sides[0] || sides[1]) inside.push_back({c, sides});
  });
  out[0] = faces_of(cx, first, across, inside);
  for (std::size_t k = 1; k < pieces.size(); ++k) {
    for (std::size_t at = first_source[k]; at < first_source[k + 1]; ++at) {
      const std::size_t c = sources[at];
      if (c >= cx.contributions.size()) continue;  // a cut: no polygon
      if (std::find(sources.begin() + std::ptrdiff_t(first_source[k]),
                    sources.begin() + std::ptrdiff_t(at),
                    c) != sources.begin() + std::ptrdiff_t(at))
        continue;  // its polygon is done
      const std::array<bool, 2> sides = inside_sides(cx, c, pieces[k]);
      const auto it = std::find_if(inside.begin(), inside.end(),
                                   [&](const Inside& in) { return in.polygon == c; });
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
    const std::array<std::uint64_t, 2> key{(std::uint64_t(owner) << 1) | (side > 0 ? 1u : 0u),
                                           name};
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
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return keys_[a] < keys_[b]; });
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
  const std::array<std::string, 2> down{cells_of(cx, p, o[0].down, 0),
                                        cells_of(cx, p, o[1].down, 1)};
  if (o[0].down != o[1].down || down[0] != down[1] || faces.down_pinched) {
    if (o[0].down >= 0) groups.add(-1, o[0].down, down[0], {b, a, p.line, -1});
    if (o[1].down >= 0) groups.add(-1, o[1].down, down[1], {a, b, p.line, 1});
  }
}

}  // namespace

struct PlaneBoolean::State {
  const PlaneSet& set;
  PlaneRef plane;
  int i, j;  // the view axes: dominant_axis dropped
  std::vector<Contribution> contributions;
  std::vector<Cut> cuts;
  std::vector<std::pair<std::size_t, std::size_t>> cuts_by_owner;  // (owner, cut index), sorted
  PointCache points;
  std::vector<Edge> edges;
  BoxGrid near;  // of the contributions' polygons (Box2::index: the contribution)
  // Every edge's pieces with the faces on their two sides.
  std::vector<Piece> pieces;
  std::vector<PieceFaces> owners;

  State(const PlaneSet& s, PlaneRef p, std::vector<Contribution> c)
      : set(s),
        plane(p),
        i((dominant_axis(s, p.id) + 1) % 3),
        j((i + 1) % 3),
        contributions(without_covered(s, without_duplicates(std::move(c)))),
        points(s),
        near(bounds_of_polygons()) {}
  [[nodiscard]] Context context() {
    return {set, plane, i, j, contributions, cuts, cuts_by_owner, points};
  }

  [[nodiscard]] std::vector<Box2> bounds_of_polygons() const {
    std::vector<Box2> out;
    out.reserve(contributions.size());
    for (const Contribution& c : contributions) {
      Box2 b = empty_box2();
      b.index = out.size();
      for (const XPoint& v : c.polygon.vertices) {
        const auto vi = bounds(v, i), vj = bounds(v, j);
        b.min_x = std::min(b.min_x, vi.first), b.min_y = std::min(b.min_y, vj.first);
        b.max_x = std::max(b.max_x, vi.second), b.max_y = std::max(b.max_y, vj.second);
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

PlaneBoolean::PlaneBoolean(const PlaneSet& set, PlaneRef plane,
                           std::vector<Contribution> contributions)
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
  const std::vector<std::size_t> rep = find_equal_points(cx.points, cx.i, cx.j);
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
    directed.erase(std::unique(directed.begin(), directed.end(),
                               [](const DirectedPiece& x, const DirectedPiece& y) {
                                 return x.from == y.from && x.to == y.to;
                               }),
                   directed.end());
    const auto& [side_of, owner, cells] = groups.key(group);
    std::vector<PieceLoop> loops = link_loops(st.plane, side_of, std::move(directed), st.points);
    for (const PieceLoop& loop : loops) {
      if (!loop.is_hole) continue;
      std::vector<XPoint>& hole =
          out.holes.emplace_back(std::size_t(owner), std::vector<XPoint>{}).second;
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
