// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/solid_distance_support.h"

#include "solid/build_model.h"

#include <algorithm>
#include <iterator>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

namespace roomcad::test {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<Kernel::Point_3>;

Surface to_surface(const SolidMesh& mesh) {
  Surface out;
  std::vector<Surface::Vertex_index> vertex(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const auto p = mesh.point(v);
    vertex[v.idx()] = out.add_vertex({p[0], p[1], p[2]});
  }
  for (const auto f : mesh.faces()) {
    std::vector<Surface::Vertex_index> corners;
    for (const auto v : mesh.fv_range(f)) corners.push_back(vertex[v.idx()]);
    out.add_face(corners);
  }
  CGAL::Polygon_mesh_processing::triangulate_faces(out);
  return out;
}

/// The largest distance from the points sampled on `from` (its corners, and a grid of
/// `spacing` over its edges and faces) to the surface `to`.
double one_way(const Surface& from, const Surface& to, double spacing) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Kernel::Point_3> points;
  PMP::sample_triangle_mesh(
      from, std::back_inserter(points),
      CGAL::parameters::use_grid_sampling(true).grid_spacing(spacing).do_sample_edges(true));
  return PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(points, to);
}

}  // namespace

SolidMesh walls_and_slabs(const Plan& plan) {
  BuildOptions options;
  options.parts = {.walls = true, .floor = false, .fixtures = false, .slabs = true};
  return build_model(plan, options).walls;
}

double surface_distance(const SolidMesh& a, const SolidMesh& b, double spacing) {
  const Surface sa = to_surface(a), sb = to_surface(b);
  return std::max(one_way(sa, sb, spacing), one_way(sb, sa, spacing));
}

}  // namespace roomcad::test
