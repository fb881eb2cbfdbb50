// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/float_triangulation.h"

#include <algorithm>
#include <map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "mesh/triangulate_face.h"

namespace roomcad {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = Kernel::Point_3;
using Corners = std::array<int, 3>;  // numbers of rounded points

struct Triangle {
  Corners v;
  SolidMesh::FaceHandle face;
};

// The rounded points, each once (a point is its three floats, as an STL reader welds them), and
// the point number of every mesh vertex.
struct RoundedPoints {
  std::vector<OpenMesh::Vec3d> points;  // float values, held exactly as doubles
  std::vector<int> of_vertex;
};

RoundedPoints round_and_weld(const SolidMesh& mesh) {
  RoundedPoints r;
  std::map<std::array<float, 3>, int> number;
  r.of_vertex.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const OpenMesh::Vec3d& p = mesh.point(v);
    const std::array<float, 3> key{float(p[0]) + 0.0f, float(p[1]) + 0.0f, float(p[2]) + 0.0f};
    const auto [it, fresh] = number.emplace(key, int(r.points.size()));
    if (fresh) r.points.emplace_back(key[0], key[1], key[2]);
    r.of_vertex.push_back(it->second);
  }
  return r;
}

P3 point_of(const RoundedPoints& r, int id) {
  const OpenMesh::Vec3d& p = r.points[std::size_t(id)];
  return {p[0], p[1], p[2]};
}

// The face's corners as point numbers, without consecutive repeats and without spikes (across
// the seam too). A spike (a, b, a) is where rounding closed a sliver of the face: the ring runs
// to b and straight back. Its two edges cancel, and written they would lie on the edges of the
// faces beside the sliver, so that an edge between two rounded points would join four facets.
std::vector<int> rounded_ring(const SolidMesh& mesh, SolidMesh::FaceHandle f,
                              const RoundedPoints& r) {
  std::vector<int> ring;
  for (const auto v : mesh.fv_range(f)) {
    const int id = r.of_vertex[std::size_t(v.idx())];
    if (!ring.empty() && ring.back() == id) continue;
    if (ring.size() >= 2 && ring[ring.size() - 2] == id) {
      ring.pop_back();  // a, b, a: back at a
      continue;
    }
    ring.push_back(id);
  }
  for (bool cut = true; cut && ring.size() > 1;) {
    const std::size_t m = ring.size();
    cut = true;
    if (ring.front() == ring.back() || (m > 2 && ring[m - 2] == ring[0]))
      ring.pop_back();  // a repeat, or a spike b at the end returning to the first corner
    else if (m > 2 && ring[m - 1] == ring[1])
      ring.erase(ring.begin());  // a spike at the first corner, from and back to the last
    else cut = false;
  }
  return ring;
}

// Appends the ear-clipping of `ring` (point numbers), each triangle tagged with `face`.
void append_ring_triangles(const std::vector<int>& ring, const OpenMesh::Vec3d& normal,
                           SolidMesh::FaceHandle face, const RoundedPoints& r,
                           std::vector<Triangle>& out) {
  std::vector<OpenMesh::Vec3d> points;
  points.reserve(ring.size());
  for (const int id : ring) points.push_back(r.points[std::size_t(id)]);
  auto triangles = triangulate_face(points, normal);
  // Zero area (every corner on one line): a fan of flat triangles, which are dropped later and
  // their corners inserted into their neighbours' edges.
  if (triangles.empty())
    for (int k = 1; k + 1 < int(ring.size()); ++k) triangles.push_back({0, k, k + 1});
  for (const auto& t : triangles)
    out.push_back(
        {{ring[std::size_t(t[0])], ring[std::size_t(t[1])], ring[std::size_t(t[2])]}, face});
}

bool has_repeated_corner(const Corners& v) { return v[0] == v[1] || v[1] == v[2] || v[2] == v[0]; }

bool is_collinear(const Corners& v, const RoundedPoints& r) {
  return CGAL::collinear(point_of(r, v[0]), point_of(r, v[1]), point_of(r, v[2]));
}

bool is_flat(const Corners& v, const RoundedPoints& r) {
  return has_repeated_corner(v) || is_collinear(v, r);
}

// The points to insert into edges: every corner of a collinear triangle, sorted, once each.
std::vector<int> corners_of_collinear_triangles(const std::vector<Triangle>& triangles,
                                                const RoundedPoints& r) {
  std::vector<int> corners;
  for (const Triangle& t : triangles)
    if (!has_repeated_corner(t.v) && is_collinear(t.v, r))
      corners.insert(corners.end(), t.v.begin(), t.v.end());
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  return corners;
}

// The triangle's corners with every inserted point that lies strictly inside one of its edges,
// in order along the edge (exact predicates: the points are exactly on the edge in float).
std::vector<int> refined_ring(const Corners& v, const std::vector<int>& inserted,
                              const RoundedPoints& r) {
  std::vector<int> ring;
  for (int k = 0; k < 3; ++k) {
    const P3 a = point_of(r, v[std::size_t(k)]), b = point_of(r, v[std::size_t(k + 1) % 3]);
    ring.push_back(v[std::size_t(k)]);
    const auto first = static_cast<std::ptrdiff_t>(ring.size());
    for (const int q : inserted) {
      const P3 p = point_of(r, q);
      if (CGAL::collinear(a, p, b) && CGAL::collinear_are_strictly_ordered_along_line(a, p, b))
        ring.push_back(q);
    }
    std::sort(ring.begin() + first, ring.end(), [&](int p, int q) {
      return CGAL::collinear_are_strictly_ordered_along_line(a, point_of(r, p), point_of(r, q));
    });
  }
  return ring;
}

}  // namespace

std::vector<FloatTriangle> triangulate_in_float(const SolidMesh& mesh) {
  const RoundedPoints r = round_and_weld(mesh);
  std::vector<Triangle> triangles;
  for (const auto f : mesh.faces()) {
    const std::vector<int> ring = rounded_ring(mesh, f, r);
    // A ring of fewer than 3 points collapsed onto a segment: its edges cancel in pairs.
    if (ring.size() >= 3) append_ring_triangles(ring, mesh.normal(f), f, r, triangles);
  }
  // Dropping a collinear triangle (x, m, y) leaves the edge x->y of the triangle across its long
  // edge unmatched, and the edges x->m, m->y of the other two: splitting x->y at m restores them.
  const std::vector<int> inserted = corners_of_collinear_triangles(triangles, r);
  std::vector<Triangle> kept;
  kept.reserve(triangles.size());
  for (const Triangle& t : triangles) {
    if (is_flat(t.v, r)) continue;
    const std::vector<int> ring =
        inserted.empty() ? std::vector<int>{} : refined_ring(t.v, inserted, r);
    if (ring.size() <= 3) {
      kept.push_back(t);
      continue;
    }
    const OpenMesh::Vec3d a = r.points[std::size_t(t.v[0])];
    const OpenMesh::Vec3d normal =
        (r.points[std::size_t(t.v[1])] - a) % (r.points[std::size_t(t.v[2])] - a);
    append_ring_triangles(ring, normal, t.face, r, kept);
  }
  std::vector<FloatTriangle> out;
  out.reserve(kept.size());
  for (const Triangle& t : kept) {
    FloatTriangle& ft = out.emplace_back();
    for (int k = 0; k < 3; ++k)
      ft.corners[std::size_t(k)] = OpenMesh::Vec3f(r.points[std::size_t(t.v[std::size_t(k)])]);
    ft.face = t.face;
  }
  return out;
}

}  // namespace roomcad
