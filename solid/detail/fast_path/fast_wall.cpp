// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/fast_path/fast_wall.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace roomcad::detail {
namespace {

constexpr int kOutside = -2;  // cell state: beyond the wall
constexpr int kSolid = -1;    // cell state: wall material; >= 0: index of the hole

struct GridPoint {
  std::size_t i, j;
  int s;  // 0: right face, 1: left face
};

struct GridFace {
  std::vector<GridPoint> corners;  // in order; edges run along grid lines or across the thickness
  FaceKind kind;
  int object;
};

class WallGrid {
 public:
  explicit WallGrid(const WallFrame& f) : f_(f) {
    u_ = {0.0, f.length};
    z_ = {f.base, f.top};
    for (const Hole& h : f.holes) {
      u_.insert(u_.end(), {h.u0, h.u1});
      z_.insert(z_.end(), {h.z0, h.z1});
    }
    for (const Attachment& a : f.attachments) {
      u_.insert(u_.end(), {a.u0, a.u1});
      z_.push_back(a.top);
    }
    sort_unique(u_);
    sort_unique(z_);
    cells_.assign((u_.size() - 1) * (z_.size() - 1), kSolid);
    for (std::size_t k = 0; k < f.holes.size(); ++k) mark_hole(k);
    attached_top_.assign(2 * (u_.size() - 1), -INFINITY);
    for (const Attachment& a : f.attachments)
      for (std::size_t c = index_of(u_, a.u0); c < index_of(u_, a.u1); ++c)
        attached_top_[2 * c + (a.side > 0)] = a.top;
  }
  /// Whether the side face s (0 right, 1 left) is solid at cell (c, r): wall material not
  /// covered by an attached stem (rows below the stem's top, which is a row line).
  bool is_side_solid(int s, std::ptrdiff_t c, std::ptrdiff_t r) const {
    return cell(c, r) == kSolid &&
           !(z_[std::size_t(r)] < attached_top_[2 * std::size_t(c) + std::size_t(s)]);
  }
  std::size_t nu() const { return u_.size(); }
  std::size_t nz() const { return z_.size(); }
  /// State of cell (c, r); indices one past either end are outside.
  int cell(std::ptrdiff_t c, std::ptrdiff_t r) const {
    if (c < 0 || r < 0 || c >= std::ptrdiff_t(nu() - 1) || r >= std::ptrdiff_t(nz() - 1))
      return kOutside;
    return cells_[std::size_t(c) * (nz() - 1) + std::size_t(r)];
  }
  OpenMesh::Vec3d point(const GridPoint& p) const {
    Point2 xy;
    if (p.i == 0) xy = f_.footprint[p.s == 0 ? 0 : 3];
    else if (p.i == nu() - 1) xy = f_.footprint[p.s == 0 ? 1 : 2];
    else xy = attached_point(p).value_or(side_point(f_, u_[p.i], p.s == 0 ? -1 : 1));
    return {xy.x, xy.y, z_[p.j]};
  }
  /// A stem's corner, where one lies at this grid point: shared exactly with the stem.
  std::optional<Point2> attached_point(const GridPoint& p) const {
    for (const Attachment& a : f_.attachments) {
      if ((a.side > 0) != (p.s == 1)) continue;
      if (a.u0 == u_[p.i]) return a.p0;
      if (a.u1 == u_[p.i]) return a.p1;
    }
    return std::nullopt;
  }
  /// The cells of hole k: columns [c0, c1) and rows [r0, r1).
  std::array<std::size_t, 4> cells_of(std::size_t k) const {
    const Hole& h = f_.holes[k];
    return {index_of(u_, h.u0), index_of(u_, h.u1), index_of(z_, h.z0), index_of(z_, h.z1)};
  }

 private:
  static void sort_unique(std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  static std::size_t index_of(const std::vector<double>& v, double x) {
    return std::size_t(std::lower_bound(v.begin(), v.end(), x) - v.begin());
  }
  void mark_hole(std::size_t k) {
    const auto [c0, c1, r0, r1] = cells_of(k);
    for (std::size_t c = c0; c < c1; ++c)
      for (std::size_t r = r0; r < r1; ++r) cells_[c * (nz() - 1) + r] = int(k);
  }
  const WallFrame& f_;
  std::vector<double> u_, z_;
  std::vector<int> cells_;
  std::vector<double> attached_top_;  // [2 * column + side]: top of the stem there, or -inf
};

struct Context {
  const WallFrame& frame;
  const WallGrid& grid;
  int wall_object;
  int first_opening_object;
  int object_of(int empty) const {
    return empty >= 0 ? first_opening_object + int(frame.holes[std::size_t(empty)].opening)
                      : wall_object;
  }
};

// Vertical cuts that leave no side-face piece around a hole: from each hole enclosed by wall
// material, down and up along its first column line, through solid cells, to the next empty
// cell or the border. cut[i * rows + r]: the edge on column line i at row r is cut.
std::vector<char> find_cuts(const Context& cx, int s) {
  const WallGrid& g = cx.grid;
  const std::size_t nc = g.nu() - 1, nr = g.nz() - 1;
  std::vector<char> cut(g.nu() * nr, 0);
  for (std::size_t k = 0; k < cx.frame.holes.size(); ++k) {
    const auto [c0, c1, r0, r1] = g.cells_of(k);
    if (c0 == 0 || c1 == nc || r0 == 0 || r1 == nr) continue;  // a notch: nothing to cut
    // c0 copied into the capture: C++20 lets a lambda name a structured binding, clang 14
    // (the sanitized build's compiler) does not yet.
    auto both_solid = [&g, s, column = std::ptrdiff_t(c0)](std::size_t r) {
      return g.is_side_solid(s, column - 1, std::ptrdiff_t(r)) &&
             g.is_side_solid(s, column, std::ptrdiff_t(r));
    };
    for (std::size_t r = r0; r-- > 0 && both_solid(r);) cut[c0 * nr + r] = 1;
    for (std::size_t r = r1; r < nr && both_solid(r); ++r) cut[c0 * nr + r] = 1;
  }
  return cut;
}

struct Edge {
  std::size_t i, j;  // start
  int dir;           // 0: +u, 1: +z, 2: -u, 3: -z
};

std::pair<std::size_t, std::size_t> end_of(const Edge& e) {
  const std::size_t i = e.dir == 0 ? e.i + 1 : e.dir == 2 ? e.i - 1 : e.i;
  const std::size_t j = e.dir == 1 ? e.j + 1 : e.dir == 3 ? e.j - 1 : e.j;
  return {i, j};
}

// The boundary edges of the solid cells (and both sides of each cut), counter-clockwise
// around the solid in the (u, z) plane.
std::vector<Edge> side_edges(const WallGrid& g, const std::vector<char>& cut, int s) {
  const std::size_t nr = g.nz() - 1;
  auto is_solid = [&](std::ptrdiff_t c, std::ptrdiff_t r) { return g.is_side_solid(s, c, r); };
  auto apart_u = [&](std::size_t c, std::size_t r) {  // on column line c, row r
    return !(is_solid(std::ptrdiff_t(c) - 1, std::ptrdiff_t(r)) &&
             is_solid(std::ptrdiff_t(c), std::ptrdiff_t(r))) ||
           cut[c * nr + r];
  };
  auto apart_z = [&](std::size_t c, std::size_t r) {  // on row line r, column c
    return !(is_solid(std::ptrdiff_t(c), std::ptrdiff_t(r) - 1) &&
             is_solid(std::ptrdiff_t(c), std::ptrdiff_t(r)));
  };
  std::vector<Edge> edges;
  for (std::size_t c = 0; c + 1 < g.nu(); ++c)
    for (std::size_t r = 0; r < nr; ++r) {
      if (!is_solid(std::ptrdiff_t(c), std::ptrdiff_t(r))) continue;
      if (apart_z(c, r)) edges.push_back({c, r, 0});
      if (apart_u(c + 1, r)) edges.push_back({c + 1, r, 1});
      if (apart_z(c, r + 1)) edges.push_back({c + 1, r + 1, 2});
      if (apart_u(c, r)) edges.push_back({c, r + 1, 3});
    }
  return edges;
}

// Links the edges into loops; where two loops touch at a point, each turns left, so every
// loop stays a simple polygon. @return the loops' corners (where the direction changes).
std::vector<std::vector<GridPoint>> trace_loops(const WallGrid& g, const std::vector<Edge>& edges) {
  std::vector<std::vector<std::size_t>> leaving(g.nu() * g.nz());
  for (std::size_t e = 0; e < edges.size(); ++e)
    leaving[edges[e].i * g.nz() + edges[e].j].push_back(e);
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<GridPoint>> loops;
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    std::vector<GridPoint> corners;
    std::size_t e = first;
    do {
      used[e] = 1;
      const auto [i, j] = end_of(edges[e]);
      std::size_t next = first;
      bool found = false;
      for (const int turn : {1, 0, 3})  // left, straight, right
        for (std::size_t n : leaving[i * g.nz() + j])
          if (!found && (!used[n] || n == first) && edges[n].dir == (edges[e].dir + turn) % 4)
            next = n, found = true;
      if (edges[next].dir != edges[e].dir) corners.push_back({i, j, 0});
      e = next;
    } while (e != first);
    loops.push_back(std::move(corners));
  }
  return loops;
}

// Where every hole lies inside the side face (touching no border) and the holes follow one
// another along u without sharing a column, the face splits in two along a chain through
// existing corners: wall start, each hole's bottom edge, wall end. Below the chain: one
// polygon; above: one polygon running round each hole. No new vertex, so the triangles are
// as few as for the face with holes (V + 2H - 2). @return the two loops, counter-clockwise
// in (u, z) (for s = 0), or nothing where the chain does not apply. O(holes).
std::optional<std::array<std::vector<GridPoint>, 2>> find_chain_split(const Context& cx, int s) {
  const WallGrid& g = cx.grid;
  const std::size_t nc = g.nu() - 1, nr = g.nz() - 1;
  if (cx.frame.holes.empty()) return std::nullopt;
  for (const Attachment& a : cx.frame.attachments)
    if ((a.side > 0) == (s == 1)) return std::nullopt;
  std::vector<GridPoint> below{{0, 0, 0}, {nc, 0, 0}}, above{{0, 0, 0}};
  std::size_t last_column = 0;
  for (std::size_t k = 0; k < cx.frame.holes.size(); ++k) {
    const auto [c0, c1, r0, r1] = g.cells_of(k);
    if (c0 <= last_column || c1 >= nc || r0 == 0 || r1 >= nr) return std::nullopt;
    last_column = c1;
    above.insert(above.end(), {{c0, r0, 0}, {c0, r1, 0}, {c1, r1, 0}, {c1, r0, 0}});
  }
  for (std::size_t k = cx.frame.holes.size(); k-- > 0;) {  // hole bottoms, right to left
    const auto [c0, c1, r0, r1] = g.cells_of(k);
    below.insert(below.end(), {{c1, r0, 0}, {c0, r0, 0}});
  }
  above.insert(above.end(), {{nc, 0, 0}, {nc, nr, 0}, {0, nr, 0}});
  return std::array<std::vector<GridPoint>, 2>{std::move(below), std::move(above)};
}

// The side faces: the solid part of the (u, z) grid, cut into pieces without holes. The left
// face is traced on its own (stems may be glued to one side only), then turned to face +w.
void add_side_faces(const Context& cx, std::vector<GridFace>& out) {
  for (const int s : {0, 1}) {
    std::vector<std::vector<GridPoint>> loops;
    if (auto chain = find_chain_split(cx, s))
      loops = {std::move((*chain)[0]), std::move((*chain)[1])};
    else loops = trace_loops(cx.grid, side_edges(cx.grid, find_cuts(cx, s), s));
    for (std::vector<GridPoint> loop : loops) {
      if (s == 1) {
        std::reverse(loop.begin(), loop.end());
        for (GridPoint& p : loop) p.s = 1;
      }
      out.push_back({std::move(loop), FaceKind::wall_face, cx.wall_object});
    }
  }
}

/// The boundary between cells `before` and `after` along one axis: 0 if both solid or both
/// empty, +1 if the face looks towards `after` (solid before), -1 if towards `before`.
int facing(int before, int after) {
  if ((before == kSolid) == (after == kSolid)) return 0;
  return before == kSolid ? 1 : -1;
}

// Faces across the thickness at u = u[i] (ends and jambs), merged along z.
void add_u_faces(const Context& cx, std::size_t i, std::vector<GridFace>& out) {
  const std::size_t nr = cx.grid.nz() - 1;
  const bool capless =
      (i == 0 && cx.frame.capless[0]) || (i + 1 == cx.grid.nu() && cx.frame.capless[1]);
  auto state = [&](std::size_t r) {
    const int a = cx.grid.cell(std::ptrdiff_t(i) - 1, std::ptrdiff_t(r));
    const int b = cx.grid.cell(std::ptrdiff_t(i), std::ptrdiff_t(r));
    const int dir = facing(a, b);
    return std::pair{dir, dir > 0 ? b : a};  // which way, and the empty cell's state
  };
  for (std::size_t r0 = 0; r0 < nr;) {
    const auto s = state(r0);
    std::size_t r1 = r0 + 1;
    while (r1 < nr && state(r1) == s) ++r1;
    if (s.first != 0 && !(capless && s.second == kOutside)) {
      const FaceKind kind = s.second == kOutside ? FaceKind::wall_end : FaceKind::jamb;
      const int obj = cx.object_of(s.second);
      if (s.first > 0) out.push_back({{{i, r0, 0}, {i, r0, 1}, {i, r1, 1}, {i, r1, 0}}, kind, obj});
      else out.push_back({{{i, r0, 0}, {i, r1, 0}, {i, r1, 1}, {i, r0, 1}}, kind, obj});
    }
    r0 = r1;
  }
}

FaceKind z_face_kind(int dir, int empty) {
  if (empty == kOutside) return dir > 0 ? FaceKind::wall_top : FaceKind::wall_bottom;
  return dir > 0 ? FaceKind::sill : FaceKind::lintel;
}

// Faces across the thickness at z = z[j] (top, bottom, sills, lintels), merged along u.
void add_z_faces(const Context& cx, std::size_t j, std::vector<GridFace>& out) {
  const std::size_t nc = cx.grid.nu() - 1;
  auto state = [&](std::size_t c) {
    const int a = cx.grid.cell(std::ptrdiff_t(c), std::ptrdiff_t(j) - 1);
    const int b = cx.grid.cell(std::ptrdiff_t(c), std::ptrdiff_t(j));
    const int dir = facing(a, b);
    return std::pair{dir, dir > 0 ? b : a};
  };
  for (std::size_t c0 = 0; c0 < nc;) {
    const auto s = state(c0);
    std::size_t c1 = c0 + 1;
    while (c1 < nc && state(c1) == s) ++c1;
    if (s.first != 0) {
      const FaceKind kind = z_face_kind(s.first, s.second);
      const int obj = cx.object_of(s.second);
      if (s.first > 0) out.push_back({{{c0, j, 0}, {c1, j, 0}, {c1, j, 1}, {c0, j, 1}}, kind, obj});
      else out.push_back({{{c0, j, 0}, {c0, j, 1}, {c1, j, 1}, {c1, j, 0}}, kind, obj});
    }
    c0 = c1;
  }
}

// Writes the faces as polygons, adding on each edge every face corner lying on it.
FaceSoup emit_faces(const Context& cx, const std::vector<GridFace>& faces) {
  const std::size_t nu = cx.grid.nu(), nz = cx.grid.nz();
  std::vector<char> corner(nu * nz * 2, 0);
  auto at = [&](std::size_t i, std::size_t j, int s) -> char& {
    return corner[(i * nz + j) * 2 + std::size_t(s)];
  };
  for (const GridFace& f : faces)
    for (const GridPoint& p : f.corners) at(p.i, p.j, p.s) = 1;
  FaceSoup soup;
  soup.reserve(faces.size());
  for (const GridFace& f : faces) {
    SoupFace out{{}, f.kind, f.object, cx.frame.color, {}, {}};
    const std::size_t n = f.corners.size();
    for (std::size_t k = 0; k < n; ++k) {
      const GridPoint a = f.corners[k], b = f.corners[(k + 1) % n];
      out.points.push_back(cx.grid.point(a));
      // Edges across the thickness and chain cuts through a side's inside have no inner vertices.
      if (a.s != b.s || (a.i != b.i && a.j != b.j)) continue;
      const bool along_u = a.j == b.j;
      const std::size_t from = along_u ? a.i : a.j, to = along_u ? b.i : b.j;
      const int step = to > from ? 1 : -1;
      for (std::size_t x = from + step; x != to; x += step) {
        const GridPoint p = along_u ? GridPoint{x, a.j, a.s} : GridPoint{a.i, x, a.s};
        if (at(p.i, p.j, p.s)) out.points.push_back(cx.grid.point(p));
      }
    }
    soup.push_back(std::move(out));
  }
  return soup;
}

}  // namespace

bool has_holes_clear_of_joins(const WallFrame& f) {
  if (f.holes.empty()) return true;
  const double lo = f.capless[0] ? std::max(u_of(f, f.footprint[0]), u_of(f, f.footprint[3])) : 0.0;
  const double hi =
      f.capless[1] ? std::min(u_of(f, f.footprint[1]), u_of(f, f.footprint[2])) : f.length;
  for (const Hole& h : f.holes) {
    if (f.capless[0] && !(h.u0 > lo)) return false;
    if (f.capless[1] && !(h.u1 < hi)) return false;
  }
  return true;
}

FaceSoup build_fast_wall(const WallFrame& frame, int wall_object, int first_opening_object) {
  const WallGrid grid(frame);
  const Context cx{frame, grid, wall_object, first_opening_object};
  std::vector<GridFace> faces;
  add_side_faces(cx, faces);
  for (std::size_t i = 0; i < grid.nu(); ++i) add_u_faces(cx, i, faces);
  for (std::size_t j = 0; j < grid.nz(); ++j) add_z_faces(cx, j, faces);
  return emit_faces(cx, faces);
}

}  // namespace roomcad::detail
