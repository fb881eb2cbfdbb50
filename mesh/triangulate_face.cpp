// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/triangulate_face.h"

#include <cmath>
#include <numeric>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace roomcad {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = Kernel::Point_2;

// Projects onto the coordinate plane most parallel to the polygon: exact (drops a coordinate),
// so orientation predicates on the projection are exact for the input doubles.
std::vector<P2> project(std::span<const OpenMesh::Vec3d> points, const OpenMesh::Vec3d& normal) {
  const double ax = std::abs(normal[0]), ay = std::abs(normal[1]), az = std::abs(normal[2]);
  const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const int u = drop == 0 ? 1 : 0;
  const int v = drop == 2 ? 1 : 2;
  std::vector<P2> projected;
  projected.reserve(points.size());
  for (const auto& p : points) projected.emplace_back(p[u], p[v]);
  return projected;
}

double twice_signed_area(const std::vector<P2>& p) {
  double sum = 0.0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    sum += (p[j].x() - p[i].x()) * (p[j].y() + p[i].y());
  return sum;
}

bool is_left_turn(const P2& a, const P2& b, const P2& c) {
  return CGAL::orientation(a, b, c) == CGAL::LEFT_TURN;
}

// True if p lies inside or on the counter-clockwise triangle abc.
bool touches_triangle(const P2& a, const P2& b, const P2& c, const P2& p) {
  return CGAL::orientation(a, b, p) != CGAL::RIGHT_TURN &&
         CGAL::orientation(b, c, p) != CGAL::RIGHT_TURN &&
         CGAL::orientation(c, a, p) != CGAL::RIGHT_TURN;
}

// An ear: a strictly convex corner whose triangle holds no other remaining vertex.
bool is_ear(const std::vector<P2>& p, const std::vector<int>& ring, std::size_t k) {
  const std::size_t n = ring.size();
  const int a = ring[(k + n - 1) % n], b = ring[k], c = ring[(k + 1) % n];
  if (!is_left_turn(p[a], p[b], p[c])) return false;
  for (const int other : ring) {
    if (other == a || other == b || other == c) continue;
    if (p[other] == p[a] || p[other] == p[b] || p[other] == p[c]) continue;
    if (touches_triangle(p[a], p[b], p[c], p[other])) return false;
  }
  return true;
}

double ear_area(const std::vector<P2>& p, const std::vector<int>& ring, std::size_t k) {
  const std::size_t n = ring.size();
  return CGAL::area(p[ring[(k + n - 1) % n]], p[ring[k]], p[ring[(k + 1) % n]]);
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_face(std::span<const OpenMesh::Vec3d> points,
                                                 const OpenMesh::Vec3d& normal) {
  std::vector<std::array<int, 3>> triangles;
  if (points.size() < 3) return triangles;
  std::vector<P2> p = project(points, normal);
  const double area = twice_signed_area(p);
  if (area == 0.0) return triangles;
  // Work counter-clockwise in the projection; flip the output back if the input was clockwise.
  const bool flipped = area < 0.0;
  std::vector<int> ring(points.size());
  std::iota(ring.begin(), ring.end(), 0);
  if (flipped) std::reverse(ring.begin(), ring.end());

  triangles.reserve(points.size() - 2);
  while (ring.size() > 3) {
    std::size_t chosen = ring.size();
    for (std::size_t k = 0; k < ring.size() && chosen == ring.size(); ++k)
      if (is_ear(p, ring, k)) chosen = k;
    if (chosen == ring.size()) {  // not simple: clip the fattest corner rather than loop forever
      chosen = 0;
      for (std::size_t k = 1; k < ring.size(); ++k)
        if (ear_area(p, ring, k) > ear_area(p, ring, chosen)) chosen = k;
    }
    const std::size_t n = ring.size();
    triangles.push_back({ring[(chosen + n - 1) % n], ring[chosen], ring[(chosen + 1) % n]});
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(chosen));
  }
  triangles.push_back({ring[0], ring[1], ring[2]});
  if (flipped)
    for (auto& t : triangles) std::swap(t[1], t[2]);
  return triangles;
}

}  // namespace roomcad
