// SPDX-License-Identifier: GPL-3.0-or-later
// Feature edges (creases and boundaries) and occluding triangles of a mesh.
#include "render/detail/feature_edges.h"

#include <optional>

#include "mesh/triangulate_face.h"

namespace roomcad::detail {
namespace {

glm::dvec3 to_glm(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

/// @return the vertex of the face farthest from the line p-q, or nullopt if every vertex is on
/// it (a degenerate face). The farthest, not the first off the line: the modeller's rounding
/// leaves vertices of the same line a few ulps off it, and those would tilt the plane.
std::optional<glm::dvec3> off_edge_vertex(const SolidMesh& mesh, SolidMesh::FaceHandle f,
                                          const glm::dvec3& p, const glm::dvec3& q) {
  std::optional<glm::dvec3> best;
  double best_distance = -1.0;
  for (const auto vh : mesh.fv_range(f)) {
    const glm::dvec3 r = to_glm(mesh.point(vh));
    const double d = glm::length(glm::cross(q - p, r - p));
    if (d > best_distance && !is_collinear(p, q, r)) best = r, best_distance = d;
  }
  return best;
}

bool is_feature_edge(const SolidMesh& mesh, SolidMesh::EdgeHandle e, const glm::dvec3& p,
                     const glm::dvec3& q) {
  if (mesh.is_boundary(e)) return true;
  const auto f0 = mesh.face_handle(mesh.halfedge_handle(e, 0));
  const auto f1 = mesh.face_handle(mesh.halfedge_handle(e, 1));
  const auto r0 = off_edge_vertex(mesh, f0, p, q);
  const auto r1 = off_edge_vertex(mesh, f1, p, q);
  const bool same_facing = (mesh.calc_face_normal(f0) | mesh.calc_face_normal(f1)) > 0.0;
  return !r0 || !r1 || is_crease(p, q, *r0, *r1, same_facing);
}

}  // namespace

void append_feature_edges(const SolidMesh& mesh, std::vector<Edge3>& out) {
  for (const auto e : mesh.edges()) {
    if (mesh.has_edge_status() && mesh.status(e).deleted()) continue;
    const auto h = mesh.halfedge_handle(e, 0);
    const glm::dvec3 p = to_glm(mesh.point(mesh.from_vertex_handle(h)));
    const glm::dvec3 q = to_glm(mesh.point(mesh.to_vertex_handle(h)));
    if (p != q && is_feature_edge(mesh, e, p, q)) out.push_back({p, q});
  }
}

void append_triangles(const SolidMesh& mesh, std::vector<Triangle3>& out) {
  std::vector<OpenMesh::Vec3d> points;
  for (const auto f : mesh.faces()) {
    if (mesh.has_face_status() && mesh.status(f).deleted()) continue;
    points.clear();
    for (const auto vh : mesh.fv_range(f)) points.push_back(mesh.point(vh));
    if (points.size() < 3) continue;
    for (const auto& t : triangulate_face(points, mesh.calc_face_normal(f))) {
      out.push_back({to_glm(points[t[0]]), to_glm(points[t[1]]), to_glm(points[t[2]])});
    }
  }
}

}  // namespace roomcad::detail
