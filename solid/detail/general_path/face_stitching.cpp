// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/face_stitching.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <span>
#include <tuple>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "core/flat_index.h"

namespace roomcad::detail {
namespace {

using Key = std::array<std::uint64_t, 3>;

Key coordinates_key(const OpenMesh::Vec3d& p) {  // + 0.0: -0.0 and 0.0 are one coordinate
  return {std::bit_cast<std::uint64_t>(p[0] + 0.0), std::bit_cast<std::uint64_t>(p[1] + 0.0),
          std::bit_cast<std::uint64_t>(p[2] + 0.0)};
}

// The distinct rounded points of the faces and the exact points behind each (distinct exact
// points may round to one double point, where features are thinner than an ulp), in flat
// arrays: a build has tens of thousands of corners.
struct PointTable {
  static constexpr std::uint32_t kNone = UINT32_MAX;
  explicit PointTable(const PlaneSet& set) : exact(set) {}
  std::vector<OpenMesh::Vec3d> points;
  // Per point, its exact points in order of first use: the first, then each one's next.
  std::vector<std::uint32_t> first_exact, last_exact, next_exact;
  PointCache exact;                         // every distinct exact point
  std::vector<std::size_t> first_corner;    // per face, where its corners start (and the end)
  std::vector<std::uint32_t> corner_point;  // per corner, its point
  std::vector<std::uint32_t> corner_exact;  // per corner, its face's own exact point

  [[nodiscard]] std::span<const std::uint32_t> polygon(std::size_t face) const {
    return std::span(corner_point)
        .subspan(first_corner[face], first_corner[face + 1] - first_corner[face]);
  }
  [[nodiscard]] std::span<const std::uint32_t> exact_polygon(std::size_t face) const {
    return std::span(corner_exact)
        .subspan(first_corner[face], first_corner[face + 1] - first_corner[face]);
  }
};

PointTable number_faces(const PlaneSet& set, std::span<const SolidFace* const> faces) {
  PointTable t(set);
  t.first_corner.reserve(faces.size() + 1);
  t.first_corner.push_back(0);
  for (const SolidFace* f : faces)
    t.first_corner.push_back(t.first_corner.back() + f->vertices.size());
  const std::size_t corners = t.first_corner.back();
  t.corner_point.resize(corners), t.corner_exact.resize(corners);
  std::vector<const XPoint*> exact_points;  // in order of first use
  // The two numberings, by rounded coordinates and by exact representation, are independent.
  tbb::parallel_invoke(
      [&] {
        FlatIndex<Key> by_coordinates(corners / 3 + 1);
        std::size_t c = 0;
        for (const SolidFace* f : faces)
          for (const auto& r : f->rounded) {
            const OpenMesh::Vec3d p(r[0], r[1], r[2]);
            const auto [at, added] =
                by_coordinates.try_emplace(coordinates_key(p), std::uint32_t(t.points.size()));
            if (added) t.points.push_back(p);
            t.corner_point[c++] = at;
          }
      },
      [&] {
        FlatIndex<Key> by_representation(corners / 3 + 1);
        std::size_t c = 0;
        for (const SolidFace* f : faces)
          for (const XPoint& v : f->vertices) {
            const auto [rep, fresh] = by_representation.try_emplace(
                representation_key(v), std::uint32_t(exact_points.size()));
            if (fresh) exact_points.push_back(&v);
            t.corner_exact[c++] = rep;
          }
      });
  // Each exact point, at its first corner, joins its rounded point's list.
  t.first_exact.assign(t.points.size(), PointTable::kNone);
  t.last_exact.assign(t.points.size(), PointTable::kNone);
  t.next_exact.assign(exact_points.size(), PointTable::kNone);
  for (const XPoint* v : exact_points) t.exact.add(*v);
  for (std::size_t c = 0, known = 0; c < corners; ++c) {
    const std::uint32_t rep = t.corner_exact[c], at = t.corner_point[c];
    if (rep < known)
      continue;  // not its first corner: exact points are numbered in order of first corner
    known = rep + 1;
    (t.last_exact[at] == PointTable::kNone ? t.first_exact[at] : t.next_exact[t.last_exact[at]]) =
        rep;
    t.last_exact[at] = rep;
  }
  return t;
}

// Items filed by group, a counting sort: first[g] is where group g's items start in `filed`
// (first[groups] its end), each group's in the items' order. O(items + groups).
struct Filed {
  std::vector<std::uint32_t> first, filed;
};
Filed file_by_group(const std::vector<std::uint32_t>& group_of, std::size_t groups) {
  Filed out;
  out.first.assign(groups + 1, 0);
  for (const std::uint32_t g : group_of) ++out.first[g + 1];
  for (std::size_t g = 1; g < out.first.size(); ++g) out.first[g] += out.first[g - 1];
  out.filed.resize(group_of.size());
  std::vector<std::uint32_t> next(out.first.begin(), out.first.end() - 1);
  for (std::size_t i = 0; i < group_of.size(); ++i)
    out.filed[next[group_of[i]]++] = std::uint32_t(i);
  return out;
}

// A uniform grid of the points, for finding those near an edge along no axis: up to 32 cells
// along each axis (fewer for few points, about two per cube root of their number), the points
// sorted by cell, each cell's range in one dense array (no hashing per cell visited: a long
// edge visits dozens).
class PointGrid {
 public:
  explicit PointGrid(const std::vector<OpenMesh::Vec3d>& points) {
    for (const auto& p : points)
      for (int k = 0; k < 3; ++k) {
        low_[k] = std::min(low_[k], p[k]);
        high_[k] = std::max(high_[k], p[k]);
      }
    double extent = 0.0;
    for (int k = 0; k < 3; ++k) extent = std::max(extent, high_[k] - low_[k]);
    side_ = std::clamp(int(2.0 * std::cbrt(double(points.size()))), 1, 32);
    cell_ = std::max(extent / side_, std::numeric_limits<double>::min());
    std::vector<std::uint32_t> cell_of_point(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) cell_of_point[i] = cell_of(points[i]);
    Filed by_cell =
        file_by_group(cell_of_point, std::size_t(side_) * std::size_t(side_) * std::size_t(side_));
    first_ = std::move(by_cell.first);
    filed_ = std::move(by_cell.filed);
  }
  /// Calls f(i) for every point in the cells the box [a, b] (grown by `margin`) touches.
  template <class F>
  void for_each_near(const OpenMesh::Vec3d& a, const OpenMesh::Vec3d& b, double margin,
                     F&& f) const {
    std::array<int, 3> lo{}, hi{};
    for (int k = 0; k < 3; ++k) {
      lo[std::size_t(k)] = index(std::min(a[k], b[k]) - margin, k);
      hi[std::size_t(k)] = index(std::max(a[k], b[k]) + margin, k);
    }
    for (int x = lo[0]; x <= hi[0]; ++x)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int z = lo[2]; z <= hi[2]; ++z) {
          const std::size_t cell = cell_at(x, y, z);
          for (std::uint32_t at = first_[cell]; at < first_[cell + 1]; ++at)
            f(std::size_t(filed_[at]));
        }
  }

 private:
  // The cell along axis k holding coordinate v, clamped to the grid (a NaN to cell 0).
  int index(double v, int k) const {
    const double c = std::floor((std::clamp(v, low_[k], high_[k]) - low_[k]) / cell_);
    return c >= 0.0 ? int(std::min(c, double(side_ - 1))) : 0;
  }
  std::size_t cell_at(int x, int y, int z) const {
    return (std::size_t(x) * std::size_t(side_) + std::size_t(y)) * std::size_t(side_) +
           std::size_t(z);
  }
  std::uint32_t cell_of(const OpenMesh::Vec3d& p) const {
    return std::uint32_t(cell_at(index(p[0], 0), index(p[1], 1), index(p[2], 2)));
  }
  double low_[3] = {INFINITY, INFINITY, INFINITY}, high_[3] = {-INFINITY, -INFINITY, -INFINITY};
  int side_ = 1;  // cells along each axis
  double cell_ = 1.0;
  std::vector<std::uint32_t> first_;  // per cell, where its points start in filed_ (and the end)
  std::vector<std::uint32_t> filed_;  // point indices, cell by cell
};

// The points on each line along an axis, by the two coordinates they share, in order along
// it: the only points that may lie inside an edge along that axis (its ends differing in that
// coordinate only: most edges of a home) are those of its line between its ends, found by a
// lookup and a binary search where the grid's walk visits every point of the cells along it.
class AxisLines {
 public:
  explicit AxisLines(const std::vector<OpenMesh::Vec3d>& points) {
    std::vector<std::uint32_t> line_of(points.size());
    for (int a = 0; a < 3; ++a) {
      Family& f = families_[std::size_t(a)];
      f.lines = FlatIndex<LineKey>(points.size());
      std::uint32_t lines = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const auto [line, added] = f.lines.try_emplace(key(points[i], a), lines);
        lines += added;
        line_of[i] = line;
      }
      Filed by_line = file_by_group(line_of, lines);
      f.start = std::move(by_line.first);
      f.order = std::move(by_line.filed);
      for (std::size_t l = 0; l + 1 < f.start.size(); ++l)
        std::sort(f.order.begin() + f.start[l], f.order.begin() + f.start[l + 1],
                  [&](std::uint32_t x, std::uint32_t y) { return points[x][a] < points[y][a]; });
      f.along.resize(points.size());
      for (std::size_t m = 0; m < points.size(); ++m) f.along[m] = points[f.order[m]][a];
    }
  }
  /// Calls f(i) for every point i of the line along `axis` through u and v strictly between
  /// them, in order along it. @pre u and v differ in coordinate `axis` only.
  template <class F>
  void for_each_between(const OpenMesh::Vec3d& u, const OpenMesh::Vec3d& v, int axis, F&& f) const {
    const Family& family = families_[std::size_t(axis)];
    const std::uint32_t line = family.lines.find(key(u, axis));
    if (line == FlatIndex<LineKey>::kNone) return;
    const double low = std::min(u[axis], v[axis]), high = std::max(u[axis], v[axis]);
    const auto begin = family.along.begin() + family.start[line],
               end = family.along.begin() + family.start[line + 1];
    for (auto at = std::upper_bound(begin, end, low); at != end && *at < high; ++at)
      f(std::size_t(family.order[std::size_t(at - family.along.begin())]));
  }

 private:
  using LineKey = std::array<std::uint64_t, 2>;
  struct Family {
    FlatIndex<LineKey> lines;          // the two other coordinates -> the line's number
    std::vector<std::uint32_t> start;  // per line, where its points start in order (and the end)
    std::vector<std::uint32_t> order;  // point indices, line by line, each line's along the axis
    std::vector<double> along;         // their coordinates along the axis
  };
  // The coordinates other than `axis` (+ 0.0: -0.0 and 0.0 are one coordinate).
  static LineKey key(const OpenMesh::Vec3d& p, int axis) {
    return {std::bit_cast<std::uint64_t>(p[(axis + 1) % 3] + 0.0),
            std::bit_cast<std::uint64_t>(p[(axis + 2) % 3] + 0.0)};
  }
  std::array<Family, 3> families_;
};

// Whether rounded point w lies within a few ulps of the segment u-v, strictly between them.
bool is_near_segment(const OpenMesh::Vec3d& u, const OpenMesh::Vec3d& v, const OpenMesh::Vec3d& w) {
  const OpenMesh::Vec3d d = v - u, r = w - u;
  const double len2 = d.sqrnorm();
  if (len2 == 0.0) return false;
  const double t = (r | d) / len2;
  double scale = 0.0;
  for (int k = 0; k < 3; ++k)
    scale = std::max({scale, std::abs(u[k]), std::abs(v[k]), std::abs(w[k])});
  const double tol = 64.0 * std::numeric_limits<double>::epsilon() * scale;
  return t > 0.0 && t < 1.0 && (r - d * t).norm() <= tol;
}

// The axis along which u and v differ if they differ along that one only, else -1.
int only_differing_axis(const OpenMesh::Vec3d& u, const OpenMesh::Vec3d& v) {
  int axis = -1;
  for (int a = 0; a < 3; ++a)
    if (u[a] != v[a]) {
      if (axis >= 0) return -1;
      axis = a;
    }
  return axis;
}

// The axis along which u -> v changes most, and the sign of that change (exact).
std::pair<int, int> edge_axis(PointCache& exact, std::size_t u, std::size_t v,
                              const OpenMesh::Vec3d& d) {
  std::array<int, 3> axes{0, 1, 2};
  std::sort(axes.begin(), axes.end(),
            [&](int a, int b) { return std::abs(d[a]) > std::abs(d[b]); });
  for (int a : axes)
    if (const int s = exact.compare(v, u, a); s != 0) return {a, s};
  return {0, 0};
}

// Whether rounded point i is its exact point (the only one behind it), not a rounding.
bool is_exact_corner(PointTable& t, std::size_t i) {
  const std::uint32_t e = t.first_exact[i];
  if (e == PointTable::kNone || t.next_exact[e] != PointTable::kNone) return false;
  for (int k = 0; k < 3; ++k)
    if (t.exact.compare(e, t.points[i][k], k) != 0) return false;
  return true;
}

}  // namespace

IndexedSoup stitch_faces(const PlaneSet& set, std::span<const SolidFace* const> faces) {
  // Shared with the soup's is_exact, which snapping may ask after this returns.
  const auto t = std::make_shared<PointTable>(number_faces(set, faces));
  const PointGrid grid(t->points);
  const AxisLines lines(t->points);
  IndexedSoup out;
  out.polygons.resize(faces.size());
  // Faces are independent (the exact points' cache is safe to share): in parallel, each
  // polygon in its own slot, so the result does not depend on the thread count.
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t fi) {
    const SolidFace& f = *faces[fi];
    const std::span<const std::uint32_t> poly = t->polygon(fi), exact_poly = t->exact_polygon(fi);
    std::vector<std::size_t>& result = out.polygons[fi];
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const std::size_t next = (k + 1) % poly.size();
      const std::size_t ui = poly[k], vi = poly[next], eu = exact_poly[k], ev = exact_poly[next];
      result.push_back(ui);
      const OpenMesh::Vec3d& u = t->points[ui];
      const OpenMesh::Vec3d& v = t->points[vi];
      // Candidates near the edge in doubles; each decided on its exact points: on the face's
      // plane and the edge's line, strictly between the face's own exact ends.
      std::vector<std::pair<std::size_t, std::size_t>> on_edge;  // (point, its exact point)
      int axis = -1, dir = 0;
      const auto decide = [&](std::size_t wi) {
        if (std::find(poly.begin(), poly.end(), wi) != poly.end()) return;
        for (std::size_t w = t->first_exact[wi]; w != PointTable::kNone; w = t->next_exact[w]) {
          if (t->exact.side(f.plane, w) != 0 || t->exact.side(f.lines[k], w) != 0) continue;
          if (axis < 0) std::tie(axis, dir) = edge_axis(t->exact, eu, ev, v - u);
          if (t->exact.compare(w, eu, axis) != dir || t->exact.compare(ev, w, axis) != dir)
            continue;
          on_edge.emplace_back(wi, w);
          break;
        }
      };
      // Along an axis (u and v differing in that coordinate only: most edges of a home), a
      // point strictly inside the exact edge rounds to the other two coordinates of u and v
      // and strictly between them along it: each of its coordinates lies between the exact
      // ends', rounding is monotone, and rounding to u's or v's coordinate along the axis
      // would make it u's or v's own point. Otherwise, it rounds within a few ulps of the
      // segment.
      if (const int along = only_differing_axis(u, v); along >= 0) {
        lines.for_each_between(u, v, along, decide);
      } else {
        grid.for_each_near(u, v, 1e-9 * (1.0 + u.norm()), [&](std::size_t wi) {
          if (wi != ui && wi != vi && is_near_segment(u, v, t->points[wi])) decide(wi);
        });
      }
      std::sort(on_edge.begin(), on_edge.end(), [&](const auto& a, const auto& b) {
        return t->exact.compare(a.second, b.second, axis) * dir < 0;
      });
      for (const auto& [wi, w] : on_edge) result.push_back(wi);
    }
  });
  out.tags.resize(faces.size());
  std::iota(out.tags.begin(), out.tags.end(), std::size_t{0});
  out.points = t->points;
  out.is_exact = [t](std::size_t i) { return is_exact_corner(*t, i); };
  return out;
}

}  // namespace roomcad::detail
