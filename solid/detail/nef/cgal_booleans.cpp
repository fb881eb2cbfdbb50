// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/nef/cgal_booleans.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <fmt/format.h>

#include "solid/build_model.h"
#include "solid/detail/assembly/classify_face.h"
#include "solid/detail/assembly/facet_labels.h"
#include "solid/detail/assembly/snap_soup.h"
#include "solid/detail/frames/exact_wall.h"

namespace roomcad::detail {
namespace {

using Nef = CGAL::Nef_polyhedron_3<EK>;
using EMesh = CGAL::Surface_mesh<EK::Point_3>;

// A prism over a convex counter-clockwise polygon, from z0 to z1, as a Nef polyhedron.
Nef make_prism(const std::vector<EK::Point_2>& polygon, double z0, double z1) {
  const std::size_t n = polygon.size();
  std::vector<EK::Point_3> points;
  for (double z : {z0, z1})
    for (const EK::Point_2& p : polygon) points.emplace_back(p.x(), p.y(), z);
  std::vector<std::vector<std::size_t>> faces(2);
  for (std::size_t k = 0; k < n; ++k) {
    faces[0].push_back(n - 1 - k);
    faces[1].push_back(n + k);
    const std::size_t next = (k + 1) % n;
    faces.push_back({k, next, next + n, k + n});
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
  for (std::size_t k = 0; k < walls.size() && k < 6; ++k)
    ids += fmt::format("{}'{}'", k ? ", " : "", walls[k]->id);
  return walls.size() > 6 ? ids + ", ..." : ids;
}

// The result's points rounded to doubles, snapped where they round to within a few ulps of
// each other (snap_soup: points that are exact doubles stay apart), and its polygons over them.
IndexedSoup round_soup(const std::vector<EK::Point_3>& exact,
                       std::vector<std::vector<std::size_t>> polygons) {
  IndexedSoup out;
  out.points.reserve(exact.size());
  std::vector<char> is_exact;
  is_exact.reserve(exact.size());
  for (const EK::Point_3& p : exact) {
    const OpenMesh::Vec3d& r =
        out.points.emplace_back(round_to_nearest(p.x()) + 0.0, round_to_nearest(p.y()) + 0.0,
                                round_to_nearest(p.z()) + 0.0);
    is_exact.push_back(EK::FT(r[0]) == p.x() && EK::FT(r[1]) == p.y() && EK::FT(r[2]) == p.z());
  }
  out.is_exact = [is_exact = std::move(is_exact)](std::size_t i) { return is_exact[i] != 0; };
  out.polygons = std::move(polygons);
  const double tolerance = snap_tolerance(out.points);
  return snap_soup(std::move(out), tolerance);
}

// Puts the soup in an order of its own: points sorted by their exact coordinates, equal ones
// merged, each polygon starting at its lowest point, polygons sorted. CGAL gives them in the
// order of its records, which follows memory addresses: without this the same plan built
// twice gave different files. It can also give one point twice (walls touching along an edge:
// the edge's ends, once for each wall), and snap_soup keeps equal exact points apart: split_fans
// then numbered both copies alike, and the mesh could not hold them.
void sort_soup(std::vector<EK::Point_3>& points, std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return CGAL::compare_xyz(points[a], points[b]) == CGAL::SMALLER;
  });
  std::vector<std::size_t> rank(points.size());
  std::vector<EK::Point_3> sorted;
  sorted.reserve(points.size());
  for (const std::size_t i : order) {
    if (sorted.empty() || sorted.back() != points[i]) sorted.push_back(points[i]);
    rank[i] = sorted.size() - 1;
  }
  points = std::move(sorted);
  for (std::vector<std::size_t>& polygon : polygons) {
    for (std::size_t& i : polygon) i = rank[i];
    std::rotate(polygon.begin(), std::min_element(polygon.begin(), polygon.end()), polygon.end());
  }
  std::sort(polygons.begin(), polygons.end());
}

FaceSoup to_soup(const Nef& solid, std::span<const WallFrame* const> walls,
                 int first_opening_object) {
  std::vector<EK::Point_3> exact;
  std::vector<std::vector<std::size_t>> polygons;
  CGAL::convert_nef_polyhedron_to_polygon_soup(solid, exact, polygons, false);
  sort_soup(exact, polygons);
  const IndexedSoup r = round_soup(exact, std::move(polygons));
  std::pair<std::size_t, std::size_t> bad;
  const FanSplit fans = split_fans(r.polygons, r.points, bad);
  if (fans.vertex.empty() && !r.polygons.empty())
    throw PreconditionError(
        fmt::format("build_model: the solid of walls {} is not 2-manifold: more than two of its "
                    "faces meet at "
                    "the edge from ({}, {}, {}) to ({}, {}, {}), and they cannot be paired across "
                    "their material",
                    wall_list(walls), r.points[bad.first][0], r.points[bad.first][1],
                    r.points[bad.first][2], r.points[bad.second][0], r.points[bad.second][1],
                    r.points[bad.second][2]),
        Code::not_buildable);
  FaceSoup soup;
  soup.reserve(r.polygons.size());
  for (std::size_t k = 0; k < r.polygons.size(); ++k) {
    SoupFace f;
    set_corners(f, r.polygons, k, r.points, fans);
    const FaceLabel label = classify_face(f.points, walls, first_opening_object);
    f.kind = label.kind;
    f.object = label.object;
    f.color = label.color;
    soup.push_back(std::move(f));
  }
  unify_facet_labels(r, soup);
  return soup;
}

}  // namespace

FaceSoup build_cluster_cgal(std::span<const WallFrame* const> walls, int first_opening_object) {
  // The reference path builds prisms: flat tops and rectangular holes only.
  for (const WallFrame* f : walls)
    if (needs_general_path(*f))
      throw PreconditionError(
          fmt::format("build_model: wall '{}' has a sloped top or a shaped opening, which "
                      "the Nef path (--boolean nef) does not build; the default path does",
                      f->id),
          Code::not_buildable);
  std::vector<Nef> prisms, holes;
  // A footprint or hole with no area, or a height that rounds to nothing, has no volume.
  for (const WallFrame* f : walls) {
    if (const auto footprint = exact_footprint(*f); !footprint.empty() && f->base < f->top)
      prisms.push_back(make_prism(footprint, f->base, f->top));
    for (const Hole& h : f->holes)
      if (const auto hole = exact_hole_footprint(*f, h); !hole.empty() && h.z0 < h.z1)
        holes.push_back(make_prism(hole, h.z0, h.z1));
  }
  const bool prisms_were_empty = prisms.empty();
  Nef solid = unite_balanced(std::move(prisms));
  if (!holes.empty()) solid -= unite_balanced(std::move(holes));
  if (solid.is_empty() && !prisms_were_empty)
    throw PreconditionError(fmt::format("build_model: the walls joined to wall '{}' leave nothing "
                                        "once their openings are cut",
                                        walls.front()->id),
                            Code::not_buildable);
  return to_soup(solid, walls, first_opening_object);
}

}  // namespace roomcad::detail
