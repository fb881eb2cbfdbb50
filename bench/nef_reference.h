// SPDX-License-Identifier: GPL-3.0-or-later
// The outside CGAL reference of the modeling benchmark: the plan's walls as CGAL Nef
// polyhedra, united as a balanced tree, all openings subtracted in one batch (the fastest
// exact CGAL recipe), written out as a polygon soup. Plain CGAL, none of roomcad's code:
// each wall is its box extended by half its thickness at both ends (so an L corner is the
// full square, as roomcad's mitre), each opening a box a centimetre wider than the wall.
#pragma once

#include <cmath>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>

#include "bench/polygon_measure.h"
#include "plan/plan.h"

namespace roomcad::bench {

using NefKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Nef = CGAL::Nef_polyhedron_3<NefKernel>;

/// The box [u0, u1] x [w0, w1] x [z0, z1] in the frame of wall w (u along it, w to its left).
inline Nef make_wall_box(const Wall& w, double u0, double u1, double w0, double w1, double z0,
                         double z1) {
  const double len = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
  const double dx = (w.to.x - w.from.x) / len, dy = (w.to.y - w.from.y) / len;
  std::vector<NefKernel::Point_3> points;
  for (double z : {z0, z1})
    for (auto [u, v] : {std::pair{u0, w0}, {u1, w0}, {u1, w1}, {u0, w1}})
      points.emplace_back(w.from.x + u * dx - v * dy, w.from.y + u * dy + v * dx, z);
  std::vector<std::vector<std::size_t>> faces{{3, 2, 1, 0}, {4, 5, 6, 7}};
  for (std::size_t k = 0; k < 4; ++k) faces.push_back({k, (k + 1) % 4, (k + 1) % 4 + 4, k + 4});
  CGAL::Surface_mesh<NefKernel::Point_3> mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  return Nef(mesh);
}

/// Unites the solids pairwise, level by level (each operand stays small).
inline Nef unite_as_balanced_tree(std::vector<Nef> parts) {
  if (parts.empty()) return Nef(Nef::EMPTY);
  while (parts.size() > 1) {
    std::vector<Nef> next;
    for (std::size_t i = 0; i + 1 < parts.size(); i += 2) next.push_back(parts[i] + parts[i + 1]);
    if (parts.size() % 2 == 1) next.push_back(std::move(parts.back()));
    parts = std::move(next);
  }
  return std::move(parts.front());
}

/// @return the walls minus the openings, its points rounded to doubles. Seconds for 10 x 10.
inline PolygonSoup build_nef_reference(const Plan& plan) {
  std::vector<Nef> walls, holes;
  for (const Wall& w : plan.walls) {
    const double len = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y), t = w.thickness / 2;
    walls.push_back(make_wall_box(w, -t, len + t, -t, t, w.base, w.base + w.height));
  }
  for (const Opening& o : plan.openings) {
    const Wall& w = *find_wall(plan, o.wall);
    const double t = w.thickness / 2 + 0.01, z0 = w.base + o.sill;
    holes.push_back(make_wall_box(w, o.offset, o.offset + o.width, -t, t, z0, z0 + o.height));
  }
  const Nef solid =
      unite_as_balanced_tree(std::move(walls)) - unite_as_balanced_tree(std::move(holes));
  std::vector<NefKernel::Point_3> exact;
  PolygonSoup soup;
  CGAL::convert_nef_polyhedron_to_polygon_soup(solid, exact, soup.polygons, false);
  for (const auto& p : exact)
    soup.points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  return soup;
}

}  // namespace roomcad::bench
