#include "modeling/detail/cgal_booleans.h"

#include <vector>

#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <fmt/format.h>

#include "modeling/build_model.h"
#include "modeling/detail/classify_face.h"
#include "modeling/detail/exact_wall.h"

namespace roomcad::detail {
namespace {

using Nef = CGAL::Nef_polyhedron_3<EK>;
using EMesh = CGAL::Surface_mesh<EK::Point_3>;

// A prism over a counter-clockwise quad, from z0 to z1, as a Nef polyhedron.
Nef make_prism(const std::array<EK::Point_2, 4>& quad, double z0, double z1) {
  std::vector<EK::Point_3> points;
  for (double z : {z0, z1})
    for (const EK::Point_2& p : quad) points.emplace_back(p.x(), p.y(), z);
  std::vector<std::vector<std::size_t>> faces{{3, 2, 1, 0}, {4, 5, 6, 7}};
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t n = (k + 1) % 4;
    faces.push_back({k, n, n + 4, k + 4});
  }
  EMesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  return Nef(mesh);
}

// Unites the solids pairwise, level by level, so that each operand stays small.
Nef unite_balanced(std::vector<Nef> parts) {
  if (parts.empty()) return Nef(Nef::EMPTY);
  while (parts.size() > 1) {
    std::vector<Nef> next;
    next.reserve(parts.size() / 2 + 1);
    for (std::size_t i = 0; i + 1 < parts.size(); i += 2) next.push_back(parts[i] + parts[i + 1]);
    if (parts.size() % 2 == 1) next.push_back(std::move(parts.back()));
    parts = std::move(next);
  }
  return std::move(parts.front());
}

// Names the walls of a cluster for messages.
std::string wall_list(std::span<const WallFrame* const> walls) {
  std::string ids;
  for (std::size_t k = 0; k < walls.size() && k < 6; ++k) ids += fmt::format("{}#{}", k ? ", " : "", walls[k]->wall);
  return walls.size() > 6 ? ids + ", ..." : ids;
}

FaceSoup to_soup(const Nef& solid, std::span<const WallFrame* const> walls, int first_opening_object) {
  std::vector<EK::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  CGAL::convert_nef_polyhedron_to_polygon_soup(solid, points, polygons, false);
  std::vector<OpenMesh::Vec3d> rounded;
  rounded.reserve(points.size());
  for (const EK::Point_3& p : points)
    rounded.emplace_back(round_to_nearest(p.x()), round_to_nearest(p.y()), round_to_nearest(p.z()));
  std::pair<std::size_t, std::size_t> bad;
  const auto copies = split_fans(polygons, points.size(), bad);
  if (copies.empty() && !polygons.empty())
    throw PreconditionError(fmt::format(
        "build_model: the solid of walls {} is not 2-manifold: more than two of its faces meet at "
        "the edge from ({}, {}, {}) to ({}, {}, {}) (walls touching along an edge)", wall_list(walls),
        rounded[bad.first][0], rounded[bad.first][1], rounded[bad.first][2], rounded[bad.second][0],
        rounded[bad.second][1], rounded[bad.second][2]));
  FaceSoup soup;
  soup.reserve(polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    SoupFace f;
    for (std::size_t i : polygons[k]) f.points.push_back(rounded[i]);
    f.copies = copies[k];
    const FaceLabel label = classify_face(f.points, walls, first_opening_object);
    f.kind = label.kind;
    f.object = label.object;
    f.color = label.color;
    soup.push_back(std::move(f));
  }
  return soup;
}

}  // namespace

FaceSoup build_cluster_cgal(std::span<const WallFrame* const> walls, int first_opening_object) {
  std::vector<Nef> prisms, holes;
  for (const WallFrame* f : walls) {
    prisms.push_back(make_prism(exact_footprint(*f), f->base, f->top));
    for (const Hole& h : f->holes) holes.push_back(make_prism(exact_hole_footprint(*f, h), h.z0, h.z1));
  }
  Nef solid = unite_balanced(std::move(prisms));
  if (!holes.empty()) solid -= unite_balanced(std::move(holes));
  if (solid.is_empty() && !walls.empty())
    throw PreconditionError(fmt::format("build_model: the walls joined to wall #{} leave nothing "
                                        "once their openings are cut", walls.front()->wall));
  return to_soup(solid, walls, first_opening_object);
}

}  // namespace roomcad::detail
