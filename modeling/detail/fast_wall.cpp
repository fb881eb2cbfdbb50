#include "modeling/detail/fast_wall.h"

#include <algorithm>

namespace roomcad::detail {
namespace {

constexpr int kOutside = -2;  // cell state: beyond the wall
constexpr int kSolid = -1;    // cell state: wall material; >= 0: index of the hole

struct GridPoint {
  std::size_t i, j;
  int s;  // 0: right face, 1: left face
};

struct GridFace {
  std::array<GridPoint, 4> corners;
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
    sort_unique(u_);
    sort_unique(z_);
    cells_.assign((u_.size() - 1) * (z_.size() - 1), kSolid);
    for (std::size_t k = 0; k < f.holes.size(); ++k) mark_hole(k);
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
    else xy = side_point(f_, u_[p.i], p.s == 0 ? -1 : 1);
    return {xy.x, xy.y, z_[p.j]};
  }

 private:
  static void sort_unique(std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  std::size_t index_of(const std::vector<double>& v, double x) const {
    return std::size_t(std::lower_bound(v.begin(), v.end(), x) - v.begin());
  }
  void mark_hole(std::size_t k) {
    const Hole& h = f_.holes[k];
    for (std::size_t c = index_of(u_, h.u0); c < index_of(u_, h.u1); ++c)
      for (std::size_t r = index_of(z_, h.z0); r < index_of(z_, h.z1); ++r)
        cells_[c * (nz() - 1) + r] = int(k);
  }
  const WallFrame& f_;
  std::vector<double> u_, z_;
  std::vector<int> cells_;
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

void add_side_faces(const Context& cx, std::vector<GridFace>& out) {
  const std::size_t nr = cx.grid.nz() - 1;
  for (std::size_t c = 0; c + 1 < cx.grid.nu(); ++c) {
    for (std::size_t r0 = 0; r0 < nr;) {
      if (cx.grid.cell(std::ptrdiff_t(c), std::ptrdiff_t(r0)) != kSolid) { ++r0; continue; }
      std::size_t r1 = r0 + 1;
      while (r1 < nr && cx.grid.cell(std::ptrdiff_t(c), std::ptrdiff_t(r1)) == kSolid) ++r1;
      out.push_back({{{{c, r0, 0}, {c + 1, r0, 0}, {c + 1, r1, 0}, {c, r1, 0}}},
                     FaceKind::wall_face, cx.wall_object});
      out.push_back({{{{c, r0, 1}, {c, r1, 1}, {c + 1, r1, 1}, {c + 1, r0, 1}}},
                     FaceKind::wall_face, cx.wall_object});
      r0 = r1;
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
  const bool capless = (i == 0 && cx.frame.capless[0]) || (i + 1 == cx.grid.nu() && cx.frame.capless[1]);
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
      if (s.first > 0)
        out.push_back({{{{i, r0, 0}, {i, r0, 1}, {i, r1, 1}, {i, r1, 0}}}, kind, obj});
      else
        out.push_back({{{{i, r0, 0}, {i, r1, 0}, {i, r1, 1}, {i, r0, 1}}}, kind, obj});
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
      if (s.first > 0)
        out.push_back({{{{c0, j, 0}, {c1, j, 0}, {c1, j, 1}, {c0, j, 1}}}, kind, obj});
      else
        out.push_back({{{{c0, j, 0}, {c0, j, 1}, {c1, j, 1}, {c1, j, 0}}}, kind, obj});
    }
    c0 = c1;
  }
}

// Writes the faces as polygons, adding on each edge every face corner lying on it.
FaceSoup emit_faces(const Context& cx, const std::vector<GridFace>& faces) {
  const std::size_t nu = cx.grid.nu(), nz = cx.grid.nz();
  std::vector<char> corner(nu * nz * 2, 0);
  auto at = [&](std::size_t i, std::size_t j, int s) -> char& { return corner[(i * nz + j) * 2 + std::size_t(s)]; };
  for (const GridFace& f : faces)
    for (const GridPoint& p : f.corners) at(p.i, p.j, p.s) = 1;
  FaceSoup soup;
  soup.reserve(faces.size());
  for (const GridFace& f : faces) {
    SoupFace out{{}, f.kind, f.object, cx.frame.color};
    for (std::size_t k = 0; k < 4; ++k) {
      const GridPoint a = f.corners[k], b = f.corners[(k + 1) % 4];
      out.points.push_back(cx.grid.point(a));
      if (a.s != b.s) continue;  // an edge across the thickness has no inner vertices
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

double u_of(const WallFrame& f, const Point2& p) {
  return (p.x - f.from.x) * f.dir.x + (p.y - f.from.y) * f.dir.y;
}

}  // namespace

bool has_holes_clear_of_mitres(const WallFrame& f) {
  if (f.holes.empty()) return true;
  const double lo = f.capless[0] ? std::max(u_of(f, f.footprint[0]), u_of(f, f.footprint[3])) : 0.0;
  const double hi = f.capless[1] ? std::min(u_of(f, f.footprint[1]), u_of(f, f.footprint[2])) : f.length;
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
